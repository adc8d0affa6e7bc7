// Report(key, value) and Print(value) (CGA's report and print, issue 43): values collected
// per start shape in the order they ran, the same from the interpreter and the JIT; the
// statistics of each collection; the JSON of fgsg run --report; where they are refused.
#include "backend/interp/interpreter.h"
#include "backend/jit/jit.h"
#include "backend/native/object_cache.h"
#include "frontend/diagnostics.h"
#include "ir/pipeline.h"
#include "runtime/io/write_reports.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <iostream>
#include <string>

namespace {

using namespace fgsg;

ir::Module compile(const std::string& text) {
  auto file = frontend::SourceFile::make("test.fgsg", text);
  frontend::Diagnostics diags(&file);
  ir::Module m;
  if (!ir::compileSource(file, m, diags)) {
    diags.print(std::cerr);
    FAIL("the test grammar does not compile");
  }
  return m;
}

bool sameValue(const rt::ReportValue& a, const rt::ReportValue& b) {
  return a.kind == b.kind && a.text == b.text &&
         std::memcmp(&a.number, &b.number, sizeof(double)) == 0;  // the same bits
}

// Derives `text` with both engines; they must report and print the same. Returns the
// interpreter's result.
rt::DeriveResult bothEngines(const std::string& text, const rt::DeriveOptions& options = {}) {
  const ir::Module m = compile(text);
  backend::jit::Jit jit;
  const auto code = jit.compileProgram(m, text, backend::native::ObjectCache{std::string()});
  rt::AssetLibrary assets;
  rt::DeriveResult interp = backend::interpret(m, options, assets);
  rt::DeriveResult jitted = backend::deriveCompiled(m, code.program(), options, assets);
  REQUIRE(interp.ok == jitted.ok);
  REQUIRE(interp.reports.size() == jitted.reports.size());
  for (size_t i = 0; i < interp.reports.size(); ++i) {
    CHECK(interp.reports[i].start == jitted.reports[i].start);
    CHECK(interp.reports[i].key == jitted.reports[i].key);
    CHECK(sameValue(interp.reports[i].value, jitted.reports[i].value));
  }
  REQUIRE(interp.prints.size() == jitted.prints.size());
  for (size_t i = 0; i < interp.prints.size(); ++i) {
    CHECK(interp.prints[i].text == jitted.prints[i].text);
    CHECK(interp.prints[i].line == jitted.prints[i].line);
    CHECK(interp.prints[i].col == jitted.prints[i].col);
  }
  CHECK(rt::io::encodeReportsJson(interp, options.lots) == rt::io::encodeReportsJson(jitted, options.lots));
  return interp;
}

rt::Lot rectangleLot(double x0, double w, double h, const std::string& id) {
  rt::Lot lot;
  lot.outer = {{x0, 0}, {x0 + w, 0}, {x0 + w, h}, {x0, h}};
  lot.id = id;
  return lot;
}

}  // namespace

TEST_CASE("Report collects numbers, booleans and strings in the order they ran", "[report]") {
  const auto r = bothEngines(R"(
    attr n = 3;
    Axiom ~> Report("count", n) Report("flag", n > 2) Report("name", "tower")
             S(4, 2, 0) Subdiv("X"){ ~1: Part }*;
    Part ~> Report("width", Scope.sx) Report("index", Shape.index) P;
  )");
  REQUIRE(r.ok);
  REQUIRE(r.reports.size() == 3 + 2 * 4);
  CHECK(r.reports[0].key == "count");
  CHECK(r.reports[0].value.kind == rt::ReportValue::Kind::Number);
  CHECK(r.reports[0].value.number == 3);
  CHECK(r.reports[1].value.kind == rt::ReportValue::Kind::Boolean);
  CHECK(r.reports[1].value.number == 1);
  CHECK(r.reports[2].value.kind == rt::ReportValue::Kind::String);
  CHECK(r.reports[2].value.text == "tower");
  for (size_t k = 3; k < r.reports.size(); k += 2) {
    CHECK(r.reports[k].key == "width");
    CHECK(r.reports[k].value.number == Approx(1.0));
    CHECK(r.reports[k].start == 0);
  }
  const auto collections = rt::collectAllReports(r.reports);
  REQUIRE(collections.size() == 5);  // sorted by key
  CHECK(collections[0].key == "count");
  CHECK(collections[2].key == "index");
  CHECK(collections[2].sum == 0 + 1 + 2 + 3);
  CHECK(collections[2].min == 0);
  CHECK(collections[2].max == 3);
  CHECK(collections[2].average == 1.5);
  CHECK(collections[2].nonZero == 3);
  CHECK(collections[3].key == "name");
  CHECK(collections[3].numeric == 0);
  REQUIRE(collections[3].stringCounts.size() == 1);
  CHECK(collections[3].stringCounts[0] == std::make_pair(std::string("tower"), uint64_t(1)));
  CHECK(collections[4].values.size() == 4);
  CHECK(collections[4].sum == Approx(4.0));
}

