"""Resuming and stopping fgsg batch (python/fgsg/batch.py): a job is skipped only when
the earlier outcome says its output was made from the same inputs (grammar with its
modules, seed, attributes, files it reads) and keeps that outcome's figures; a changed
input, --force, or no record runs it again. Ctrl-C (SIGINT to the whole process group, as
a terminal sends it) and SIGTERM end `fgsg batch` with one line and no traceback, exit
130 / 143, and a manifest that lists exactly the jobs whose outputs were written; running
the same command again finishes the rest. Stopped before any job finished, the earlier
manifest is left as it was."""
import json
import os
import shutil
import signal
import subprocess
import time

import pytest
from distributed import Client

from fgsg import batch

SOURCE = os.environ["FGSG_SOURCE"]
FGSG = os.environ["FGSG_BINARY"]
PLANT = os.path.join(SOURCE, "examples", "abop_plant.fgsg")
MUELLER = os.path.join(SOURCE, "examples", "mueller_building.fgsg")
CITY = os.path.join(SOURCE, "examples", "city.fgsg")
LOTS = os.path.join(SOURCE, "examples", "city", "lots.geojson")
FOREST_JOBS = os.path.join(SOURCE, "examples", "forest_jobs.json")


@pytest.fixture(scope="module")
def client():
    with batch.local_cluster(1) as cluster:
        with Client(cluster) as c:
            yield c


def grammar_with_a_module(folder, size):
    folder.mkdir(exist_ok=True)
    (folder / "part.fgsg").write_text(f'attr size = {size};\nA ~> S(size, 1, 1) I("cube");\n')
    (folder / "main.fgsg").write_text('import "part" as p;\nX ~> p.A;\n')
    return str(folder / "main.fgsg")


def test_the_inputs_hash_ignores_the_id_the_output_and_the_order_of_attrs(tmp_path):
    job = {"id": "a", "grammar": MUELLER, "seed": 3, "attrs": {"lot_width": 12, "lot_depth": 9},
           "output": str(tmp_path / "a.glb")}
    same = dict(job, id="b", output=str(tmp_path / "b.glb"), attrs={"lot_depth": 9, "lot_width": 12})
    assert batch.job_inputs(job) == batch.job_inputs(same)
    for changed in (dict(job, seed=4), dict(job, attrs={"lot_width": 12}), dict(job, grammar=PLANT),
                    dict(job, surface=LOTS), dict(job, lots=LOTS)):
        assert batch.job_inputs(changed) != batch.job_inputs(job)
    assert len(batch.job_inputs(job)) == 64  # hex sha256


def test_a_job_whose_inputs_changed_runs_again_and_the_others_keep_their_figures(tmp_path, client):
    own = tmp_path / "own.fgsg"
    shutil.copyfile(PLANT, own)
    main = grammar_with_a_module(tmp_path / "modules", 1)
    lots = tmp_path / "lots.geojson"
    shutil.copyfile(LOTS, lots)
    out = tmp_path / "out"
    jobs = [{"id": "seed", "grammar": PLANT, "seed": 1, "attrs": {}, "output": str(out / "seed.glb")},
            {"id": "attrs", "grammar": MUELLER, "seed": 1, "attrs": {"lot_width": 12}, "output": str(out / "attrs.glb")},
            {"id": "grammar", "grammar": str(own), "seed": 1, "attrs": {}, "output": str(out / "grammar.glb")},
            {"id": "module", "grammar": main, "seed": 1, "attrs": {}, "output": str(out / "module.glb")},
            {"id": "lots", "grammar": CITY, "seed": 2, "attrs": {}, "lots": str(lots), "output": str(out / "lots.glb")},
            {"id": "same", "grammar": MUELLER, "seed": 5, "attrs": {"lot_width": 20}, "output": str(out / "same.glb")}]
    first = batch.run_batch(jobs, client)
    assert all(o["ok"] and len(o["inputs"]) == 64 for o in first), first
    module_bytes = (out / "module.glb").read_bytes()

    jobs[0]["seed"] = 2
    jobs[1]["attrs"] = {"lot_width": 13}
    own.write_text(own.read_text() + "\n// changed: a comment is a change too\n")
    grammar_with_a_module(tmp_path / "modules", 2)                    # the imported module, not the grammar
    lots.write_text(json.dumps(json.loads(lots.read_text()), indent=2))  # the same lots, other bytes
    again = batch.run_batch(jobs, client, previous=first)
    assert [o["id"] for o in again if o.get("skipped")] == ["same"]
    assert all(o.get("rerun") == "its inputs changed" for o in again[:-1]), again
    assert again[-1] == dict(first[-1], skipped=True)  # the first run's figures and inputs
    assert (out / "module.glb").read_bytes() != module_bytes  # S(2, 1, 1) now
    assert all(o["inputs"] != p["inputs"] for o, p in zip(again[:-1], first[:-1]))

    forced = batch.run_batch(jobs, client, previous=again, force=True)
    assert not any(o.get("skipped") for o in forced)
    assert all(o["ok"] and o["rerun"] == "--force" for o in forced)
    # No record of what made an output: it is made again.
    unknown = batch.run_batch(jobs[-1:], client, previous=[])
    assert unknown[0]["rerun"] == "no earlier outcome records what made the output"
    # A failed job runs again even when nothing changed.
    failed = dict(again[-1], ok=False, error="earlier")
    assert batch.run_batch(jobs[-1:], client, previous=[failed])[0]["rerun"] == "it failed before"


