// What a page may send fgsg view (cli/view_message.h): checked before anything changes.
#include "cli/view_message.h"

#include <catch2/catch.hpp>

using fgsg::cli::PageRequest;
using fgsg::cli::parsePageRequest;

namespace {

std::string refused(const std::string& text) {
  PageRequest r;
  std::string reason;
  if (parsePageRequest(text, r, reason)) return "";
  return reason.empty() ? "(no reason)" : reason;
}

}  // namespace

TEST_CASE("view messages: set and pick as the page sends them") {
  PageRequest r;
  std::string reason;
  REQUIRE(parsePageRequest(R"({"type":"set","attrs":{"lot_width":"24","roof":true,"h":3.5},"seed":7})", r, reason));
  CHECK(r.kind == PageRequest::Kind::Set);
  CHECK(r.hasAttrs);
  CHECK(r.hasSeed);
  CHECK(r.seed == 7);
  REQUIRE(r.attrs.size() == 3);
  CHECK(r.attrs[0] == std::make_pair(std::string("h"), std::string("3.5")));
  CHECK(r.attrs[1] == std::make_pair(std::string("lot_width"), std::string("24")));
  CHECK(r.attrs[2] == std::make_pair(std::string("roof"), std::string("true")));
  REQUIRE(parsePageRequest(R"({"type":"set","seed":3})", r, reason));
  CHECK_FALSE(r.hasAttrs);
  REQUIRE(parsePageRequest(R"({"type":"pick","instance":12})", r, reason));
  CHECK(r.kind == PageRequest::Kind::Pick);
  CHECK(r.instance == 12);
}

TEST_CASE("view messages: a derivation step, a whole number up to the largest derive parallel N (#48)") {
  PageRequest r;
  std::string reason;
  REQUIRE(parsePageRequest(R"({"type":"set","step":0})", r, reason));
  CHECK(r.hasStep);
  CHECK(r.step == 0);
  CHECK_FALSE(r.hasAttrs);
  CHECK_FALSE(r.hasSeed);
  REQUIRE(parsePageRequest(R"({"type":"set","attrs":{"n":"2"},"step":2147483647})", r, reason));
  CHECK(r.step == 2147483647u);
  REQUIRE(parsePageRequest(R"({"type":"set","seed":4})", r, reason));
  CHECK_FALSE(r.hasStep);  // the page's step stays
  const std::string whole = "set: \"step\" must be a whole number from 0 to 2147483647";
  CHECK(refused(R"({"type":"set","step":-1})") == whole);
  CHECK(refused(R"({"type":"set","step":1.5})") == whole);
  CHECK(refused(R"({"type":"set","step":"3"})") == whole);
  CHECK(refused(R"({"type":"set","step":2147483648})") == whole);
  CHECK(refused(R"({"type":"set","step":null})") == whole);
}

TEST_CASE("view messages: garbage, wrong kinds and unknown fields are refused with a reason") {
  CHECK(refused("") == "not a JSON object");
  CHECK(refused("\x01\x02garbage") == "not a JSON object");
  CHECK(refused("[1,2]") == "not a JSON object");
  CHECK(refused(R"({"attrs":{}})") == "no \"type\"");
  CHECK(refused(R"({"type":"read","file":"/etc/passwd"})").find("unknown message type") == 0);
  CHECK(refused(R"({"type":"set","file":"/etc/passwd"})").find("unknown field") != std::string::npos);
  CHECK_FALSE(refused(R"({"type":"set","seed":-1})").empty());
  CHECK_FALSE(refused(R"({"type":"set","seed":1.5})").empty());
  CHECK_FALSE(refused(R"({"type":"set","seed":"1"})").empty());
  CHECK_FALSE(refused(R"({"type":"set","attrs":[1]})").empty());
  CHECK_FALSE(refused(R"({"type":"set","attrs":{"x":[1]}})").empty());
  CHECK_FALSE(refused(R"({"type":"set","attrs":{"x":null}})").empty());
  CHECK_FALSE(refused(R"({"type":"set","attrs":{"x":1e999}})").empty());  // not finite
  CHECK_FALSE(refused(R"({"type":"set","attrs":{"":"1"}})").empty());
  CHECK_FALSE(refused(R"({"type":"set","attrs":{")" + std::string(200, 'n') + R"(":"1"}})").empty());
  CHECK_FALSE(refused(R"({"type":"set","attrs":{"x":")" + std::string(5000, 'v') + R"("}})").empty());
  CHECK_FALSE(refused(R"({"type":"pick"})").empty());
  CHECK_FALSE(refused(R"({"type":"pick","instance":4294967296})").empty());
  CHECK_FALSE(refused(R"({"type":"pick","instance":1,"zz":2})").empty());
  // fuzz_view_message (issue 42): the JSON parser stops at a NUL byte, so a valid message
  // followed by a NUL and anything was accepted as that message.
  CHECK(refused(std::string(R"({"type":"set","seed":3})") + '\0' + "garbage") ==
        "a NUL byte at byte 23 (not JSON text)");
  CHECK(refused(std::string("\" \"\0\0\0type\": \"pcki\"", 20)).find("a NUL byte at byte 3") == 0);
  // A long message's text is not quoted back whole.
  const std::string why = refused(R"({"type":")" + std::string(10000, 'q') + R"("})");
  CHECK(why.size() < 200);
}

