"""The Python package `fgsg` (python/): results equal `fgsg run`'s bytes, errors carry
their location, numpy arrays are views, and threads derive concurrently with the same
results as one after another. Run by CTest with PYTHONPATH=build/python and FGSG_BINARY
(the fgsg executable) and FGSG_SOURCE (the source tree) set."""
import os
import subprocess
import threading

import numpy as np
import pytest

import fgsg

SOURCE = os.environ["FGSG_SOURCE"]
FGSG = os.environ["FGSG_BINARY"]
MUELLER = os.path.join(SOURCE, "examples", "mueller_building.fgsg")
PLANT = os.path.join(SOURCE, "examples", "abop_plant.fgsg")


def run_cli(grammar, out, *args):
    # Result.write writes the flattened mesh; fgsg run's .glb is a scene unless told so.
    subprocess.run([FGSG, "run", grammar, "-o", str(out), "--quiet", "--instancing", "off", "--group-by", "none", *args],
                   check=True)
    return out.read_bytes()


@pytest.mark.parametrize("engine", ["jit", "interp"])
def test_results_equal_fgsg_run_bytes(tmp_path, engine):
    g = fgsg.Grammar.from_file(MUELLER)
    r = g.generate(seed=7, attrs={"lot_width": 24, "roof_angle": 40.5}, engine=engine)
    r.write(tmp_path / "py.glb")
    cli = run_cli(MUELLER, tmp_path / "cli.glb", "--seed", "7", "--set", "lot_width=24", "--set", "roof_angle=40.5")
    assert (tmp_path / "py.glb").read_bytes() == cli
    assert r.stats["triangles"] == len(r.indices)


def test_a_parametric_lsystem_equals_fgsg_run(tmp_path):
    r = fgsg.Grammar.from_file(PLANT).generate(seed=3)
    r.write(tmp_path / "plant.obj")
    assert (tmp_path / "plant.obj").read_bytes() == run_cli(PLANT, tmp_path / "cli.obj", "--seed", "3")


def test_a_compiled_library_runs_with_the_same_bytes(tmp_path):
    library = tmp_path / "libplant.so"
    subprocess.run([FGSG, "compile", PLANT, "-o", str(library), "--quiet"], check=True)
    g = fgsg.Grammar.from_library(library)
    g.generate(seed=5).write(tmp_path / "lib.glb")
    assert (tmp_path / "lib.glb").read_bytes() == run_cli(PLANT, tmp_path / "cli.glb", "--seed", "5")
    with pytest.raises(RuntimeError, match="no fgsg_program_other"):
        fgsg.Grammar.from_library(library, name="other")


def test_a_library_compiled_with_a_start_rule_derives_in_its_style(tmp_path):
    # fgsg compile --start-rule Glass$Lot (#43): blue Panes and a Cap box, as fgsg run's.
    styles = os.path.join(SOURCE, "tests", "cga", "corpus", "155_style_rules.cga")
    library = tmp_path / "libglass.so"
    subprocess.run([FGSG, "compile", styles, "-o", str(library), "--quiet", "--start-rule", "Glass$Lot"], check=True)
    fgsg.Grammar.from_library(library).generate().write(tmp_path / "lib.glb")
    glass = run_cli(styles, tmp_path / "glass.glb", "--start-rule", "Glass$Lot")
    assert (tmp_path / "lib.glb").read_bytes() == glass
    assert glass != run_cli(styles, tmp_path / "default.glb")


def test_a_grammar_with_imports_takes_qualified_attrs(tmp_path):
    house = os.path.join(SOURCE, "examples", "stdlib_house.fgsg")
    r = fgsg.Grammar.from_file(house).generate(attrs={"facade.floors": 3, "roof.kind": "gable"})
    r.write(tmp_path / "py.obj")
    cli = run_cli(house, tmp_path / "cli.obj", "--set", "facade.floors=3", "--set", "roof.kind=gable")
    assert (tmp_path / "py.obj").read_bytes() == cli
    assert "facade.floors" in fgsg.Grammar.from_file(house).attrs