def fgsg_batch(jobs_file, *args, timeout=240):
    return subprocess.run([FGSG, "batch", str(jobs_file), "--workers", "1", *args], capture_output=True,
                          text=True, timeout=timeout)


def test_the_command_resumes_from_its_manifest_and_force_runs_everything(tmp_path):
    jobs = [{"id": f"p{s}", "grammar": PLANT, "seed": s, "output": f"out/{s}.glb"} for s in (1, 2, 3)]
    (tmp_path / "jobs.json").write_text(json.dumps(jobs))
    manifest = tmp_path / "jobs.manifest.json"

    first = fgsg_batch(tmp_path / "jobs.json")
    assert first.returncode == 0, first.stderr
    m1 = json.loads(manifest.read_text())
    assert (m1["format"], m1["version"], m1["complete"], m1["stopped"], m1["pending"]) == \
        ("fgsg-batch-manifest", 2, True, None, [])
    assert m1["summary"] == {"jobs": 3, "finished": 3, "succeeded": 3, "failed": 0, "skipped": 0}
    assert all(o["ok"] and o["triangles"] > 0 and len(o["inputs"]) == 64 for o in m1["jobs"])

    second = fgsg_batch(tmp_path / "jobs.json")
    assert second.returncode == 0, second.stderr
    m2 = json.loads(manifest.read_text())
    assert m2["summary"]["skipped"] == 3
    assert m2["jobs"] == [dict(o, skipped=True) for o in m1["jobs"]]  # figures kept, seconds too

    jobs[1]["seed"] = 7
    (tmp_path / "jobs.json").write_text(json.dumps(jobs))
    third = fgsg_batch(tmp_path / "jobs.json")
    assert third.returncode == 0, third.stderr
    m3 = json.loads(manifest.read_text())
    assert [bool(o.get("skipped")) for o in m3["jobs"]] == [True, False, True]
    assert m3["jobs"][1]["rerun"] == "its inputs changed"

    forced = fgsg_batch(tmp_path / "jobs.json", "--force")
    assert forced.returncode == 0, forced.stderr
    m4 = json.loads(manifest.read_text())
    assert m4["summary"]["skipped"] == 0 and all(o["rerun"] == "--force" for o in m4["jobs"])


def test_the_documented_manifest_is_the_one_written():
    text = open(os.path.join(SOURCE, "docs", "scale.md"), encoding="utf-8").read()
    assert batch.manifest_path("examples/city_jobs.json") == "examples/city_jobs.manifest.json"
    assert "examples/city_jobs.manifest.json" in text


