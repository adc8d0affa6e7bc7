// fgsg view's design element edits written into a grammar's text (cli/view_field_edit.h):
// only the element's own words change, every other byte stays. Expected texts by hand.
#include "cli/view_field_edit.h"

#include <catch2/catch.hpp>

using fgsg::cli::editFieldDesignText;
using fgsg::cli::FieldEditBounds;
using fgsg::cli::PageFieldElement;

namespace {

// A 10 x 10 plane's box: positions are written to 1e-4 (a millionth of its diagonal, 14.1).
FieldEditBounds fieldEditBox() {
  FieldEditBounds b;
  b.min[0] = b.min[1] = -5;
  b.max[0] = b.max[1] = 5;
  return b;
}

// The edited text, or "refused: REASON".
std::string fieldEdited(const std::string& text, const PageFieldElement& edit) {
  std::string out, reason;
  if (!editFieldDesignText("g.fgsg", text, "F", edit, fieldEditBox(), out, reason)) return "refused: " + reason;
  return out;
}

PageFieldElement fieldEditOf(PageFieldElement::Op op, uint32_t index = 0) {
  PageFieldElement e;
  e.op = op;
  e.index = index;
  return e;
}

const std::string kFieldEditLaidOut =
    "const hole = (0, 2.6, 0);\nconst k = 2;\nsurface plane(10, 10, 48);\nfield F = design tensor {\n"
    "  regular at vertex 0 angle 30 decay 0.5;\n  wedge at (0.2, 0.1, 0.9) decay 2; // the wedge\n"
    "  trisector at hole decay 2 strength k;\n  smooth 300;\n};\nAxiom ~> I(\"cube\");\n";

std::string fieldEditLaidOut(const std::string& from, const std::string& to) {
  std::string text = kFieldEditLaidOut;
  const size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE("view field edits: a new element goes after the block's last item, as it is laid out") {
  PageFieldElement add = fieldEditOf(PageFieldElement::Op::Add);
  add.kind = "wedge";
  add.position[0] = -1.98731234;  // to 1e-4
  add.position[1] = -0.00001;     // -0 is written 0
  add.position[2] = -1e-9;
  const std::string oneLine =
      "// c\nsurface plane(10, 10, 48);\nfield F = design tensor { trisector at (2, 0, 0) decay 1; };  // x\n"
      "Axiom ~> I(\"cube\");\n";
  CHECK(fieldEdited(oneLine, add) ==
        "// c\nsurface plane(10, 10, 48);\nfield F = design tensor { trisector at (2, 0, 0) decay 1; "
        "wedge at (-1.9873, 0, 0); };  // x\nAxiom ~> I(\"cube\");\n");
  CHECK(fieldEdited(kFieldEditLaidOut, add) == fieldEditLaidOut("  smooth 300;\n", "  smooth 300;\n  wedge at (-1.9873, 0, 0);\n"));
  PageFieldElement regular = add;
  regular.kind = "regular";
  regular.hasDirection = true;
  regular.direction[0] = regular.direction[1] = 3;  // written as a unit vector
  regular.direction[2] = 0;
  regular.hasStrength = true;
  regular.strength = 2.5;
  CHECK(fieldEdited(oneLine, regular) ==
        "// c\nsurface plane(10, 10, 48);\nfield F = design tensor { trisector at (2, 0, 0) decay 1; "
        "regular at (-1.9873, 0, 0) direction (0.7071, 0.7071, 0) strength 2.5; };  // x\nAxiom ~> I(\"cube\");\n");
  // Characters of several bytes before it: columns count characters, not bytes.
  CHECK(fieldEdited("surface plane(10,10);\nfield F = design tensor { /* é ü */ node at (0,0,0); };\n", add) ==
        "surface plane(10,10);\nfield F = design tensor { /* é ü */ node at (0,0,0); wedge at (-1.9873, 0, 0); };\n");
  // CRLF lines stay CRLF.
  CHECK(fieldEdited("surface plane(10,10);\r\nfield F = design tensor {\r\n  node at (0,0,0);\r\n};\r\n", add) ==
        "surface plane(10,10);\r\nfield F = design tensor {\r\n  node at (0,0,0);\r\n  wedge at (-1.9873, 0, 0);\r\n};\r\n");
}

TEST_CASE("view field edits: a move rewrites the at words, a strength its own, a delete the item") {
  PageFieldElement move = fieldEditOf(PageFieldElement::Op::Move, 0);
  move.position[0] = 1.5;
  move.position[1] = 2.25;
  CHECK(fieldEdited(kFieldEditLaidOut, move) == fieldEditLaidOut("regular at vertex 0 angle", "regular at (1.5, 2.25, 0) angle"));
  move.index = 2;  // `at hole`: the const's name goes with its keyword
  CHECK(fieldEdited(kFieldEditLaidOut, move) == fieldEditLaidOut("trisector at hole decay", "trisector at (1.5, 2.25, 0) decay"));
  PageFieldElement strength = fieldEditOf(PageFieldElement::Op::Strength, 2);
  strength.hasStrength = true;
  strength.strength = -0.5;
  CHECK(fieldEdited(kFieldEditLaidOut, strength) == fieldEditLaidOut("strength k;", "strength -0.5;"));
  strength.index = 1;  // none written: after the last word, before the ';' and the comment
  CHECK(fieldEdited(kFieldEditLaidOut, strength) == fieldEditLaidOut("decay 2; // the wedge", "decay 2 strength -0.5; // the wedge"));
  // A deleted element alone on its line takes the line (and its comment) with it.
  CHECK(fieldEdited(kFieldEditLaidOut, fieldEditOf(PageFieldElement::Op::Delete, 1)) ==
        fieldEditLaidOut("  wedge at (0.2, 0.1, 0.9) decay 2; // the wedge\n", ""));
  CHECK(fieldEdited(kFieldEditLaidOut, fieldEditOf(PageFieldElement::Op::Delete, 2)) ==
        fieldEditLaidOut("  trisector at hole decay 2 strength k;\n", ""));
  const std::string inline2 = "field F = design tensor { wedge at (1, 0, 0); trisector at (2, 0, 0); };\n";
  CHECK(fieldEdited(inline2, fieldEditOf(PageFieldElement::Op::Delete, 0)) == "field F = design tensor { trisector at (2, 0, 0); };\n");
  CHECK(fieldEdited(inline2, fieldEditOf(PageFieldElement::Op::Delete, 1)) == "field F = design tensor { wedge at (1, 0, 0); };\n");
}

TEST_CASE("view field edits: what cannot be written is refused with a reason") {
  PageFieldElement add = fieldEditOf(PageFieldElement::Op::Add);
  add.kind = "wedge";
  CHECK(fieldEdited(kFieldEditLaidOut, fieldEditOf(PageFieldElement::Op::Delete, 3)) ==
        "refused: field F has 3 design elements: no element 3");
  CHECK(fieldEdited("field F = design tensor { node at (0,0,0); };\n", fieldEditOf(PageFieldElement::Op::Delete, 0)) ==
        "refused: a design needs at least one element: field F's last one stays");
  PageFieldElement far = add;
  far.position[0] = 19.2;  // the box (-5..5) grown by its diagonal (14.14) ends at 19.14
  CHECK(fieldEdited(kFieldEditLaidOut, far) ==
        "refused: the position is off the surface (farther outside its bounding box than its diagonal)");
  far.position[0] = 19.1;
  CHECK(fieldEdited(kFieldEditLaidOut, far).find("wedge at (19.1, 0, 0);") != std::string::npos);
  CHECK(fieldEdited("field F = design vector { node at (0,0,0); };\n", add) ==
        "refused: a wedge is a tensor field's singularity; field F is a vector design");
  CHECK(fieldEdited("field F = tensor(\"f.tfield\");\n", add) ==
        "refused: field F is not a design (`design tensor { ... }`): it has no elements to edit");
  CHECK(fieldEdited("field G = design tensor { node at (0,0,0); };\n", add).find("the grammar's first field is G") !=
        std::string::npos);
  CHECK(fieldEdited("Axiom ~> I(\"cube\");\n", add) == "refused: the grammar declares no field");
  CHECK(fieldEdited("field F = design tensor { node at (0,0,0) };\n", add).find("refused: the grammar does not parse") == 0);
}
