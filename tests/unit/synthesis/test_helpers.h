// Shared helpers for the synthesis tests.
#pragma once

#include "runtime/synthesis/checker.h"
#include "runtime/synthesis/synthesis.h"

#include <catch2/catch.hpp>

#include <string>

namespace synth_test {

using namespace fgsg::rt::synthesis;

inline std::string examplePath(const std::string& name) {
  return std::string(FGSG_SOURCE_DIR) + "/examples/synthesis/" + name;
}

inline Example load(const std::string& name) {
  Example ex;
  Diagnostics d;
  const bool ok = loadExample(examplePath(name), ex, d);
  INFO(formatDiagnostics(d));
  REQUIRE(ok);
  return ex;
}

inline Example parse(const std::string& text) {
  Example ex;
  Diagnostics d;
  const bool ok = parseExampleText(text, "test.txt", ex, d);
  INFO(formatDiagnostics(d));
  REQUIRE(ok);
  return ex;
}

inline CheckSpec specFor(const SynthesisOptions& o) {
  CheckSpec s;
  s.periodic = o.periodic;
  s.border = o.border;
  s.symmetry = o.symmetry;
  s.weights = o.weights.empty() ? nullptr : &o.weights;
  s.connectivity = o.connectivity;
  return s;
}

inline std::string violations(const std::vector<Violation>& v) {
  std::string s;
  for (const auto& x : v) s += x.what + "\n";
  return s;
}

}  // namespace synth_test
