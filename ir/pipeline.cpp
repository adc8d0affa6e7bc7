#include "ir/pipeline.h"
#include "ir/pipeline_reusing.h"

#include "frontend/imports.h"
#include "frontend/parse.h"
#include "frontend/sema.h"
#include "ir/fold.h"
#include "ir/lower.h"
#include "ir/verifier.h"
#include "runtime/io/read_input.h"

#include <chrono>
#include <sstream>

namespace fgsg::ir {
namespace {

double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// The passes after parsing the grammar's own text, for both entries below.
bool compileParsedWithImports(frontend::SourceFile& file, Module& out, frontend::Diagnostics& diags,
                              CompileTimes* times, frontend::Program& program, bool parsed,
                              std::chrono::steady_clock::time_point t0);

}  // namespace

bool compileSource(frontend::SourceFile& file, Module& out, frontend::Diagnostics& diags,
                   CompileTimes* times, frontend::Program* keep) {
  const auto t0 = std::chrono::steady_clock::now();
  frontend::Program local;
  frontend::Program& program = keep ? *keep : local;
  program.fileName = file.name;
  const bool parsed = frontend::parseProgram(file, program, diags);
  return compileParsedWithImports(file, out, diags, times, program, parsed, t0);
}

bool compileSourceReusing(frontend::SourceFile& file, Module& out, frontend::Diagnostics& diags,
                          frontend::Program& keep, frontend::StatementReuse& reuse) {
  const auto t0 = std::chrono::steady_clock::now();
  keep.fileName = file.name;
  const bool parsed = frontend::parseProgramReusing(file, keep, diags, reuse);
  return compileParsedWithImports(file, out, diags, nullptr, keep, parsed, t0);
}

namespace {

bool compileParsedWithImports(frontend::SourceFile& file, Module& out, frontend::Diagnostics& diags,
                              CompileTimes* times, frontend::Program& program, bool parsed,
                              std::chrono::steady_clock::time_point t0) {
  // Its modules: their texts join `file`'s, which then keys the JIT's cache on them too.
  parsed = frontend::resolveImports(file, program, diags) && parsed;
  if (times) times->parseSeconds = secondsSince(t0);
  if (!parsed) return false;
  t0 = std::chrono::steady_clock::now();
  frontend::SemaResult sema;
  bool analysed = frontend::analyze(program, sema, diags);
  if (times) times->analyzeSeconds = secondsSince(t0);
  if (!analysed) return false;
  t0 = std::chrono::steady_clock::now();
  out = lowerProgram(program, sema);
  foldConstants(out);
  std::vector<std::string> problems;
  if (!verifyModule(out, problems)) {
    std::string all;
    for (const auto& p : problems) all += "\n  " + p;
    diags.error("E999", frontend::SourceRange{{1, 1}, {1, 1}},
                "internal compiler error: the IR failed verification (please report this "
                "grammar):" + all);
    return false;
  }
  if (times) times->lowerSeconds = secondsSince(t0);
  return true;
}

}  // namespace

bool readSourceFile(const std::string& path, frontend::SourceFile& out, std::string& error) {
  std::string text;
  if (!rt::io::readInputFile(path, "a grammar file", text, error)) return false;
  out = frontend::SourceFile::make(path, std::move(text));
  return true;
}

}  // namespace fgsg::ir
