"""fgsg.batch on Dask (python/fgsg/batch.py): 32 jobs on a LocalCluster of 2 workers give
the same bytes as run one after another; a rerun skips what exists; a failing job is
reported with its location and the others succeed; the jobs of a worker killed mid-batch
are retried and their outputs are the same."""
import json
import os
import signal

import pytest
from distributed import Client, LocalCluster

from fgsg import batch

SOURCE = os.environ["FGSG_SOURCE"]
PLANT = os.path.join(SOURCE, "examples", "abop_plant.fgsg")
MUELLER = os.path.join(SOURCE, "examples", "mueller_building.fgsg")


def jobs_in(folder, count=32):
    return [{"id": f"plant-{s}", "grammar": PLANT if s % 2 else MUELLER, "seed": s,
             "attrs": {} if s % 2 else {"lot_width": 10 + s}, "output": str(folder / f"{s:03}.glb")}
            for s in range(1, count + 1)]


@pytest.fixture(scope="module")
def client():
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0") as cluster:
        with Client(cluster) as c:
            yield c


def test_a_local_cluster_gives_the_sequential_bytes_and_a_rerun_skips(tmp_path, client):
    sequential = jobs_in(tmp_path / "seq")
    for job in sequential:
        assert batch.run_job(job)["ok"]
    jobs = jobs_in(tmp_path / "cluster")
    seen = []
    outcomes = batch.run_batch(jobs, client, progress=lambda d, t, f: seen.append((d, t, f)))
    assert [o["id"] for o in outcomes] == [j["id"] for j in jobs]
    assert all(o["ok"] and not o.get("skipped") for o in outcomes)
    for a, b in zip(sequential, jobs):
        assert open(a["output"], "rb").read() == open(b["output"], "rb").read()
    assert seen[-1] == (32, 32, 0)
    # Resumable: everything exists, nothing is run again.
    mtimes = [os.path.getmtime(j["output"]) for j in jobs]
    again = batch.run_batch(jobs, client)
    assert all(o.get("skipped") for o in again)
    assert mtimes == [os.path.getmtime(j["output"]) for j in jobs]


def test_a_killed_worker_s_jobs_are_retried(tmp_path, client):
    reference = jobs_in(tmp_path / "ref", 16)
    for job in reference:
        batch.run_job(job)
    jobs = jobs_in(tmp_path / "killed", 16)
    killed = []

    def kill_one_worker(outcome):
        if not killed:  # after the first result: a worker process dies; its nanny restarts it
            worker, pid = sorted(client.run(os.getpid).items())[0]
            os.kill(pid, signal.SIGKILL)
            killed.append(worker)

    outcomes = batch.run_batch(jobs, client, on_result=kill_one_worker)
    assert killed
    assert all(o["ok"] for o in outcomes)
    for a, b in zip(reference, jobs):
        assert open(a["output"], "rb").read() == open(b["output"], "rb").read()


def test_the_command_reports_failures_per_job_in_its_manifest(tmp_path, capsys):
    jobs = [{"id": "good", "grammar": "plant.fgsg", "seed": 1, "output": "out/good.glb"},
            {"id": "bad", "grammar": "house.fgsg", "attrs": {"lot_width": "wide"}, "output": "out/bad.glb"},
            {"id": "missing", "grammar": "nothing.fgsg", "output": "out/missing.glb"}]
    os.symlink(PLANT, tmp_path / "plant.fgsg")
    os.symlink(MUELLER, tmp_path / "house.fgsg")
    os.symlink(os.path.join(SOURCE, "examples", "assets"), tmp_path / "assets")
    (tmp_path / "jobs.json").write_text(json.dumps({"jobs": jobs}))
    code = batch.main([str(tmp_path / "jobs.json"), "--workers", "2"])
    assert code == 1
    manifest = json.loads((tmp_path / "jobs.manifest.json").read_text())
    by_id = {o["id"]: o for o in manifest["jobs"]}
    assert by_id["good"]["ok"] and (tmp_path / "out" / "good.glb").exists()
    assert not by_id["bad"]["ok"] and by_id["bad"]["code"].startswith("R")
    assert by_id["bad"]["file"].endswith("house.fgsg")
    assert not by_id["missing"]["ok"] and "nothing.fgsg" in by_id["missing"]["error"]
    err = capsys.readouterr().err
    assert "job bad failed" in err and "1 of 3 jobs succeeded" in err


def test_malformed_jobs_are_usage_errors(tmp_path, capsys):
    (tmp_path / "jobs.json").write_text(json.dumps([{"grammar": "a.fgsg"}]))
    assert batch.main([str(tmp_path / "jobs.json")]) == 2
    assert 'job 0 needs "output"' in capsys.readouterr().err
    (tmp_path / "jobs.json").write_text(json.dumps([{"output": "a.glb"}]))
    assert batch.main([str(tmp_path / "jobs.json")]) == 2
    assert 'job 0 needs "grammar"' in capsys.readouterr().err


def test_the_example_batches_load_and_their_jobs_run(tmp_path):
    for name, count in (("city_jobs.json", 100), ("forest_jobs.json", 16)):
        jobs = batch.load_jobs(os.path.join(SOURCE, "examples", name))
        assert len(jobs) == count
        for job in jobs[:2]:  # two neighbouring lots or tiles, written elsewhere
            outcome = batch.run_job(dict(job, output=str(tmp_path / name / os.path.basename(job["output"]))))
            assert outcome["ok"], outcome
            assert outcome["triangles"] > 0


def test_a_job_may_run_a_compiled_library(tmp_path):
    import subprocess
    library = tmp_path / "libplant.so"
    subprocess.run([os.environ["FGSG_BINARY"], "compile", PLANT, "-o", str(library), "--quiet"], check=True)
    from_source = batch.run_job({"id": "s", "grammar": PLANT, "seed": 4, "attrs": {}, "output": str(tmp_path / "s.glb")})
    from_library = batch.run_job({"id": "l", "library": str(library), "seed": 4, "attrs": {},
                                  "output": str(tmp_path / "l.glb")})
    assert from_source["ok"] and from_library["ok"]
    assert (tmp_path / "s.glb").read_bytes() == (tmp_path / "l.glb").read_bytes()


def test_a_job_may_derive_lot_footprints(tmp_path):
    import subprocess
    city = os.path.join(SOURCE, "examples", "city.fgsg")
    lots = os.path.join(SOURCE, "examples", "city", "lots.geojson")
    outcome = batch.run_job({"id": "block", "grammar": city, "seed": 2, "attrs": {}, "lots": lots,
                             "output": str(tmp_path / "block.glb")})
    assert outcome["ok"], outcome
    subprocess.run([os.environ["FGSG_BINARY"], "run", city, "--lots", lots, "--seed", "2", "-o",
                    str(tmp_path / "cli.glb"), "--quiet"], check=True)
    assert (tmp_path / "block.glb").read_bytes() == (tmp_path / "cli.glb").read_bytes()
