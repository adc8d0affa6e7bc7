// A grammar's native code and what makes it. The compiler itself (backend/jit, LLVM)
// lives in lib/libfgsg_llvm.so, loaded only by commands that compile (llvm_plugin.h);
// the rest of fgsg sees it through this interface, so that `fgsg --version`, `check`,
// `synth` or a run whose code is cached never load libLLVM (issue #18).
#pragma once

#include "ir/ir.h"

#include <chrono>
#include <memory>
#include <string>

struct FgsgProgram;

namespace fgsg::backend::native {

class ObjectCache;

// A whole grammar's native code for deriveCompiled (backend/interp/interpreter.h). It
// keeps its code loaded (a JIT unit or a shared library) for as long as it lives; one
// from a JIT must not outlive that JIT.
class CompiledProgram {
 public:
  CompiledProgram() = default;
  CompiledProgram(const FgsgProgram* program, std::shared_ptr<void> unit, bool fromCache, bool optimized)
      : program_(program), unit_(std::move(unit)), fromCache_(fromCache), optimized_(optimized) {}

  const FgsgProgram& program() const { return *program_; }
  bool fromCache() const { return fromCache_; }
  bool optimized() const { return optimized_; }  // false: the first tier's machine code
  double seconds() const { return seconds_; }    // compiling (or loading) and linking
  void setSeconds(double s) { seconds_ = s; }

 private:
  const FgsgProgram* program_ = nullptr;
  std::shared_ptr<void> unit_;  // unloads the code
  bool fromCache_ = false;
  bool optimized_ = true;
  double seconds_ = 0.0;
};

// How a grammar missing from the cache is compiled. Tiered: its code is linked as soon
// as the first tier is ready (quick, unoptimised) while the optimised object is compiled
// on another thread and stored in the cache for the next run (the compiler's destructor
// waits for it). Optimized: the optimised object at once. Baseline: the first tier
// only, never cached (to measure it).
enum class Tiering { Tiered, Optimized, Baseline };

class ProgramCompiler {
 public:
  virtual ~ProgramCompiler() = default;

  // Compiles a grammar into a unit of its own, or loads its object from `cache` when it
  // holds one for this grammar and machine. `source` is the grammar's text (part of the
  // cache key). Without a cache folder the optimised code is compiled at once. Throws
  // std::runtime_error.
  virtual CompiledProgram compileProgram(const ir::Module& m, const std::string& source, const ObjectCache& cache,
                                         Tiering tiering = Tiering::Tiered) = 0;

  // Waits until the optimising compiles of Tiering::Tiered are in the cache.
  virtual void waitForCache() = 0;
  // The destructor waits for those compiles until `limit` at the latest (fgsg run's
  // --max-seconds): one still running then is abandoned, its object never stored (it
  // only fills the cache), and its thread left to the process's end; a process with any
  // must end with std::_Exit after flushing its output (see abandonedCompiles in
  // llvm_plugin.h).
  virtual void stopWaitingAt(std::chrono::steady_clock::time_point limit) = 0;
};

}  // namespace fgsg::backend::native
