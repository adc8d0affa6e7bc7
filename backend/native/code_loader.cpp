#include "backend/native/code_loader.h"

#include "backend/native/llvm_plugin.h"
#include "backend/native/runtime_symbols.h"

namespace fgsg::backend::native {

CodeLoader::CodeLoader(ObjectCache cache) : cache_(std::move(cache)) {}

CodeLoader::~CodeLoader() = default;

CompiledProgram CodeLoader::load(const ir::Module& m, const std::string& source) {
  const auto start = std::chrono::steady_clock::now();
  if (!cache_.folder().empty()) {
    const std::string key = ObjectCache::key(m, source);
    std::optional<CompiledProgram> cached = cache_.loadLibrary(key);
    // A library missing or damaged beside a good object is linked again from it: one run
    // of the C compiler, still no LLVM.
    if (!cached)
      if (std::optional<std::string> object = cache_.load(key); object && cache_.storeLibrary(key, *object))
        cached = cache_.loadLibrary(key);
    if (cached) {
      cached->setSeconds(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      return std::move(*cached);
    }
  }
  if (!compiler_) {
    compiler_ = llvmPlugin().makeCompiler(runtimeSymbols());
    compiler_->stopWaitingAt(waitLimit_);
  }
  CompiledProgram code = compiler_->compileProgram(m, source, cache_);
  code.setSeconds(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return code;
}

void CodeLoader::stopWaitingAt(std::chrono::steady_clock::time_point limit) {
  waitLimit_ = limit;
  if (compiler_) compiler_->stopWaitingAt(limit);
}

int abandonedCompiles() { return llvmPluginLoaded() ? llvmPlugin().abandonedCompiles() : 0; }

}  // namespace fgsg::backend::native
