// libFuzzer target: the whole front end on arbitrary text (parse, semantic analysis,
// lowering, folding, verification) with every diagnostic formatted, and the IR printed
// when the grammar compiles. Findings: crashes, sanitizer reports, uncaught exceptions,
// an internal compiler error (E999: the verifier rejected lowered IR), a compile that
// fails without an error, and an error whose location lies outside the text.
#include "frontend/diagnostics.h"
#include "ir/pipeline.h"
#include "ir/printer.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_frontend finding: %s\n", what.c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace fgsg;
  if (size > 16384) return -1;  // long inputs only slow the search down
  const std::string text(reinterpret_cast<const char*>(data), size);

  const frontend::SourceFile source = frontend::SourceFile::make("fuzz.fgsg", text);
  frontend::Diagnostics diags(&source);
  ir::Module module;
  const bool ok = ir::compileSource(source, module, diags);
  for (const auto& d : diags.all()) {
    const std::string shown = diags.format(d);
    if (d.code == "E999") finding(shown);
    if (d.severity == frontend::Severity::Error &&
        (d.range.begin.line < 1 || d.range.begin.line > static_cast<int>(source.lines.size()) + 1))
      finding("error outside the text: " + shown);
  }
  if (ok == diags.hasErrors()) finding(ok ? "compiled, yet errors were reported" : "failed without an error");
  if (ok) (void)ir::printModule(module);
  return 0;
}
