// envelope in both dialects (issue #44): CityEngine's forms become fgsg's Envelope and
// EnvelopePerEdge (the arrays' shorter one filled with op_envelope's defaults, base height 0
// and angle 90), and wrong arguments are located errors.
#include "cga_compile_helpers.h"

#include "ir/printer.h"

#include <catch2/catch.hpp>

#include <string>

using namespace fgsg;

namespace {

struct EnvelopeCompiled : frontend::test::CgaCompiled {
  std::string ir;  // the module printed, when it compiled
};

EnvelopeCompiled envelopeCompile(const std::string& text, const std::string& name = "test.cga") {
  EnvelopeCompiled c;
  static_cast<frontend::test::CgaCompiled&>(c) = frontend::test::compileGrammarText(text, name);
  if (c.ok) c.ir = ir::printModule(c.module);
  return c;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("envelope's forms in the .cga dialect", "[cga][dialect][envelope]") {
  const EnvelopeCompiled sides = envelopeCompile("@StartRule\nLot --> envelope(world.up, 12, 6, 45, 3, 60) X\n");
  INFO(sides.messages);
  REQUIRE(sides.ok);
  CHECK(has(sides.ir, "shape-operation \"Envelope\" 1, 12, 6, 45, 3, 60"));
  const EnvelopeCompiled perEdge = envelopeCompile("@StartRule\nLot --> envelope(normal, 20, [1, 2, 3], [45]) X\n");
  INFO(perEdge.messages);
  REQUIRE(perEdge.ok);
  CHECK(has(perEdge.ir, "shape-operation \"EnvelopePerEdge\" 0, 20, 1, 45, 2, 90, 3, 90"));
  const EnvelopeCompiled moreAngles = envelopeCompile("@StartRule\nLot --> envelope(normal, 20, [], [30, 40]) X\n");
  REQUIRE(moreAngles.ok);
  CHECK(has(moreAngles.ir, "shape-operation \"EnvelopePerEdge\" 0, 20, 0, 30, 0, 40"));
}

TEST_CASE("envelope's wrong arguments are located errors", "[cga][dialect][envelope]") {
  const EnvelopeCompiled count = envelopeCompile("@StartRule\nLot --> envelope(normal, 10, 6) X\n");
  CHECK(has(count.messages, "test.cga:2:9: error[E016]: 'envelope' takes 4 to 10 arguments, got 3"));
  const EnvelopeCompiled odd = envelopeCompile("@StartRule\nLot --> envelope(normal, 10, 6, 45, 2) X\n");
  CHECK(has(odd.messages, "test.cga:2:9: error[E016]: 'envelope' takes 4, 6, 8 or 10 arguments, got 5"));
  const EnvelopeCompiled direction = envelopeCompile("@StartRule\nLot --> envelope(up, 10, 6, 45) X\n");
  CHECK(has(direction.messages, "test.cga:2:18: error[E028]: envelope's direction is normal or world.up, not 'up'"));
  const EnvelopeCompiled array = envelopeCompile("@StartRule\nattr h = 3\nLot --> envelope(normal, 10, [1, 2], h) X\n");
  CHECK(has(array.messages, "test.cga:3:38: error[E801]: envelope's base heights and angles other than two arrays"));
  const EnvelopeCompiled body = envelopeCompile("@StartRule\nLot --> envelope(normal, 10, 6, 45) { all : X }\n");
  CHECK_FALSE(body.ok);
}

TEST_CASE("envelope in the fgsg dialect", "[cga][dialect][envelope]") {
  const EnvelopeCompiled ok = envelopeCompile(
      "axiom: Lot;\nLot ~> Envelope(\"normal\", 10, 6, 45) X EnvelopePerEdge(\"world.up\", 8, 0, 45, 0, 90) Y;\n",
      "test.fgsg");
  INFO(ok.messages);
  REQUIRE(ok.ok);
  CHECK(has(ok.ir, "shape-operation \"EnvelopePerEdge\" 1, 8, 0, 45, 0, 90"));
  const EnvelopeCompiled word = envelopeCompile("axiom: Lot;\nLot ~> Envelope(\"up\", 10, 6, 45) X;\n", "test.fgsg");
  CHECK(has(word.messages, "test.fgsg:2:17: error[E028]: 'Envelope' takes normal, world.up here, not \"up\""));
  const EnvelopeCompiled pairs = envelopeCompile("axiom: Lot;\nLot ~> EnvelopePerEdge(\"normal\", 10, 6) X;\n", "test.fgsg");
  CHECK(has(pairs.messages, "test.fgsg:2:8: error[E016]: 'EnvelopePerEdge' takes a direction, maxHeight and pairs"));
  const EnvelopeCompiled forms = envelopeCompile("axiom: Lot;\nLot ~> Envelope(\"normal\", 10, 6, 45, 1) X;\n", "test.fgsg");
  CHECK(has(forms.messages, "error[E016]: 'Envelope' takes 4, 6, 8 or 10 arguments, got 5"));
}

TEST_CASE("contextCompare in both dialects, its wrong arguments located", "[cga][dialect][context]") {
  const EnvelopeCompiled ok = envelopeCompile(
      "@StartRule\nLot --> label(\"lot\") report(\"r\", contextCompare(inter, \"lot\", world.southernmost)) X\n");
  INFO(ok.messages);
  REQUIRE(ok.ok);
  CHECK(has(ok.ir, "Shape.contextCompare(\"inter\", \"lot\", comparison 1)"));
  const EnvelopeCompiled two = envelopeCompile("@StartRule\nLot --> report(\"r\", contextCompare(all, \"lot\")) X\n");
  CHECK(has(two.messages, "test.cga:2:21: error[E016]: 'contextCompare' takes 3 arguments"));
  const EnvelopeCompiled word =
      envelopeCompile("@StartRule\nLot --> report(\"r\", contextCompare(all, \"lot\", world.up)) X\n");
  CHECK(has(word.messages, "test.cga:2:48: error[E016]: the comparison of 'contextCompare' is world.northernmost"));
  const EnvelopeCompiled fgsg = envelopeCompile(
      "axiom: Lot;\nLot ~> Report(\"r\", Shape.contextCompare(\"all\", \"lot\", \"area.smallest\")) X;\n", "test.fgsg");
  INFO(fgsg.messages);
  CHECK(fgsg.ok);
  CHECK(has(fgsg.ir, "comparison 7"));
  const EnvelopeCompiled bad = envelopeCompile(
      "axiom: Lot;\nLot ~> Report(\"r\", Shape.contextCompare(\"all\", \"lot\", \"up\")) X;\n", "test.fgsg");
  CHECK(has(bad.messages, "test.fgsg:2:20: error[E025]: the comparison of 'Shape.contextCompare' is the constant"));
}
