"""fgsg.batch on Dask (python/fgsg/batch.py): 32 jobs on a LocalCluster of 2 workers give
the same bytes as run one after another; a rerun given the first run's outcomes skips what
they say was made from the same inputs; a failing job is
reported with its location and the others succeed; the jobs of a worker killed mid-batch
are retried and their outputs are the same. Two jobs naming one output and a manifest that
cannot be written are refused before anything runs; a damaged output (empty, cut short) is
written again, not skipped; every server the batch starts listens on 127.0.0.1 only."""
import json
import os
import signal
import urllib.error
import urllib.request

import pytest
import psutil
from distributed import Client

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
    with batch.local_cluster(2) as cluster:
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
    # Resumable: everything exists and the outcomes say what made it: nothing runs again.
    mtimes = [os.path.getmtime(j["output"]) for j in jobs]
    again = batch.run_batch(jobs, client, previous=outcomes)
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
            {"id": "bad", "grammar": "house.fgsg", "attrs": {"lot_widht": 3}, "output": "out/bad.glb"},
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
                    str(tmp_path / "cli.glb"), "--quiet", "--instancing", "off", "--group-by", "none"], check=True)
    assert (tmp_path / "block.glb").read_bytes() == (tmp_path / "cli.glb").read_bytes()


def test_two_jobs_naming_one_output_are_refused_before_any_runs(tmp_path, capsys):
    jobs = [{"id": "a", "grammar": PLANT, "seed": 1, "output": "out/same.glb"},
            {"id": "b", "grammar": PLANT, "seed": 2, "output": "out/./same.glb"},
            {"id": "c", "grammar": PLANT, "seed": 3, "output": "out/c.glb"}]
    (tmp_path / "jobs.json").write_text(json.dumps({"jobs": jobs}))
    with pytest.raises(ValueError, match="jobs 'a' and 'b' both write"):
        batch.load_jobs(str(tmp_path / "jobs.json"))
    assert batch.main([str(tmp_path / "jobs.json"), "--workers", "1"]) == 2
    assert "jobs 'a' and 'b' both write" in capsys.readouterr().err
    assert not (tmp_path / "out").exists() and not (tmp_path / "jobs.manifest.json").exists()


def test_verify_output_tells_a_whole_file_from_a_damaged_one(tmp_path):
    job = {"id": "p", "grammar": PLANT, "seed": 4, "attrs": {}}
    for ext in (".glb", ".ply", ".obj"):
        whole = tmp_path / ("whole" + ext)
        assert batch.run_job(dict(job, output=str(whole)))["ok"]
        assert batch.verify_output(str(whole)) is None
        data = whole.read_bytes()
        (tmp_path / ("empty" + ext)).write_bytes(b"")
        assert "empty" in batch.verify_output(str(tmp_path / ("empty" + ext)))
        (tmp_path / ("cut" + ext)).write_bytes(data[:-5])
        assert batch.verify_output(str(tmp_path / ("cut" + ext))) is not None, ext
    glb = (tmp_path / "whole.glb").read_bytes()
    (tmp_path / "longer.glb").write_bytes(glb + b"\0" * 4)  # the header's length no longer the file's
    assert "header says" in batch.verify_output(str(tmp_path / "longer.glb"))
    (tmp_path / "text.glb").write_bytes(b"not a glb at all, but long enough")
    assert "not a binary glTF" in batch.verify_output(str(tmp_path / "text.glb"))
    os.mkdir(tmp_path / "folder.glb")
    assert batch.verify_output(str(tmp_path / "folder.glb")) == "not a regular file"


def test_a_damaged_output_is_written_again_not_skipped(tmp_path, client):
    jobs = jobs_in(tmp_path / "out", 4)
    reference_outcomes = batch.run_batch(jobs, client)
    assert all(o["ok"] for o in reference_outcomes)
    reference = [open(j["output"], "rb").read() for j in jobs]
    open(jobs[1]["output"], "wb").close()                      # 0 bytes
    with open(jobs[2]["output"], "r+b") as f:                   # cut short
        f.truncate(len(reference[2]) // 2)
    damaged = []
    outcomes = batch.run_batch(jobs, client, on_damaged=lambda job, why: damaged.append(job["id"]),
                               previous=reference_outcomes)
    assert damaged == [jobs[1]["id"], jobs[2]["id"]]
    assert [bool(o.get("skipped")) for o in outcomes] == [True, False, False, True]
    assert "empty" in outcomes[1]["replaced"] and "header says" in outcomes[2]["replaced"]
    assert all(o["ok"] for o in outcomes)
    assert [open(j["output"], "rb").read() for j in jobs] == reference


def test_a_manifest_that_is_a_directory_is_refused_before_any_job_runs(tmp_path, capsys):
    (tmp_path / "jobs.json").write_text(json.dumps([{"grammar": PLANT, "output": "out/a.glb"}]))
    os.mkdir(tmp_path / "jobs.manifest.json")
    assert batch.main([str(tmp_path / "jobs.json"), "--workers", "1"]) == 2
    assert "is a directory" in capsys.readouterr().err
    assert sorted(os.listdir(tmp_path)) == ["jobs.json", "jobs.manifest.json"]  # no output, no temp file
    assert os.listdir(tmp_path / "jobs.manifest.json") == []
    # The JOBS path itself a directory: a usage error, not a traceback.
    assert batch.main([str(tmp_path / "jobs.manifest.json")]) == 2
    assert "is a directory" in capsys.readouterr().err


def listening(process):
    """(pid, ip, port) of every listening TCP socket of `process` and its descendants."""
    found = []
    for p in [process] + process.children(recursive=True):
        try:
            found += [(p.pid, c.laddr.ip, c.laddr.port) for c in p.connections(kind="inet")
                      if c.status == psutil.CONN_LISTEN]
        except psutil.NoSuchProcess:
            pass
    return found


def status_of(url):
    try:
        return urllib.request.urlopen(url, timeout=10).status
    except urllib.error.HTTPError as e:
        return e.code


def test_every_server_of_a_batch_listens_on_127_0_0_1_and_the_dashboard_is_off(tmp_path, monkeypatch):
    seen = []
    run_batch = batch.run_batch

    def run_and_look(jobs, client, **kw):  # while `fgsg batch` runs: its cluster is up
        client.wait_for_workers(2)
        seen.append(listening(psutil.Process()))
        return run_batch(jobs, client, **kw)

    monkeypatch.setattr(batch, "run_batch", run_and_look)
    (tmp_path / "jobs.json").write_text(json.dumps([{"grammar": PLANT, "output": "a.glb"}]))
    assert batch.main([str(tmp_path / "jobs.json"), "--workers", "2"]) == 0
    sockets = seen[0]
    # Scheduler (comm and HTTP), two nannies, two workers (comm and HTTP each).
    assert len(sockets) >= 7, sockets
    assert {ip for _, ip, _ in sockets} == {"127.0.0.1"}, sockets
    # The information pages are off; the HTTP server only answers health checks.
    with batch.local_cluster(1) as cluster:
        port = cluster.scheduler.http_server.port
        assert status_of(f"http://127.0.0.1:{port}/health") == 200
        assert status_of(f"http://127.0.0.1:{port}/info/main/workers.html") == 404
    with batch.local_cluster(1, dashboard=True) as cluster, Client(cluster) as c:
        c.wait_for_workers(1)
        assert {ip for _, ip, _ in listening(psutil.Process())} == {"127.0.0.1"}
        port = cluster.scheduler.http_server.port
        assert status_of(f"http://127.0.0.1:{port}/info/main/workers.html") == 200
