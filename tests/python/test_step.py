"""generate(step=N), fgsg run --step N from Python (#48): an L-system derived N steps
instead of its length. F -> F [ + F ] F [ - F ] F turns each F into 5 Fs, so step k
draws 5**k segments (counted by hand: 1, 5, 25, 125), each a ribbon of 2 triangles; the
interpreter and the JIT give the same mesh at every step; step = the length is the
derivation without step=; past the length the length is derived with a UserWarning (as
fgsg run warns); the length an attr gives (`derive parallel n;`) counts with attrs=.
step is an int from 0 to 2**31 - 1 (a TypeError for a bool, float or str, a ValueError
out of range), and a grammar that is no L-system takes none (a ValueError)."""
import os
import subprocess
import warnings

import numpy as np
import pytest

import fgsg

SOURCE = os.environ["FGSG_SOURCE"]
FGSG = os.environ["FGSG_BINARY"]
FIG_1_24A = os.path.join(SOURCE, "examples", "abop", "fig1_24a.fgsg")  # derive parallel n; attr n = 5; lines
SEQUENTIAL = os.path.join(SOURCE, "examples", "stepped_column.fgsg")
PLANT = ('derive parallel 3;\nturtle angle 25.7 segments "ribbons";\naxiom: F;\n'
         'F -> F [ + F ] F [ - F ] F;\n')
SEGMENTS = [1, 5, 25, 125]  # 5**k, by hand


@pytest.fixture(scope="module")
def plant():
    return fgsg.Grammar.from_text(PLANT, "plant.fgsg")


def mesh(result):
    return result.positions.tobytes(), result.indices.tobytes()


@pytest.mark.parametrize("step", [0, 1, 2, 3])
def test_step_k_draws_5_to_the_k_ribbons_with_both_engines(plant, step):
    results = {engine: plant.generate(step=step, engine=engine) for engine in ("jit", "interp")}
    for engine, r in results.items():
        assert (r.stats["instances"], r.stats["triangles"]) == (SEGMENTS[step], 2 * SEGMENTS[step]), engine
    assert mesh(results["jit"]) == mesh(results["interp"])


def test_step_is_what_fgsg_run_step_writes(plant, tmp_path):
    source = tmp_path / "plant.fgsg"
    source.write_text(PLANT)
    subprocess.run([FGSG, "run", str(source), "--step", "2", "--instancing", "off", "--group-by", "none", "-q", "-o", str(tmp_path / "cli.glb")], check=True)
    fgsg.Grammar.from_file(source).generate(step=2).write(tmp_path / "py.glb")
    assert (tmp_path / "py.glb").read_bytes() == (tmp_path / "cli.glb").read_bytes()


def test_the_length_is_the_derivation_without_step_and_past_it_warns(plant):
    whole = plant.generate()
    assert mesh(plant.generate(step=3)) == mesh(whole)
    assert mesh(plant.generate(step=2)) != mesh(whole)
    with pytest.warns(UserWarning, match=r"^step=7 is past plant.fgsg's derivation length 3: step 3, its last, "
                                         r"is derived \(as lpfg's animate mode stops there\)$"):
        past = plant.generate(step=7)
    assert mesh(past) == mesh(whole)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no warning up to the length
        plant.generate(step=0)
        plant.generate(step=3)


def test_an_attr_gives_the_length(plant):
    fig = fgsg.Grammar.from_file(FIG_1_24A)
    assert fig.generate(step=2).stats["lines"] == 25  # of n = 5's derivation
    with pytest.warns(UserWarning, match=r"step=4 is past .*fig1_24a.fgsg's derivation length 2"):
        stopped = fig.generate(attrs={"n": 2}, step=4)
    assert stopped.stats["lines"] == 25
    with pytest.raises(fgsg.GrammarError, match="n"):
        fig.generate(attrs={"n": 2.5}, step=1)  # R010, as without step


@pytest.mark.parametrize("step, error, message", [
    (True, TypeError, "step must be an int, not bool"),
    (1.0, TypeError, "step must be an int, not float"),
    ("2", TypeError, "step must be an int, not str"),
    (-1, ValueError, "step must be from 0 to 2147483647, got -1"),
    (2**31, ValueError, "step must be from 0 to 2147483647, got 2147483648"),
])
def test_a_step_that_is_not_a_whole_number_in_range_is_refused(plant, step, error, message):
    with pytest.raises(error) as e:
        plant.generate(step=step)
    assert str(e.value) == message


def test_a_numpy_int_is_a_step(plant):
    assert plant.generate(step=np.int64(1)).stats["instances"] == 5


def test_a_grammar_that_is_no_l_system_takes_no_step():
    column = fgsg.Grammar.from_file(SEQUENTIAL)
    with pytest.raises(ValueError, match=r"^step=1: .*stepped_column.fgsg is no L-system: its derivation is "
                                         r"sequential"):
        column.generate(step=1)
    column.generate()  # without step it derives
