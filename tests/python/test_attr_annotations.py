"""Grammar.attr_annotations: a .cga attr's annotations (@Range, @Enum, @Hidden, @Group,
@Order, @Description ...) as Annotation(name, args, named), without changing Grammar.attrs."""
import pytest

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


TWO_RULES = '''@StartRule
Lot --> split(x) { 5 : A }*
Other --> split(x) { 10 : A }*
A --> extrude(3) Mass
'''


def test_start_rule():
    """from_text/from_file(start_rule=...): as fgsg run --start-rule (the default lot is 20 m)."""
    own = fgsg.Grammar.from_text(TWO_RULES, "two.cga").generate(seed=1)
    other = fgsg.Grammar.from_text(TWO_RULES, "two.cga", start_rule="Other").generate(seed=1)
    assert own.stats["instances"] == 4
    assert other.stats["instances"] == 2
    with pytest.raises(fgsg.GrammarError, match=r"--start-rule Nope: the start rule 'Nope' is not a rule of this file; "
                                                r"rules that can start: Lot \(@StartRule\), A, Other"):
        fgsg.Grammar.from_text(TWO_RULES, "two.cga", start_rule="Nope")
    with pytest.raises(fgsg.GrammarError, match=r"only a \.cga grammar"):
        fgsg.Grammar.from_text('axiom: A;\nA -> I("cube");\n', "g.fgsg", start_rule="A")
    with pytest.raises(TypeError):
        fgsg.Grammar.from_text(TWO_RULES, "two.cga", start_rule=3)


STYLED = '''@StartRule
Lot --> split(x) { 5 : A }*
A --> extrude(3) Mass
style Wide
Lot --> split(x) { 10 : A }*
'''


def test_start_rule_chooses_a_style():
    """start_rule="Style$Rule": the rule in that style, as CityEngine's rule packages write it
    (the style Wide redefines Lot: two 10 m parts of the default 20 m lot instead of four)."""
    assert fgsg.Grammar.from_text(STYLED, "styled.cga").generate(seed=1).stats["instances"] == 4
    wide = fgsg.Grammar.from_text(STYLED, "styled.cga", start_rule="Wide$Lot").generate(seed=1)
    assert wide.stats["instances"] == 2
    with pytest.raises(fgsg.GrammarError, match=r"this file has no style 'Wid' \(its styles: Default, Wide\); "
                                                r"did you mean 'Wide'\?"):
        fgsg.Grammar.from_text(STYLED, "styled.cga", start_rule="Wid$Lot")