def forest_jobs(folder, copies):
    tiles = batch.load_jobs(FOREST_JOBS)
    return [dict(t, id=f"{t['id']}-{k}", seed=t.get("seed", 1) + 100 * k, output=str(folder / f"{t['id']}-{k}.glb"))
            for k in range(copies) for t in tiles]


def stop_when_written(jobs_file, out, count, sig, group):
    """Runs `fgsg batch` in a session of its own, sends `sig` (to its whole process group
    when `group`, as a terminal's Ctrl-C) once `count` more outputs exist; its result."""
    before = len(os.listdir(out)) if out.exists() else 0
    p = subprocess.Popen([FGSG, "batch", str(jobs_file), "--workers", "1"], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        deadline = time.monotonic() + 180
        while time.monotonic() < deadline and p.poll() is None:
            if out.exists() and len([f for f in os.listdir(out) if f.endswith(".glb")]) >= before + count:
                break
            time.sleep(0.02)
        assert p.poll() is None, "the batch ended before it could be stopped"
        (os.killpg if group else os.kill)(p.pid, sig)
        _, err = p.communicate(timeout=120)
    finally:
        if p.poll() is None:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait(10)
    return p.returncode, err


def test_ctrl_c_and_sigterm_stop_with_one_line_and_the_manifest_lists_what_finished(tmp_path):
    out = tmp_path / "out"
    jobs = forest_jobs(out, 4)  # 64 tiles of about 0.1 s each
    (tmp_path / "jobs.json").write_text(json.dumps(jobs))
    manifest = tmp_path / "jobs.manifest.json"

    def check(code, err, expected_code, sig_name):
        assert code == expected_code, err
        assert "Traceback" not in err, err
        said = [line for line in err.splitlines() if f"stopped by {sig_name}" in line]
        assert len(said) == 1, err
        m = json.loads(manifest.read_text())
        finished = m["jobs"]
        assert not m["complete"] and m["stopped"] == f"stopped by {sig_name}"
        assert 0 < len(finished) < len(jobs)
        assert m["summary"]["finished"] == len(finished) and f"{len(finished)} of {len(jobs)} jobs finished" in said[0]
        assert sorted([o["id"] for o in finished] + m["pending"]) == sorted(j["id"] for j in jobs)
        for o in finished:
            assert o["ok"] and batch.verify_output(o["output"]) is None, o
        assert not [f for f in os.listdir(tmp_path) if f.endswith(".tmp")]
        return len(finished)

    code, err = stop_when_written(tmp_path / "jobs.json", out, 4, signal.SIGINT, group=True)
    after_int = check(code, err, 130, "SIGINT")
    code, err = stop_when_written(tmp_path / "jobs.json", out, 4, signal.SIGTERM, group=False)
    after_term = check(code, err, 143, "SIGTERM")
    assert after_term > after_int

    rest = fgsg_batch(tmp_path / "jobs.json")
    assert rest.returncode == 0, rest.stderr
    m = json.loads(manifest.read_text())
    assert m["complete"] and m["summary"]["succeeded"] == len(jobs)
    assert m["summary"]["skipped"] == after_term


def test_stopped_before_any_job_finished_the_manifest_is_left_as_it_was(tmp_path, capsys, monkeypatch):
    (tmp_path / "jobs.json").write_text(json.dumps([{"grammar": PLANT, "output": "a.glb"}]))
    earlier = '{"format": "fgsg-batch-manifest", "version": 2, "jobs": []}\n'
    (tmp_path / "jobs.manifest.json").write_text(earlier)

    def interrupted(jobs, client, outcomes=None, **kw):
        outcomes[:] = [None] * len(jobs)
        raise KeyboardInterrupt

    monkeypatch.setattr(batch, "run_batch", interrupted)
    assert batch.main([str(tmp_path / "jobs.json"), "--workers", "1"]) == 130
    err = capsys.readouterr().err
    assert err.strip().splitlines()[-1].endswith("stopped by SIGINT before any job finished; "
                                                 f"{tmp_path / 'jobs.manifest.json'} is unchanged")
    assert (tmp_path / "jobs.manifest.json").read_text() == earlier
