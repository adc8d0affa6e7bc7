"""Grammar.attr_annotations: a .cga attr's annotations (@Range, @Enum, @Hidden, @Group,
@Order, @Description ...) as Annotation(name, args, named), without changing Grammar.attrs."""
import fgsg

CGA = '''version "2023.0"
@Range(min=2, max=30, stepsize=0.5) @Group("Size", 1) @Order(2)
attr height = 12.5
@Enum("flat", "gable") @Description("the roof's shape")
attr roof = "gable"
@Hidden
attr debug = false
attr plain = 3
@StartRule
Lot --> extrude(height) Mass
'''


def test_cga_attr_annotations(tmp_path):
    path = tmp_path / "ann.cga"
    path.write_text(CGA)
    g = fgsg.Grammar.from_file(path)
    notes = g.attr_annotations
    assert list(notes)[:4] == ["height", "roof", "debug", "plain"]
    assert notes["height"] == [
        fgsg.Annotation("Range", (), {"min": "2", "max": "30", "stepsize": "0.5"}),
        fgsg.Annotation("Group", ("Size", "1"), {}),
        fgsg.Annotation("Order", ("2",), {}),
    ]
    assert notes["roof"] == [
        fgsg.Annotation("Enum", ("flat", "gable"), {}),
        fgsg.Annotation("Description", ("the roof's shape",), {}),
    ]
    assert notes["debug"] == [fgsg.Annotation("Hidden", (), {})]
    assert notes["plain"] == []
    assert notes["height"][0].named["max"] == "30"
    # Grammar.attrs is as before: (name, kind, default).
    assert g.attrs["height"] == fgsg.Attr("height", "num", 12.5)
    assert g.attrs["roof"] == fgsg.Attr("roof", "str", "gable")
    assert g.attrs["debug"] == fgsg.Attr("debug", "bool", False)
    assert tuple(g.attrs["plain"]) == ("plain", "num", 3.0)


def test_fgsg_attrs_have_no_annotations():
    g = fgsg.Grammar.from_text('attr w = 4;\naxiom: A;\nA -> S(w, 1, 1) I("cube");\n', "plain.fgsg")
    assert g.attr_annotations == {"w": []}
