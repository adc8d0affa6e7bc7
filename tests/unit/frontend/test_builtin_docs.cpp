// frontend/builtin_docs.cpp: one doc for every builtin command, function, query and field
// member (the table fgsg lsp hovers with and docs/language.md's reference is generated
// from), each query's signature a call that type-checks, and every .cga entry tied to the
// fgsg builtin the dialect translates it to.
#include "frontend/builtin_docs.h"
#include "frontend/builtins.h"
#include "frontend/cga/cga_parse.h"
#include "frontend/sema_environment.h"
#include "ir/builtins.h"
#include "ir/ir.h"
#include "sema_helpers.h"

#include <catch2/catch.hpp>

#include <set>
#include <string>

using namespace fgsg::frontend;
using namespace fgsg::frontend::test;

namespace {

std::set<std::string> docNamesOf(BuiltinDocKind kind) {
  std::set<std::string> names;
  for (const BuiltinDoc& d : builtinDocs())
    if (d.kind == kind) names.insert(d.name);
  return names;
}

}  // namespace

TEST_CASE("builtin docs: every entry has a doc and a signature, each name once per kind", "[builtin_docs]") {
  std::set<std::pair<int, std::string>> seen;
  for (const BuiltinDoc& d : builtinDocs()) {
    INFO(d.name);
    CHECK(seen.insert({static_cast<int>(d.kind), d.name}).second);
    REQUIRE(d.doc != nullptr);
    CHECK(std::string(d.doc).size() >= 10);
    CHECK(std::string(d.doc).back() == '.');
    CHECK_FALSE(builtinDocSignature(d).empty());
    CHECK(findBuiltinDoc(d.kind, d.name) == &d);
  }
}

TEST_CASE("builtin docs: every command and function of builtins.h has one, and no other", "[builtin_docs]") {
  std::set<std::string> commands, functions;
  for (const CommandInfo& c : allCommands()) commands.insert(c.name);
  for (const FunctionInfo& f : allFunctions()) functions.insert(f.name);
  CHECK(docNamesOf(BuiltinDocKind::Command) == commands);
  CHECK(docNamesOf(BuiltinDocKind::Function) == functions);
  // A command's signature is its CommandInfo's, not a second copy.
  for (const BuiltinDoc& d : builtinDocs())
    if (d.kind == BuiltinDocKind::Command) {
      INFO(d.name);
      CHECK(d.signature == nullptr);
      CHECK(builtinDocSignature(d) == findCommand(d.name)->signature);
    }
  CHECK(builtinDocSignature(*findBuiltinDoc(BuiltinDocKind::Command, "Subdiv")) ==
        "Subdiv(\"X\", s1, s2, ...){ a | b ... }");
}

TEST_CASE("builtin docs: every Feature and field member has one", "[builtin_docs]") {
  std::set<std::string> feature;
  for (const auto& m : featureMemberNames()) feature.insert("Feature." + m);
  std::set<std::string> documentedFeature;
  for (const auto& q : docNamesOf(BuiltinDocKind::Query))
    if (q.rfind("Feature.", 0) == 0) documentedFeature.insert(q);
  CHECK(documentedFeature == feature);
  const auto fieldMembers = fieldMemberNames();
  CHECK(docNamesOf(BuiltinDocKind::FieldMember) == std::set<std::string>(fieldMembers.begin(), fieldMembers.end()));
}

TEST_CASE("builtin docs: every query of the IR's table has one, and no other", "[builtin_docs]") {
  // The IR numbers every Scope, Shape and Geometry query (ir/builtins.cpp's kQueries); the
  // Field, Texture and Feature kinds are named by the module (their members: above).
  std::set<std::string> queries;
  for (int q = 0; q <= static_cast<int>(fgsg::ir::kLastQuery); ++q) {
    const auto& signature = fgsg::ir::querySignature(static_cast<fgsg::ir::Query>(q));
    if (*signature.object) queries.insert(std::string(signature.object) + "." + signature.member);
  }
  std::set<std::string> documented;
  for (const auto& name : docNamesOf(BuiltinDocKind::Query))
    if (name.rfind("Feature.", 0) != 0 && name.rfind("Lot.", 0) != 0) documented.insert(name);
  CHECK(documented == queries);
  CHECK(docNamesOf(BuiltinDocKind::Query).count("Lot.area") == 1);
  CHECK(docNamesOf(BuiltinDocKind::Query).count("Lot.prop") == 1);
}

TEST_CASE("builtin docs: each query's signature type-checks in a grammar", "[builtin_docs]") {
  for (const BuiltinDoc& d : builtinDocs()) {
    if (d.kind != BuiltinDocKind::Query) continue;
    const auto a = analyse("axiom: S(1, 1, 1) A;\nA ~> Print(" + std::string(d.signature) + ");\n");
    INFO(d.signature << "\n" << a.printed);
    CHECK(a.ok);
    CHECK(a.printed.find("error") == std::string::npos);
  }
  // An object's member the table does not have is not one sema knows either.
  CHECK_FALSE(analyse("axiom: S(1, 1, 1) A;\nA ~> Print(Scope.sw);\n").ok);
}

