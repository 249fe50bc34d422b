"""Batch tessellation from Python: the local engine, and a Dask LocalCluster of two worker
processes on loopback giving the same rows and byte-identical files, with a failing job
reported, never dropped."""
import filecmp

import pytest

from genmod import batch

JOBS = """
sphere res=12 out=sphere.obj
torus res=12 major_radius=-1 out=bad.obj     # out of range: this job fails
doorknob tolerance=0.01 out=knob.ply
torus res=8:16:2 out=torus_{res}.off
"""

COMPARED = ("name", "status", "triangles", "vertices", "error_bound", "limits_hit", "valid", "message")


def check_rows(rows):
    assert [r["status"] for r in rows] == ["ok", "error", "ok", "ok", "ok"]
    assert "major_radius" in rows[1]["message"]
    knob = rows[2]
    assert knob["valid"] is True and knob["message"] == "" and knob["error_bound"] <= 0.01
    assert rows[3]["triangles"] < rows[4]["triangles"]  # res 8 then 16


def test_local_batch_runs_every_job_in_order(tmp_path):
    seen = []
    rows = batch.run(JOBS, tmp_path, threads=2, progress=lambda done, total: seen.append((done, total)))
    check_rows(rows)
    assert (tmp_path / "knob.ply").stat().st_size > 0 and not (tmp_path / "bad.obj").exists()
    assert seen[-1] == (5, 5)
    with pytest.raises(RuntimeError, match="no_such_model"):
        batch.parse("no_such_model out=x.obj")


def test_dask_cluster_equals_the_local_batch(tmp_path):
    distributed = pytest.importorskip("distributed")
    local_dir, cluster_dir = tmp_path / "local", tmp_path / "cluster"
    local = batch.run(JOBS, local_dir, threads=1)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        progress = []
        remote = batch.run(JOBS, cluster_dir, client=client, progress=lambda d, t: progress.append(d))
    check_rows(remote)
    for a, b in zip(local, remote):
        assert {k: a[k] for k in COMPARED} == {k: b[k] for k in COMPARED}
        if a["status"] == "ok":
            name = a["output"].rsplit("/", 1)[1]
            assert filecmp.cmp(local_dir / name, cluster_dir / name, shallow=False), name
    assert progress[-1] == 5
