"""A batch job's "step" (fgsg.batch, docs/scale.md; #48): fgsg run --step for a job. The
L-system F -> F [ + F ] F [ - F ] F draws 5**k ribbons of 2 triangles at step k (counted
by hand: 1/2, 5/10, 25/50, 125/250), the bytes of `fgsg run --step k`. A step is in the
job's inputs hash, so `fgsg batch` run again re-runs the job whose step changed and skips
the others; null is no step. A step that is not a whole number from 0 to 2**31 - 1 stops
the batch before any job runs (exit 2) with an error naming the job; a step for a grammar
that is no L-system fails that job only."""
import json
import os
import subprocess

import pytest

from fgsg import batch

SOURCE = os.environ["FGSG_SOURCE"]
FGSG = os.environ["FGSG_BINARY"]
SEQUENTIAL = os.path.join(SOURCE, "examples", "stepped_column.fgsg")
PLANT = ('derive parallel 3;\nturtle angle 25.7 segments "ribbons";\naxiom: F;\n'
         'F -> F [ + F ] F [ - F ] F;\n')
SEGMENTS = [1, 5, 25, 125]  # 5**k, by hand


@pytest.fixture
def plant(tmp_path):
    (tmp_path / "plant.fgsg").write_text(PLANT)
    return "plant.fgsg"


def write_jobs(folder, jobs):
    path = folder / "jobs.json"
    path.write_text(json.dumps(jobs))
    return path


def test_a_job_s_step_draws_5_to_the_k_ribbons_as_fgsg_run_step(tmp_path, plant):
    path = write_jobs(tmp_path, [{"id": f"s{k}", "grammar": plant, "step": k, "output": f"out/{k}.glb"}
                                 for k in range(4)] + [{"id": "whole", "grammar": plant, "output": "out/whole.glb"}])
    jobs = batch.load_jobs(path)
    for k, job in enumerate(jobs):
        outcome = batch.run_job(job)
        assert outcome["ok"], outcome
        want = SEGMENTS[k] if k < 4 else SEGMENTS[3]
        assert (outcome["instances"], outcome["triangles"]) == (want, 2 * want), outcome
    for k in (0, 2):
        subprocess.run([FGSG, "run", str(tmp_path / plant), "--step", str(k), "--instancing", "off", "--group-by", "none",
                        "-q", "-o", str(tmp_path / f"cli{k}.glb")],
                       check=True)
        assert (tmp_path / f"out/{k}.glb").read_bytes() == (tmp_path / f"cli{k}.glb").read_bytes()
    assert (tmp_path / "out/3.glb").read_bytes() == (tmp_path / "out/whole.glb").read_bytes()


def test_the_step_is_in_the_inputs_hash_and_null_is_no_step(tmp_path, plant):
    jobs = batch.load_jobs(write_jobs(tmp_path, [
        {"id": "none", "grammar": plant, "output": "a.glb"},
        {"id": "null", "grammar": plant, "step": None, "output": "b.glb"},
        {"id": "two", "grammar": plant, "step": 2, "output": "c.glb"},
        {"id": "two again", "grammar": plant, "step": 2, "output": "d.glb"},
        {"id": "three", "grammar": plant, "step": 3, "output": "e.glb"}]))
    hashes = [batch.job_inputs(j) for j in jobs]
    assert hashes[0] == hashes[1]  # null: the whole derivation, as without a step
    assert hashes[2] == hashes[3]
    assert len({hashes[0], hashes[2], hashes[4]}) == 3  # step 3 is the length, but another input
    assert "step" not in jobs[1]


@pytest.mark.parametrize("step, shown", [(True, "true"), (1.5, "1.5"), (2.0, "2.0"), ("2", '"2"'), (-1, "-1"),
                                         (2**31, "2147483648"), ([1], "[1]")])
def test_a_bad_step_stops_the_batch_naming_the_job(tmp_path, plant, step, shown):
    path = write_jobs(tmp_path, [{"id": "fine", "grammar": plant, "step": 1, "output": "a.glb"},
                                 {"id": "tree-7", "grammar": plant, "step": step, "output": "b.glb"}])
    message = (f'{path}: job 1 (\'tree-7\'): "step" must be a whole number from 0 to 2147483647 '
               f"(the L-system's derivation step, as fgsg run --step), not {shown}")
    with pytest.raises(ValueError) as e:
        batch.load_jobs(path)
    assert str(e.value) == message
    run = subprocess.run([FGSG, "batch", str(path), "--workers", "1"], capture_output=True, text=True, timeout=120)
    assert (run.returncode, run.stderr) == (2, f"fgsg batch: {message}\n")
    assert not (tmp_path / "a.glb").exists()


def test_a_step_for_a_grammar_that_is_no_l_system_fails_that_job(tmp_path):
    outcome = batch.run_job({"id": "column", "grammar": SEQUENTIAL, "seed": 1, "attrs": {}, "step": 1,
                             "output": str(tmp_path / "c.glb")})
    assert not outcome["ok"]
    assert outcome["error"].startswith("ValueError: step=1: ") and "stepped_column.fgsg is no L-system" in outcome["error"]
    assert not (tmp_path / "c.glb").exists()


def test_fgsg_batch_reruns_the_job_whose_step_changed(tmp_path, plant):
    jobs = [{"id": f"p{k}", "grammar": plant, "step": k, "output": f"out/{k}.glb"} for k in (0, 1, 2)]
    path = write_jobs(tmp_path, jobs)
    manifest = tmp_path / "jobs.manifest.json"

    def fgsg_batch():
        run = subprocess.run([FGSG, "batch", str(path), "--workers", "1"], capture_output=True, text=True,
                             timeout=240)
        assert run.returncode == 0, run.stderr
        return json.loads(manifest.read_text())["jobs"]

    first = fgsg_batch()
    assert [(o["instances"], o["triangles"]) for o in first] == [(1, 2), (5, 10), (25, 50)]
    jobs[1]["step"] = 3
    write_jobs(tmp_path, jobs)
    second = fgsg_batch()
    assert [bool(o.get("skipped")) for o in second] == [True, False, True]
    assert second[1]["rerun"] == "its inputs changed"
    assert (second[1]["instances"], second[1]["triangles"]) == (125, 250)
