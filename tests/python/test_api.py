"""The fgsg package's arguments are checked as Python checks them (python/fgsg/__init__.py):
a seed or a shape limit that is not an int is a TypeError, one out of range a ValueError,
each with a message that names the argument (no pybind signature, no `--set`); an
attribute's value must be of its kind; an undeclared attribute is a GrammarError (R010).
Grammar.attrs gives each attribute's kind and default; fgsg.__version__ is the project's
version; Grammar and Result have useful reprs."""
import os
import re

import numpy as np
import pytest

import fgsg

SOURCE = os.environ["FGSG_SOURCE"]
MUELLER = os.path.join(SOURCE, "examples", "mueller_building.fgsg")
KINDS = ('derive parallel n;\nattr n = 3;\nattr label = "x";\nattr flat = true;\nattr offset = (1, 2, 3);\n'
         'attr width = 2.5;\nA ~> S(width, 1, 1) I("cube");\n')


@pytest.fixture(scope="module")
def house():
    return fgsg.Grammar.from_file(MUELLER)


@pytest.fixture(scope="module")
def kinds():
    return fgsg.Grammar.from_text(KINDS, "kinds.fgsg")


@pytest.mark.parametrize("seed, error, message", [
    (7.9, TypeError, "seed must be an int, not float"),
    ("7", TypeError, "seed must be an int, not str"),
    (True, TypeError, "seed must be an int, not bool"),
    (None, TypeError, "seed must be an int, not NoneType"),
    (-1, ValueError, "seed must be from 0 to 18446744073709551615, got -1"),
    (2**64, ValueError, "seed must be from 0 to 18446744073709551615, got 18446744073709551616"),
])
def test_a_seed_that_is_not_a_whole_number_in_range_is_refused(house, seed, error, message):
    with pytest.raises(error) as e:
        house.generate(seed=seed)
    assert str(e.value) == message


def test_seeds_of_any_integer_type_give_the_same_result(house):
    reference = house.generate(seed=7).positions
    np.testing.assert_array_equal(house.generate(seed=np.int64(7)).positions, reference)
    np.testing.assert_array_equal(house.generate(seed=2**64 - 1).positions, house.generate(seed=2**64 - 1).positions)


def test_max_shapes_is_checked_like_the_seed(house):
    with pytest.raises(ValueError, match=r"^max_shapes must be from 0 to \d+, got -3$"):
        house.generate(max_shapes=-3)
    with pytest.raises(TypeError, match="^max_shapes must be an int, not float$"):
        house.generate(max_shapes=10.5)


@pytest.mark.parametrize("attrs, error, message", [
    ({"width": "wide"}, TypeError, "attrs['width'] must be a number (int or float), not str"),
    ({"width": True}, TypeError, "attrs['width'] must be a number (int or float), not bool"),
    ({"width": [1]}, TypeError, "attrs['width'] must be a number (int or float), not list"),
    ({"width": float("nan")}, ValueError, "attrs['width'] must be a finite number, got nan"),
    ({"width": 10**400}, ValueError, "attrs['width'] must be a finite number, got inf"),
    ({"flat": 1}, TypeError, "attrs['flat'] must be a bool, not int"),
    ({"label": 3}, TypeError, "attrs['label'] must be a str, not int"),
    ({"offset": (1, 2)}, ValueError, "attrs['offset'] must be 3 numbers, got 2"),
    ({"offset": "1,2,3"}, TypeError, "attrs['offset'] must be 3 numbers (a tuple, list or array), not str"),
    ({"offset": (1, "2", 3)}, TypeError, "attrs['offset'] must be 3 numbers, not str"),
    ({1: 2}, TypeError, "attrs keys must be str (attribute names), not int"),
    ([("width", 2)], TypeError, "attrs must be a dict of attribute names to values, not list"),
])
def test_an_attribute_value_of_the_wrong_kind_is_refused_in_python_words(kinds, attrs, error, message):
    with pytest.raises(error) as e:
        kinds.generate(attrs=attrs)
    assert str(e.value) == message


def test_values_of_each_kind_are_taken(kinds):
    r = kinds.generate(attrs={"width": np.float32(4), "flat": np.bool_(False), "label": "y",
                              "offset": np.array([0.5, 1, 2]), "n": 4})
    assert r.positions[:, 0].max() - r.positions[:, 0].min() == pytest.approx(4)


def test_an_undeclared_attribute_or_a_value_the_grammar_refuses_is_a_grammar_error(house, kinds):
    with pytest.raises(fgsg.GrammarError) as e:
        house.generate(attrs={"buildng_height": 3})
    assert e.value.code == "R010" and e.value.file == MUELLER
    assert e.value.message.startswith("attrs['buildng_height']: the grammar declares no attr 'buildng_height'; "
                                      "did you mean 'building_height'? (attrs: lot_width, lot_depth, building_height,")
    with pytest.raises(fgsg.GrammarError) as e:
        kinds.generate(attrs={"n": 2.5})
    assert e.value.message == "attrs['n'] = 2.5: `derive parallel n` needs a whole number from 0 to 2147483647"
    for error in (e.value,):
        assert "--set" not in str(error)


def test_attrs_give_each_attribute_s_kind_and_default(house, kinds):
    assert list(kinds.attrs) == ["n", "label", "flat", "offset", "width"]
    assert kinds.attrs["n"] == fgsg.Attr("n", "num", 3.0)
    assert kinds.attrs["label"] == fgsg.Attr("label", "str", "x")
    assert kinds.attrs["flat"] == fgsg.Attr("flat", "bool", True)
    assert kinds.attrs["offset"] == fgsg.Attr("offset", "vec3", (1.0, 2.0, 3.0))
    assert kinds.attrs["width"].kind == "num" and kinds.attrs["width"].default == 2.5
    assert house.attrs["lot_width"] == fgsg.Attr("lot_width", "num", 16.0)
    assert "lot_width" in house.attrs and len(house.attrs) == 18


