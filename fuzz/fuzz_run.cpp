// libFuzzer target: `fgsg run` on arbitrary grammar text with tight limits (2 000 shapes,
// depth 48, 1 s), and the engines-agree oracle: on a sample of the inputs that compile,
// the JIT (first-tier code, no cache) must derive exactly what the interpreter derives:
// the same messages and the same instances, byte for byte. The JIT spends tens of
// milliseconds per grammar, so it runs on one input in FGSG_FUZZ_JIT_EVERY (default 4,
// chosen by a hash of the input so a finding reproduces). Assets and data files are
// looked up in examples/ so grammars can reach the real tile sets, fields and images.
#include "backend/engine.h"
#include "backend/interp/interpreter.h"
#include "backend/jit/jit.h"
#include "backend/native/object_cache.h"
#include "frontend/diagnostics.h"
#include "ir/pipeline.h"
#include "runtime/assemble.h"
#include "runtime/io/write_instances.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

namespace {

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_run finding: %s\n", what.c_str());
  std::abort();
}

std::string describe(const fgsg::rt::DeriveResult& r) {
  std::string out = r.ok ? "ok" : "failed";
  for (const auto& m : r.messages)
    out += "\n  " + m.code + " at " + std::to_string(m.line) + ":" + std::to_string(m.col) + ": " + m.message;
  return out;
}

bool stoppedByClock(const fgsg::rt::DeriveResult& r) {
  for (const auto& m : r.messages)
    if (m.message.find("max-seconds") != std::string::npos) return true;
  return false;
}

uint64_t hashOf(const uint8_t* data, size_t size) {
  uint64_t h = 1469598103934665603ull;  // FNV-1a
  for (size_t i = 0; i < size; ++i) h = (h ^ data[i]) * 1099511628211ull;
  return h;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace fgsg;
  if (size > 8192) return -1;
  const std::string text(reinterpret_cast<const char*>(data), size);

  const frontend::SourceFile source = frontend::SourceFile::make("fuzz.fgsg", text);
  frontend::Diagnostics diags(&source);
  ir::Module module;
  if (!ir::compileSource(source, module, diags)) return 0;

  rt::DeriveOptions options;
  options.maxShapes = 2000;
  options.maxDepth = 48;
  options.maxSeconds = 1.0;
  options.assetDirs = {FGSG_FUZZ_DATA_DIR};
  rt::AssetLibrary assets;
  assets.addSearchDir(FGSG_FUZZ_DATA_DIR);
  const rt::DeriveResult interp = backend::interpret(module, options, assets);
  const std::string interpInstances = rt::io::encodeInstancesJson(interp.instances);
  if (interp.ok) {
    std::vector<int> meshOf;
    std::string error;
    if (rt::resolveAssets(interp.instances, assets, meshOf, error))
      (void)rt::assembleInstances(interp.instances, assets, meshOf);
  }

  static const uint64_t every = [] {
    const char* env = std::getenv("FGSG_FUZZ_JIT_EVERY");
    return env ? std::strtoull(env, nullptr, 10) : 4ull;
  }();
  if (every == 0 || hashOf(data, size) % every != 0 || stoppedByClock(interp)) return 0;
  static backend::jit::Jit jit;
  const backend::native::ObjectCache noCache{std::string()};
  rt::DeriveResult jitted;
  try {
    const auto code = jit.compileProgram(module, text, noCache, backend::native::Tiering::Baseline);
    rt::AssetLibrary jitAssets;
    jitAssets.addSearchDir(FGSG_FUZZ_DATA_DIR);
    jitted = backend::deriveCompiled(module, code.program(), options, jitAssets);
  } catch (const std::exception& e) {
    finding(std::string("the JIT cannot compile a grammar the front end accepts: ") + e.what());
  }
  if (stoppedByClock(jitted)) return 0;
  if (describe(interp) != describe(jitted))
    finding("the engines report differently\ninterpreter: " + describe(interp) + "\njit: " + describe(jitted));
  if (interpInstances != rt::io::encodeInstancesJson(jitted.instances))
    finding("the engines place different instances (interpreter " +
            std::to_string(interp.instances.instances.size()) + ", jit " +
            std::to_string(jitted.instances.instances.size()) + ")");
  return 0;
}
