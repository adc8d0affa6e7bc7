// libFuzzer target: a grammar with the modules it imports (frontend/imports.h). The input
// is split at lines "---" into up to five files written to a scratch folder: the first is
// main.fgsg, compiled as `fgsg check` does; the others are m1.fgsg ... m4.fgsg beside it,
// which it (and they) may import (`import "m1" as a;`, with settings, chains, diamonds,
// cycles, missing modules, clashes); "std/..." names the same folder (FGSG_STDLIB is set
// to it: parsing the real standard library's modules on every input would make the
// target some ten times slower, and fuzz_frontend and the tests cover them). Oracles, as fuzz_frontend's: no internal compiler error (E999), every error
// located within the grammar or one of its modules, failure iff an error was reported;
// and a grammar that compiles compiles again from its text with the modules embedded (as
// a compiled library carries them, SourceFile::make) to the same IR.
#include "frontend/diagnostics.h"
#include "ir/pipeline.h"
#include "ir/printer.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <string_view>
#include <unistd.h>
#include <vector>

namespace {

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_imports finding: %s\n", what.c_str());
  std::abort();
}

std::string scratchFolder() {
  char name[] = "/dev/shm/fgsg-fuzz-imports-XXXXXX";
  if (!mkdtemp(name)) finding("cannot create a scratch folder in /dev/shm");
  setenv("FGSG_STDLIB", name, 1);
  unsetenv("FGSG_PATH");
  return name;
}

std::vector<std::string> splitFiles(std::string_view text) {
  std::vector<std::string> parts(1);
  size_t pos = 0;
  while (pos <= text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(pos, end - pos);
    if ((line == "---" || line == "---\r") && parts.size() < 5) parts.emplace_back();
    else parts.back().append(line).append(end < text.size() ? "\n" : "");
    pos = end + 1;
  }
  return parts;
}

bool compile(fgsg::frontend::SourceFile& source, std::string& ir) {
  using namespace fgsg;
  frontend::Diagnostics diags(&source);
  ir::Module module;
  const bool ok = ir::compileSource(source, module, diags);
  for (const auto& d : diags.all()) {
    const std::string shown = diags.format(d);
    if (d.code == "E999") finding(shown);
    if (d.severity == frontend::Severity::Error &&
        (d.range.begin.line < 1 || d.range.begin.line > static_cast<int>(source.lines.size()) + 1))
      finding("error outside the grammar and its modules: " + shown);
  }
  if (ok == diags.hasErrors()) finding(ok ? "compiled, yet errors were reported" : "failed without an error");
  if (ok) ir = ir::printModule(module);
  return ok;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace fgsg;
  if (size > 16384) return -1;
  static const std::string folder = scratchFolder();
  const std::vector<std::string> parts = splitFiles(std::string_view(reinterpret_cast<const char*>(data), size));
  for (size_t i = 1; i <= 4; ++i) {
    const std::string path = folder + "/m" + std::to_string(i) + ".fgsg";
    if (i >= parts.size()) {
      unlink(path.c_str());
      continue;
    }
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << parts[i];
    if (!out) finding("cannot write " + path);
  }
  const std::string main = folder + "/main.fgsg";
  frontend::SourceFile source = frontend::SourceFile::make(main, parts[0]);
  std::string ir;
  if (!compile(source, ir)) return 0;
  frontend::SourceFile embedded = frontend::SourceFile::make(main, source.text);
  std::string again;
  if (!compile(embedded, again)) finding("compiles from its files, not from its text with the modules embedded");
  if (again != ir) finding("the IR differs when the modules come embedded in the text");
  return 0;
}
