// A grammar's native code for the commands (`fgsg run`, the REPL): the cache's shared
// library when it holds one (or can link one from the cached object), loaded without
// LLVM; else compiled through the LLVM plugin (llvm_plugin.h), loaded then. It owns that compiler, whose destructor waits for the
// background compile that fills the cache: keep it until the command's output is written.
#pragma once

#include "backend/native/object_cache.h"
#include "backend/native/program_compiler.h"

#include <chrono>
#include <memory>
#include <string>

namespace fgsg::backend::native {

class CodeLoader {
 public:
  explicit CodeLoader(ObjectCache cache = ObjectCache());
  ~CodeLoader();
  CodeLoader(const CodeLoader&) = delete;
  CodeLoader& operator=(const CodeLoader&) = delete;

  // Throws std::runtime_error (rt::PluginError when the plugin cannot be loaded) when
  // the code can be neither loaded nor compiled.
  CompiledProgram load(const ir::Module& m, const std::string& source);

  // See ProgramCompiler::stopWaitingAt.
  void stopWaitingAt(std::chrono::steady_clock::time_point limit);

 private:
  ObjectCache cache_;
  std::unique_ptr<ProgramCompiler> compiler_;
  std::chrono::steady_clock::time_point waitLimit_ = std::chrono::steady_clock::time_point::max();
};

// Background compiles still running LLVM (ProgramCompiler::stopWaitingAt): a process
// with any must end with std::_Exit after flushing its output. 0 when the plugin was
// never loaded.
int abandonedCompiles();

}  // namespace fgsg::backend::native
