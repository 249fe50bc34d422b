#!/usr/bin/python3
"""The same batch on a Dask LocalCluster of 2 worker processes against the local engine on 2
threads, in one run: wall time (median of --repeats), CPU seconds of the processes that did
the work, and their ratios. The rows and files of both are checked to agree first.

    /usr/bin/python3 bench/python/cluster_vs_local.py [--repeats 3] [--jobs FILE]
"""
import argparse
import filecmp
import os
import resource
import statistics
import tempfile
import time

import distributed
from genmod import batch

# Parametric models meshed adaptively and lattice sweeps: 26 jobs of 5 ms to 1 s.
DEFAULT_JOBS = """
doorknob tolerance=0.001 out=knob.ply
gear tolerance=0.002 out=gear.ply
patio_tile tolerance=0.002 out=tile.ply
lamp_stand tolerance=0.002 out=lamp.ply
circular_beam tolerance=0.002 out=beam.ply
torus res=16:256:16 out=torus_{res}.ply
sphere res=32:160:5 out=sphere_{res}.ply
"""


def cpu_seconds():
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


def worker_cpu(client):
    return sum(client.run(lambda: time.process_time()).values())


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--jobs", help="a jobs file (default: a built-in list)")
    args = parser.parse_args()
    jobs = open(args.jobs).read() if args.jobs else DEFAULT_JOBS
    lines = batch.parse(jobs)
    print(f"{len(lines)} jobs, {args.repeats} repeats")
    with tempfile.TemporaryDirectory() as tmp, \
            distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                     dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        local_dir, cluster_dir = os.path.join(tmp, "local"), os.path.join(tmp, "cluster")
        local_rows = batch.run(jobs, local_dir, threads=2)
        cluster_rows = batch.run(jobs, cluster_dir, client=client)
        for a, b in zip(local_rows, cluster_rows):
            assert a["status"] == b["status"] == "ok", (a["message"], b["message"])
            name = os.path.basename(a["output"])
            assert filecmp.cmp(os.path.join(local_dir, name), os.path.join(cluster_dir, name), shallow=False), name
        local_wall, local_cpu, cluster_wall, cluster_cpu = [], [], [], []
        for _ in range(args.repeats):
            start, cpu = time.perf_counter(), cpu_seconds()
            batch.run(jobs, local_dir, threads=2)
            local_wall.append(time.perf_counter() - start)
            local_cpu.append(cpu_seconds() - cpu)
            start, cpu, wcpu = time.perf_counter(), cpu_seconds(), worker_cpu(client)
            batch.run(jobs, cluster_dir, client=client)
            cluster_wall.append(time.perf_counter() - start)
            cluster_cpu.append(worker_cpu(client) - wcpu + cpu_seconds() - cpu)
    lw, lc = statistics.median(local_wall), statistics.median(local_cpu)
    cw, cc = statistics.median(cluster_wall), statistics.median(cluster_cpu)
    print(f"{'':28}{'wall s':>10}{'CPU s':>10}")
    print(f"{'local engine, 2 threads':28}{lw:10.3f}{lc:10.3f}")
    print(f"{'LocalCluster, 2 workers':28}{cw:10.3f}{cc:10.3f}")
    print(f"{'cluster / local':28}{cw / lw:10.2f}{cc / lc:10.2f}")


if __name__ == "__main__":
    main()
