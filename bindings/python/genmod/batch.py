"""Batch tessellation on the local cores or on a Dask distributed cluster.

Jobs are lines of the jobs-file syntax of `genmod batch` (see `genmod batch --help`), e.g.
``doorknob tolerance=0.002 out=knob.obj`` or ``torus res=32 major_radius=1:2:5
out=torus_{major_radius}.ply``. Sweeps are expanded first; each job then travels as its text,
so a worker meshes exactly what was described, with the same C++ engine.

    from genmod import batch
    rows = batch.run("doorknob out=knob.obj\\nsphere res=16 out=s.ply", "out")      # local cores
    from distributed import Client
    rows = batch.run(jobs, "/shared/out", client=Client("tcp://scheduler:8786"))   # a cluster

Each row is a dict (name, output, status "ok"/"error", triangles, vertices, seconds,
error_bound, limits_hit, valid, message), in job order. A job that fails (a bad parameter, a
worker lost more often than the scheduler allows) is an "error" row with the reason; none is
dropped.
"""
import os
import sys

from . import _genmod


def parse(jobs, source="<jobs>"):
    """The expanded job lines of a jobs text (str) or of a list of lines."""
    text = jobs if isinstance(jobs, str) else "\n".join(jobs)
    return _genmod._parse_jobs(text, source)


def _run_one(line, output_dir, validate):
    """Runs one job line in this process (what a Dask worker calls)."""
    return _genmod._run_jobs([line], output_dir, 1, validate)[0]


def _lost(line, error):
    return {"name": line.rsplit(" out=", 1)[0], "output": "", "status": "error", "triangles": 0,
            "vertices": 0, "seconds": 0.0, "error_bound": None, "limits_hit": [], "valid": None,
            "message": f"worker failed: {type(error).__name__}: {error}"}


def _print_progress(done, total):
    """progress=True: a one-line counter on standard error."""
    sys.stderr.write(f"\rgenmod batch: {done}/{total} jobs" + ("\n" if done == total else ""))
    sys.stderr.flush()


def run(jobs, output_dir, client=None, threads=0, validate=True, retries=2, progress=None):
    """Runs the jobs; meshes are written under output_dir (relative out= paths).

    client: None runs on this machine's cores (threads, 0 = all); a distributed.Client sends
    each job to the cluster (output_dir must be reachable by the workers; on one machine it
    is). retries: times a job that raised on a worker is resubmitted. A job whose worker dies
    is rerun by the scheduler elsewhere, up to Dask's distributed.scheduler.allowed-failures
    times (default 3); after that its row is an error naming KilledWorker. progress(done,
    total) is called as jobs finish; progress=True prints a counter on standard error."""
    if progress is True:
        progress = _print_progress
    lines = parse(jobs)
    output_dir = os.path.abspath(str(output_dir))
    os.makedirs(output_dir, exist_ok=True)
    if client is None:
        rows = _genmod._run_jobs(lines, output_dir, int(threads), bool(validate))
        if progress:
            progress(len(rows), len(rows))
        return rows
    from distributed import as_completed  # only needed with a cluster

    futures = client.map(_run_one, lines, output_dir=output_dir, validate=bool(validate), pure=False,
                         retries=int(retries))
    index = {f.key: i for i, f in enumerate(futures)}
    rows = [None] * len(lines)
    done = 0
    if progress:
        progress(0, len(lines))
    for future in as_completed(futures):
        i = index[future.key]
        try:
            rows[i] = future.result()
        except Exception as error:  # a lost worker after its retries, or a pickling failure
            rows[i] = _lost(lines[i], error)
        done += 1
        if progress:
            progress(done, len(lines))
    return rows
