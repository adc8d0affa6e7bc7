// libFuzzer target: the model-synthesis example readers (WFC-style tile-set JSON when the
// text starts with '{', the label-grid text format otherwise), then a small synthesis
// from what was read. Oracles: a failure comes with a located diagnostic; a grid written
// back (writeLabelGridText) reads back as the same grid and labels; a model the solver
// calls consistent passes the independent checker.
#include "runtime/synthesis/checker.h"
#include "runtime/synthesis/example.h"
#include "runtime/synthesis/synthesis.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_synthesis_example finding: %s\n", what.c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace fgsg::rt::synthesis;
  if (size > 16384) return -1;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const size_t first = text.find_first_not_of(" \t\r\n");
  const bool json = first != std::string_view::npos && text[first] == '{';

  Example ex;
  Diagnostics diags;
  const bool ok = json ? parseTileSetJson(text, "fuzz.json", ex, diags) : parseExampleText(text, "fuzz.txt", ex, diags);
  if (!ok) {
    if (diags.empty()) finding("the read failed without a diagnostic");
    (void)formatDiagnostics(diags);
    return 0;
  }

  if (ex.grid) {
    const std::string written = writeLabelGridText(*ex.grid, ex);
    Example back;
    Diagnostics backDiags;
    if (!parseExampleText(written, "written.txt", back, backDiags))
      finding("a written grid does not read back: " + formatDiagnostics(backDiags) + "\n" + written);
    if (!back.grid || !(*back.grid == *ex.grid)) finding("a written grid reads back different:\n" + written);
    if (back.labelCount() != ex.labelCount()) finding("a written grid reads back other labels:\n" + written);
    for (int i = 0; i < ex.labelCount(); ++i)
      if (back.labels[i].name != ex.labels[i].name) finding("label " + std::to_string(i) + " renamed:\n" + written);
  }

  if (ex.labelCount() == 0) return 0;
  SynthesisOptions options;
  options.size = {4, 4, ex.dims == 2 ? 1 : 2};
  options.timeLimitSeconds = 0.2;
  options.maxAssignments = 4096;
  const SynthesisResult r = synthesize(ex, options);
  if (r.consistent) {
    CheckSpec spec;
    if (const auto v = checkModel(r.labels, ex, spec); !v.empty())
      finding("a model the solver calls consistent fails the checker: " + v[0].what);
  }
  return 0;
}