TEST_CASE("reports are collected per lot", "[report]") {
  rt::DeriveOptions o;
  o.lots = {rectangleLot(0, 20, 10, "A"), rectangleLot(30, 12, 8, "B")};
  o.lotsName = "lots.geojson";
  const auto r = bothEngines(R"(
    Lot ~> Report("lot.area", Lot.area) Extrude(3) Comp("sidefaces"){ Wall };
    Wall ~> Report("walls", 1) W;
  )", o);
  REQUIRE(r.ok);
  const auto perStart = rt::collectReports(r.reports, 2);
  REQUIRE(perStart.size() == 2);
  REQUIRE(perStart[0].size() == 2);
  CHECK(perStart[0][0].key == "lot.area");
  CHECK(perStart[0][0].sum == 200);
  CHECK(perStart[0][1].sum == 4);
  CHECK(perStart[1][0].sum == 96);
  CHECK(perStart[1][1].values.size() == 4);
  CHECK(rt::io::encodeReportsJson(r, o.lots) ==
        "{\"format\":\"fgsg-reports\",\"version\":1,\"starts\":[\n"
        "{\"start\":0,\"lot\":{\"feature\":0,\"part\":0,\"id\":\"A\"},\"reports\":{"
        "\"lot.area\":{\"values\":[200],\"count\":1,\"sum\":200,\"average\":200,\"min\":200,\"max\":200,\"nnz\":1},"
        "\"walls\":{\"values\":[1,1,1,1],\"count\":4,\"sum\":4,\"average\":1,\"min\":1,\"max\":1,\"nnz\":4}}},\n"
        "{\"start\":1,\"lot\":{\"feature\":0,\"part\":0,\"id\":\"B\"},\"reports\":{"
        "\"lot.area\":{\"values\":[96],\"count\":1,\"sum\":96,\"average\":96,\"min\":96,\"max\":96,\"nnz\":1},"
        "\"walls\":{\"values\":[1,1,1,1],\"count\":4,\"sum\":4,\"average\":1,\"min\":1,\"max\":1,\"nnz\":4}}}\n"
        "],\n"
        "\"all\":{\"lot.area\":{\"values\":[200,96],\"count\":2,\"sum\":296,\"average\":148,\"min\":96,\"max\":200,"
        "\"nnz\":2},\"walls\":{\"values\":[1,1,1,1,1,1,1,1],\"count\":8,\"sum\":8,\"average\":1,\"min\":1,\"max\":1,"
        "\"nnz\":8}}}\n");
}

TEST_CASE("a start shape without reports has an empty entry", "[report]") {
  rt::DeriveResult none;
  CHECK(rt::io::encodeReportsJson(none, {}) ==
        "{\"format\":\"fgsg-reports\",\"version\":1,\"starts\":[\n{\"start\":0,\"reports\":{}}\n],\n\"all\":{}}\n");
}

TEST_CASE("mixed values of one key: numbers summed, strings counted", "[report]") {
  using Kind = rt::ReportValue::Kind;
  const std::string key = "k", a = "a", b = "b";
  const std::vector<rt::Report> reports = {{0, key, {Kind::Number, 2, {}}},
                                           {0, key, {Kind::String, 0, b}},
                                           {0, key, {Kind::Boolean, 0, {}}},
                                           {0, key, {Kind::String, 0, a}}};
  const auto all = rt::collectAllReports(reports);
  REQUIRE(all.size() == 1);
  CHECK(all[0].values.size() == 4);
  CHECK(all[0].numeric == 2);
  CHECK(all[0].sum == 2);
  CHECK(all[0].min == 0);
  CHECK(all[0].max == 2);
  CHECK(all[0].average == 1);
  CHECK(all[0].nonZero == 1);
  REQUIRE(all[0].stringCounts.size() == 2);
  CHECK(all[0].stringCounts[0].first == "a");
  CHECK(all[0].stringCounts[1].first == "b");
}

TEST_CASE("Print keeps its text and place", "[report]") {
  const auto r = bothEngines(R"(
    Axiom ~> Print(0.1 + 0.2) Print("walls") Print(1 < 2) S(2, 3, 4) Print((Scope.sx, Scope.sy, 1.5)) A;
  )");
  REQUIRE(r.ok);
  REQUIRE(r.prints.size() == 4);
  CHECK(r.prints[0].text == "0.30000000000000004");
  CHECK(r.prints[0].line == 2);
  CHECK(r.prints[0].col == 14);
  CHECK(r.prints[1].text == "walls");
  CHECK(r.prints[2].text == "true");
  CHECK(r.prints[3].text == "(2, 3, 1.5)");
}

TEST_CASE("Report and Print need a sequential derivation", "[report]") {
  const ir::Module m = compile("derive parallel 2;\nAxiom ~> F Report(\"k\", 1) A;\nA ~> F A;\n");
  rt::AssetLibrary assets;
  const auto r = backend::interpret(m, {}, assets);
  CHECK_FALSE(r.ok);
  REQUIRE_FALSE(r.messages.empty());
  CHECK(r.messages[0].code == "R009");
  CHECK(r.messages[0].message.find("'Report' cannot appear in a parallel") != std::string::npos);
}

TEST_CASE("each seed derived apart is a start shape of its own", "[report]") {
  rt::DeriveOptions o;
  for (int k = 0; k < 3; ++k) {
    rt::DeriveOptions::Seed s;
    s.point[0] = k == 0 ? 1 : 0, s.point[1] = k == 1 ? 1 : 0, s.point[2] = k == 2 ? 1 : 0;
    o.seeds.push_back(s);
  }
  const auto r = bothEngines(R"(
    surface sphere(1);
    start = A(0)
    A(n) : n < 2 ~> Report("step", n) Print("grown") I("cube") A(n + 1)
  )", o);
  REQUIRE(r.ok);
  REQUIRE(r.instances.startBounds.size() == 4);  // three plants, apart
  REQUIRE(r.reports.size() == 6);
  for (size_t k = 0; k < 6; ++k) {
    CHECK(r.reports[k].start == k / 2);
    CHECK(r.reports[k].value.number == double(k % 2));
  }
  REQUIRE(r.prints.size() == 6);
  CHECK(r.prints[5].start == 2);
  const auto perStart = rt::collectReports(r.reports, 3);
  for (const auto& start : perStart) {
    REQUIRE(start.size() == 1);
    CHECK(start[0].sum == 1);
  }
}