TEST_CASE("builtin docs: each field member type-checks on a field that answers it", "[builtin_docs]") {
  const char* const sources[] = {"design tensor { wedge at vertex 0; }", "design vector { node at vertex 0; }",
                                 "curvature", "image(\"cat.png\")", "scalar(x)"};
  for (const BuiltinDoc& d : builtinDocs()) {
    if (d.kind != BuiltinDocKind::FieldMember) continue;
    bool answered = false;
    for (const char* source : sources) {
      const auto a = analyse(std::string("surface plane(10, 10);\nfield F = ") + source +
                             ";\naxiom: S(1, 1, 1) A;\nA ~> Print(F." + d.name + ");\n");
      answered = answered || a.ok;
    }
    INFO(d.name);
    CHECK(answered);
  }
}

TEST_CASE("builtin docs: .cga entries name the fgsg builtin they become", "[builtin_docs]") {
  const auto operations = cityEngineOperationNames();
  const std::set<std::string> knownOperations(operations.begin(), operations.end());
  for (const BuiltinDoc& d : builtinDocs()) {
    if (d.kind != BuiltinDocKind::CgaOperation && d.kind != BuiltinDocKind::CgaFunction &&
        d.kind != BuiltinDocKind::CgaAttribute) {
      CHECK(d.fgsgName == nullptr);
      continue;
    }
    INFO(d.name);
    REQUIRE(d.fgsgName != nullptr);
    const bool named = findBuiltinDoc(BuiltinDocKind::Command, d.fgsgName) ||
                       findBuiltinDoc(BuiltinDocKind::Function, d.fgsgName) ||
                       findBuiltinDoc(BuiltinDocKind::Query, d.fgsgName);
    CHECK(named);
    if (d.kind == BuiltinDocKind::CgaOperation) CHECK(knownOperations.count(d.name) == 1);
  }
  // The geometry functions the dialect translates are the table's geometry.* entries.
  std::set<std::string> geometry;
  for (const auto& member : cityEngineGeometryFunctionNames()) geometry.insert("geometry." + member);
  std::set<std::string> documented;
  for (const auto& f : docNamesOf(BuiltinDocKind::CgaFunction))
    if (f.rfind("geometry.", 0) == 0) documented.insert(f);
  CHECK(documented == geometry);
  // The functions it translates under their own names (rand, p, inside ...) have entries;
  // those fgsg has under the same name (sin ...) take the fgsg function's.
  for (const auto& [name, signature] : cityEngineFunctionSignatures()) {
    INFO(name);
    CHECK((findBuiltinDoc(BuiltinDocKind::CgaFunction, name) || findBuiltinDoc(BuiltinDocKind::Function, name)));
  }
}

TEST_CASE("builtin docs: the reference markdown has a row per entry", "[builtin_docs]") {
  const std::string md = builtinReferenceMarkdown();
  CHECK(md.find("| `Subdiv(\"X\", s1, s2, ...){ a \\| b ... }` | Cuts the scope along the axis") != std::string::npos);
  CHECK(md.find("| `Scope.sx` | The working scope's size along its X axis") != std::string::npos);
  CHECK(md.find("| `split(x\\|y\\|z) { size : Op \\| ... }*` | CityEngine's split") != std::string::npos);
  size_t rows = 0;
  for (size_t at = md.find("\n| `"); at != std::string::npos; at = md.find("\n| `", at + 1)) ++rows;
  CHECK(rows == builtinDocs().size());
}

TEST_CASE("builtin docs: every surface generator and field source has one", "[builtin_docs]") {
  // sema lists the known ones in its errors (E033, E035): the table must name the same.
  std::set<std::string> documented;
  for (const auto& name : docNamesOf(BuiltinDocKind::Surface)) {
    INFO(name);
    REQUIRE(findSurfaceGenerator(name) != nullptr);
    CHECK(builtinDocSignature(*findBuiltinDoc(BuiltinDocKind::Surface, name)) == findSurfaceGenerator(name)->signature);
    documented.insert(findSurfaceGenerator(name)->signature);
  }
  const auto unknownSurface = declarations("surface nosuch(1);");
  INFO(unknownSurface.printed);
  for (const char* g : {"torus(R, r)", "sphere(r)", "plane(w, h)", "genus2()", "cylinder(r, h)", "tori3(R, r)"}) {
    CHECK(unknownSurface.printed.find(g) != std::string::npos);
    CHECK(documented.count(g) == 1);
  }
  CHECK(documented.size() == 6);
  const auto unknownSource = declarations("surface plane(10, 10);\nfield F = nosuch(1);");
  INFO(unknownSource.printed);
  for (const auto& source : docNamesOf(BuiltinDocKind::FieldSource))
    CHECK(unknownSource.printed.find(source) != std::string::npos);
  CHECK(docNamesOf(BuiltinDocKind::FieldSource) ==
        std::set<std::string>{"tensor", "vector", "scalar", "design", "curvature", "image"});
}
