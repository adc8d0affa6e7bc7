"""Grammar.attrs with each attribute's metadata (#47): kind and default as before, the
annotations and what they say (range, step, enum); Result's preview and Jupyter view."""
import base64
import pickle
import struct

import pytest

import fgsg

CGA = '''version "2023.0"
@Range(min=2, max=30, stepsize=0.5) @Group("Size", 1)
attr height = 12.5
@Enum("flat", "gable") @Description("the roof's shape")
attr roof = "gable"
@Range(1, 8)
attr floors = 3
@Enum(1, 2, 4)
attr bays = 2
@Hidden
attr debug = false
@StartRule
Lot --> extrude(height) Mass
'''


@pytest.fixture
def annotated(tmp_path):
    path = tmp_path / "meta.cga"
    path.write_text(CGA)
    return fgsg.Grammar.from_file(path)


def test_range_step_and_enum_come_from_the_annotations(annotated):
    a = annotated.attrs
    assert a["height"].kind == "num" and a["height"].default == 12.5
    assert a["height"].range == (2.0, 30.0) and a["height"].step == 0.5 and a["height"].enum is None
    assert a["roof"].kind == "str" and a["roof"].enum == ("flat", "gable") and a["roof"].range is None
    assert a["floors"].range == (1.0, 8.0) and a["floors"].step is None  # @Range(lo, hi)
    assert a["bays"].enum == (1.0, 2.0, 4.0)  # a num attribute's values are numbers
    assert a["debug"].range is None and a["debug"].enum is None and a["debug"].step is None
    assert a["debug"].annotations == [fgsg.Annotation("Hidden", (), {})]
    assert a["height"].annotations == annotated.attr_annotations["height"]
    assert repr(a["height"]) == "Attr(name='height', kind='num', default=12.5, range=(2.0, 30.0), step=0.5)"
    assert repr(a["roof"]) == "Attr(name='roof', kind='str', default='gable', enum=('flat', 'gable'))"


def test_attrs_stay_what_code_written_before_expects(annotated):
    # Iterating gives the names; each is still the tuple (name, kind, default).
    assert list(annotated.attrs) == ["height", "roof", "floors", "bays", "debug", "lot:area"]
    name, kind, default = annotated.attrs["height"]
    assert (name, kind, default) == ("height", "num", 12.5)
    assert annotated.attrs["height"] == fgsg.Attr("height", "num", 12.5)
    again = pickle.loads(pickle.dumps(annotated.attrs["roof"]))
    assert again == annotated.attrs["roof"] and again.enum == ("flat", "gable")


def test_fgsg_attributes_have_no_annotations():
    g = fgsg.Grammar.from_text('attr w = 4;\naxiom: A;\nA -> S(w, 1, 1) I("cube");\n', "plain.fgsg")
    w = g.attrs["w"]
    assert (w.kind, w.default, w.annotations, w.range, w.step, w.enum) == ("num", 4.0, [], None, None, None)


def png_size(data):
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    return struct.unpack(">II", data[16:24])


def test_the_preview_is_shown_inline_in_jupyter():
    r = fgsg.Grammar.from_text('axiom: A;\nA -> S(2, 1, 1) I("cube");\n', "cube.fgsg").generate()
    assert png_size(r.preview_png(64, 48)) == (64, 48)
    page = r._repr_html_()
    prefix = '<img src="data:image/png;base64,'
    assert page.startswith(prefix)
    data = base64.b64decode(page[len(prefix):page.index('"', len(prefix))])
    assert png_size(data) == (480, 360)
    assert 'alt="&lt;fgsg.Result: 12 triangles, 1 instances, ' in page
    with pytest.raises(ValueError, match=r"^preview width and height must be from 1 to 8192, got 0 x 48$"):
        r.preview_png(0, 48)
    with pytest.raises(TypeError, match=r"^width must be an int, not float$"):
        r.preview_png(6.5, 48)


def test_a_result_with_nothing_to_draw_shows_its_stats():
    r = fgsg.Grammar.from_text('axiom: A;\nA -> S(2, 1, 1);\n', "empty.fgsg").generate()
    page = r._repr_html_()
    assert page.startswith("<table><caption>&lt;fgsg.Result: 0 triangles, 0 instances, ")
    assert "<tr><td>triangles</td><td>0</td></tr>" in page and "<img" not in page