def test_arrays_are_views_of_the_result():
    r = fgsg.Grammar.from_file(MUELLER).generate(seed=1)
    for a, dtype, width in ((r.positions, np.float32, 3), (r.normals, np.float32, 3), (r.indices, np.uint32, 3)):
        assert a.dtype == dtype and a.shape[1] == width
        assert not a.flags.owndata  # the engine's memory, kept alive by the array
    assert r.indices.max() < len(r.positions)
    positions = r.positions
    del r
    assert np.isfinite(positions).all()  # still valid: the view holds the result


def test_instances_are_a_structured_array():
    r = fgsg.Grammar.from_file(MUELLER).generate(seed=1)
    inst = r.instances
    assert inst.dtype.names == ("asset", "symbol", "transform", "color", "param_offset", "param_count")
    assert len(inst) == r.stats["instances"]
    assert inst["transform"].shape == (len(inst), 4, 4)
    np.testing.assert_array_equal(inst["transform"][:, 3, :], np.tile([0, 0, 0, 1], (len(inst), 1)))
    assert {r.assets[a] for a in inst["asset"]} >= {"wall.obj", "win.obj"}
    assert all(0 <= s < len(r.symbols) for s in inst["symbol"])


def test_instance_parameters_keep_their_types():
    g = fgsg.Grammar.from_text('A ~> B(2.5, true, "red", (1, 2, 3));\nB(x, b, s, v) ~> I("cube");\n', "params.fgsg")
    r = g.generate()
    assert r.instance_params(0) == [2.5, True, "red", [1, 2, 3]]
    with pytest.raises(IndexError):
        r.instance_params(5)


def test_joined_strings_read_as_instance_parameters_reports_and_scene_extras():
    # "k" + 7 is "k7", "floor" + 3 "floor3": whole numbers print without a point (#43/#44).
    g = fgsg.Grammar.from_text('A ~> Report("floor" + 3, 2) B("k" + 7, "red");\n'
                               'B(s, t) ~> Report("kind", s) I("cube");\n', "joined.fgsg")
    for engine in ("interp", "jit"):
        r = g.generate(engine=engine)
        assert r.instance_params(0) == ["k7", "red"]
        reports = r.reports["all"]
        assert reports["floor3"]["sum"] == 2 and reports["kind"]["values"] == ["k7"]
        start = r.scene()[0]
        assert start.extras["reports"]["kind"]["strings"] == {"k7": 1}


def test_a_grammar_error_carries_its_location():
    with pytest.raises(fgsg.GrammarError) as e:
        fgsg.Grammar.from_text("A ~> B;\nB ~> S(1, 1;\n", "broken.fgsg")
    assert (e.value.file, e.value.line, e.value.column, e.value.code) == ("broken.fgsg", 2, 12, "E002")
    assert "expected ',' or ')'" in e.value.message
    assert "broken.fgsg:2:12: error[E002]" in str(e.value)


def test_a_derivation_error_carries_its_location():
    g = fgsg.Grammar.from_text("attr w = 2;\nA ~> S(w, 1, 1) I(\"cube\");\n", "attrs.fgsg")
    with pytest.raises(fgsg.GrammarError) as e:
        g.generate(attrs={"width": 3})
    assert e.value.code.startswith("R")
    assert e.value.file == "attrs.fgsg"
    assert "attrs['width']: the grammar declares no attr 'width'" in e.value.message
    with pytest.raises(ValueError):
        g.generate(engine="gpu")


def test_a_missing_file_is_an_error():
    with pytest.raises(RuntimeError, match="nothing.fgsg"):
        fgsg.Grammar.from_file(os.path.join(SOURCE, "examples", "nothing.fgsg"))


def test_threads_derive_concurrently_with_the_sequential_results():
    g = fgsg.Grammar.from_file(MUELLER)
    seeds = list(range(1, 9))
    sequential = [g.generate(seed=s, attrs={"lot_width": 14 + s}).positions.copy() for s in seeds]
    results = [None] * len(seeds)

    def work(i):
        results[i] = g.generate(seed=seeds[i], attrs={"lot_width": 14 + seeds[i]}).positions.copy()

    threads = [threading.Thread(target=work, args=(i,)) for i in range(len(seeds))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for a, b in zip(sequential, results):
        np.testing.assert_array_equal(a, b)