def test_the_version_is_the_project_s():
    cmake = open(os.path.join(SOURCE, "CMakeLists.txt"), encoding="utf-8").read()
    assert fgsg.__version__ == re.search(r"project\(fgsg VERSION ([0-9.]+)", cmake).group(1)
    assert "__version__" in fgsg.__all__


def test_reprs_say_what_the_objects_are(house, kinds):
    assert repr(house) == f"<fgsg.Grammar {MUELLER!r} (grammar, 18 attrs)>"
    assert repr(kinds) == "<fgsg.Grammar 'kinds.fgsg' (grammar, 5 attrs)>"
    r = house.generate(seed=3)
    assert repr(r) == (f"<fgsg.Result: {r.stats['triangles']} triangles, {r.stats['instances']} instances, "
                       f"{r.stats['shapes']} shapes>")
    assert repr(kinds.attrs["n"]) == "Attr(name='n', kind='num', default=3.0)"


def test_the_source_carries_the_imported_modules(tmp_path):
    (tmp_path / "part.fgsg").write_text('attr size = 1;\nA ~> S(size, 1, 1) I("cube");\n')
    (tmp_path / "main.fgsg").write_text('import "part" as p;\nX ~> p.A;\n')
    g = fgsg.Grammar.from_file(tmp_path / "main.fgsg")
    assert g.source.startswith(b'import "part" as p;') and b"attr size = 1;" in g.source
    assert list(g.attrs) == ["p.size"]


def test_reports_and_prints_come_with_the_result(tmp_path):
    # Report(key, value) per lot as fgsg run --report writes it; Print's lines (issue 43).
    lots = tmp_path / "lots.geojson"
    lots.write_text('{"type": "FeatureCollection", "crs": {"type": "name", "properties": {"name": '
                    '"urn:fgsg:local-metres"}}, "features": ['
                    '{"type": "Feature", "id": "A", "properties": {}, "geometry": {"type": "Polygon", '
                    '"coordinates": [[[0, 0], [20, 0], [20, 10], [0, 10], [0, 0]]]}},'
                    '{"type": "Feature", "id": "B", "properties": {}, "geometry": {"type": "Polygon", '
                    '"coordinates": [[[30, 0], [42, 0], [42, 8], [30, 8], [30, 0]]]}}]}')
    g = fgsg.Grammar.from_text('Lot ~> Report("area", Lot.area) Print("lot") Extrude(2) Mass;\n', "lots.fgsg")
    for engine in ("interp", "jit"):
        r = g.generate(lots=str(lots), engine=engine)
        assert [s["lot"]["id"] for s in r.reports["starts"]] == ["A", "B"]
        assert [s["reports"]["area"]["values"] for s in r.reports["starts"]] == [[200], [96]]
        assert r.reports["all"]["area"]["sum"] == 296
        assert r.prints == [(1, 33, "lot"), (1, 33, "lot")]


KOCH = os.path.join(SOURCE, "examples", "koch.fgsg")


@pytest.mark.parametrize("kwargs, error, message", [
    ({"max_depth": 2.5}, TypeError, "max_depth must be an int, not float"),
    ({"max_depth": -1}, ValueError, "max_depth must be from 0 to 4294967295, got -1"),
    ({"max_depth": 2**32}, ValueError, "max_depth must be from 0 to 4294967295, got 4294967296"),
    ({"max_seconds": "10"}, TypeError, "max_seconds must be a number (int or float), not str"),
    ({"max_seconds": True}, TypeError, "max_seconds must be a number (int or float), not bool"),
    ({"max_seconds": 0}, ValueError, "max_seconds must be a positive, finite number of seconds, got 0"),
    ({"max_seconds": float("nan")}, ValueError, "max_seconds must be a positive, finite number of seconds, got nan"),
    ({"max_seconds": 10**400}, ValueError, "max_seconds must be a positive, finite number of seconds, got " + str(10**400)),
])
def test_limits_are_checked_like_the_seed(house, kwargs, error, message):
    with pytest.raises(error) as e:
        house.generate(**kwargs)
    assert str(e.value) == message


def test_the_limits_stop_the_derivation_as_fgsg_run_does():
    chain = fgsg.Grammar.from_text('axiom: A(0);\nA(i) : i < 50 ~> I("cube") T(1, 0, 0) A(i + 1);\n', "chain.fgsg")
    koch = fgsg.Grammar.from_file(KOCH)
    full = koch.generate(seed=2)
    assert chain.generate().stats["shapes"] == 51 and full.stats["shapes"] == 256
    for engine in ("jit", "interp"):
        assert koch.generate(seed=2, max_shapes=10, engine=engine).stats["shapes"] == 10
        # Depth 5: A(0) .. A(5), five cubes.
        assert chain.generate(max_depth=5, engine=engine).stats == {
            "shapes": 6, "rewrites": 5, "terminals": 1, "instances": 5, "triangles": 60}
        # A nanosecond runs out at the deadline's first look, long before the 85 rewrites.
        assert koch.generate(seed=2, max_seconds=1e-9, engine=engine).stats["shapes"] < 256
        # A generous limit changes nothing.
        np.testing.assert_array_equal(koch.generate(seed=2, max_seconds=600, engine=engine).positions, full.positions)