TEST_CASE("view messages: size and nesting are bounded before any parse") {
  // V3: 100 000 levels once overflowed the stack in a recursive dump.
  const auto deep = [](int n) {
    return R"({"type":"set","attrs":{"x":)" + std::string(n, '[') + std::string(n, ']') + "}}";
  };
  CHECK_FALSE(refused(deep(100000)).empty());
  CHECK(refused(deep(30000)).find("nested deeper") != std::string::npos);  // under the size cap: the nesting check
  CHECK(refused(deep(3)).find("nested deeper") != std::string::npos);
  CHECK(fgsg::cli::jsonNestingWithin(R"({"a":"[[[[[[[[[[[["})", 1));  // brackets in strings do not count
  CHECK(fgsg::cli::jsonNestingWithin(R"({"a":"\"[[[[[["})", 1));
  CHECK_FALSE(fgsg::cli::jsonNestingWithin("[[[", 2));
  const std::string big = R"({"type":"set","attrs":{"x":")" + std::string(70000, 'v') + R"("}})";
  CHECK(refused(big).find("message of") == 0);
  std::string many = R"({"type":"set","attrs":{)";
  for (int i = 0; i < 300; ++i) many += (i ? "," : "") + ("\"a" + std::to_string(i) + "\":1");
  CHECK_FALSE(refused(many + "}}").empty());
}

TEST_CASE("view messages: seeds, paint, undo and redo as the page sends them (#49)") {
  PageRequest r;
  std::string reason;
  REQUIRE(parsePageRequest(R"({"type":"seeds","seeds":[[0.25,1,0],[1,2,3,0,0,-1]]})", r, reason));
  CHECK(r.kind == PageRequest::Kind::Seeds);
  REQUIRE(r.seeds.size() == 2);
  CHECK(r.seeds[0].point[0] == 0.25);
  CHECK_FALSE(r.seeds[0].hasDirection);
  CHECK(r.seeds[1].hasDirection);
  CHECK(r.seeds[1].direction[2] == -1);
  REQUIRE(parsePageRequest(R"({"type":"seeds","seeds":[]})", r, reason));
  CHECK(r.seeds.empty());
  REQUIRE(parsePageRequest(
      R"({"type":"paint","texture":"mask","stroke":4,"dabs":[[0,1,0],[0.1,1,0]],"radius":0.2,"strength":0.5,"value":1,"erase":false})",
      r, reason));
  CHECK(r.kind == PageRequest::Kind::Paint);
  CHECK(r.paint.texture == "mask");
  CHECK(r.paint.stroke == 4);
  CHECK(r.paint.dabs.size() == 2);
  CHECK(r.paint.radius == 0.2);
  CHECK(r.paint.strength == 0.5);
  REQUIRE(parsePageRequest(R"({"type":"undo"})", r, reason));
  CHECK(r.kind == PageRequest::Kind::Undo);
  REQUIRE(parsePageRequest(R"({"type":"redo"})", r, reason));
  CHECK(r.kind == PageRequest::Kind::Redo);
}

TEST_CASE("view messages: resend takes no field (#49, item 5)") {
  PageRequest r;
  std::string reason;
  REQUIRE(parsePageRequest(R"({"type":"resend"})", r, reason));
  CHECK(r.kind == PageRequest::Kind::Resend);
  CHECK(refused(R"({"type":"resend","pieces":[0]})").find("unknown field") != std::string::npos);
  CHECK(refused(R"({"type":"resend","file":"/etc/passwd"})").find("unknown field") != std::string::npos);
}

TEST_CASE("view messages: bad seeds and strokes are refused with a reason (#49)") {
  CHECK(refused(R"({"type":"seeds","seeds":[[0,1]]})").find("seed 0") != std::string::npos);
  CHECK(refused(R"({"type":"seeds","seeds":[[0,1,0,0,0,0]]})").find("non-zero heading") != std::string::npos);
  CHECK(refused(R"({"type":"seeds","seeds":[[0,1,1e300]]})") != "");
  CHECK(refused(R"({"type":"seeds","seeds":[["0",1,0]]})") != "");
  CHECK(refused(R"({"type":"seeds","seeds":[[0,1,0]],"file":"/etc/passwd"})").find("unknown field") != std::string::npos);
  std::string many = R"({"type":"seeds","seeds":[)";
  for (int i = 0; i < 1025; ++i) many += std::string(i ? "," : "") + "[0,0,0]";
  CHECK(refused(many + "]}").find("at most 1024") != std::string::npos);
  const std::string dab = R"("stroke":1,"dabs":[[0,0,0]],"radius":0.1)";
  CHECK(refused(R"({"type":"paint","texture":"../g.fgsg",)" + dab + "}").find("texture") != std::string::npos);
  CHECK(refused(R"({"type":"paint","texture":"a/b",)" + dab + "}") != "");
  CHECK(refused(R"({"type":"paint","texture":"",)" + dab + "}") != "");
  CHECK(refused(R"({"type":"paint","texture":"mask","stroke":1,"dabs":[],"radius":0.1})").find("dabs") != std::string::npos);
  CHECK(refused(R"({"type":"paint","texture":"mask","stroke":1,"dabs":[[0,0,0]],"radius":-1})").find("radius") != std::string::npos);
  CHECK(refused(R"({"type":"paint","texture":"mask",)" + dab + R"(,"strength":2})").find("strength") != std::string::npos);
  CHECK(refused(R"({"type":"paint","texture":"mask",)" + dab + R"(,"value":-0.1})").find("value") != std::string::npos);
  CHECK(refused(R"({"type":"paint","texture":"mask",)" + dab + R"(,"path":"x.png"})").find("unknown field") != std::string::npos);
  CHECK(refused(R"({"type":"paint","texture":"mask","stroke":-1,"dabs":[[0,0,0]],"radius":0.1})").find("stroke") != std::string::npos);
  std::string dabs = R"({"type":"paint","texture":"mask","stroke":1,"radius":0.1,"dabs":[)";
  for (int i = 0; i < 257; ++i) dabs += std::string(i ? "," : "") + "[0,0,0]";
  CHECK(refused(dabs + "]}").find("dabs") != std::string::npos);
  CHECK(refused(R"({"type":"undo","steps":3})").find("unknown field") != std::string::npos);
}

TEST_CASE("view messages: field edits undone and redone, a drag's moves numbered (#49)") {
  PageRequest r;
  std::string reason;
  REQUIRE(parsePageRequest(R"({"type":"undo"})", r, reason));
  CHECK(r.history == PageRequest::History::Paint);  // as before: the paint strokes'
  REQUIRE(parsePageRequest(R"({"type":"undo","history":"field"})", r, reason));
  CHECK(r.kind == PageRequest::Kind::Undo);
  CHECK(r.history == PageRequest::History::Field);
  REQUIRE(parsePageRequest(R"({"type":"redo","history":"paint"})", r, reason));
  CHECK(r.kind == PageRequest::Kind::Redo);
  CHECK(r.history == PageRequest::History::Paint);
  REQUIRE(parsePageRequest(R"({"type":"fieldElement","op":"move","index":1,"position":[0,1,0],"drag":7})", r, reason));
  CHECK(r.element.drag == 7);
  REQUIRE(parsePageRequest(R"({"type":"fieldElement","op":"move","index":1,"position":[0,1,0]})", r, reason));
  CHECK(r.element.drag == 0);
  REQUIRE(parsePageRequest(R"({"type":"fieldElement","op":"move","index":1,"position":[0,1,0],"drag":9007199254740991})",
                           r, reason));
  CHECK(r.element.drag == 9007199254740991ull);

  CHECK(refused(R"({"type":"undo","history":"grammar"})").find("\"paint\" or \"field\"") != std::string::npos);
  CHECK(refused(R"({"type":"undo","history":["field"]})").find("\"paint\" or \"field\"") != std::string::npos);
  CHECK(refused(R"({"type":"redo","history":"field","count":2})").find("unknown field") != std::string::npos);
  CHECK(refused(R"({"type":"undo","history":"field","file":"g.fgsg"})").find("unknown field") != std::string::npos);
  const std::string move = R"({"type":"fieldElement","op":"move","index":0,"position":[0,0,0],"drag":)";
  CHECK(refused(move + "0}").find("\"drag\"") != std::string::npos);
  CHECK(refused(move + "-1}").find("\"drag\"") != std::string::npos);
  CHECK(refused(move + "1.5}").find("\"drag\"") != std::string::npos);
  CHECK(refused(move + "\"1\"}").find("\"drag\"") != std::string::npos);
  CHECK(refused(move + "9007199254740992}").find("\"drag\"") != std::string::npos);
  CHECK(refused(R"({"type":"fieldElement","op":"add","kind":"wedge","position":[0,0,0],"drag":1})")
            .find("unknown field") != std::string::npos);
  CHECK(refused(R"({"type":"fieldElement","op":"strength","index":0,"strength":2,"drag":1})")
            .find("unknown field") != std::string::npos);
}
