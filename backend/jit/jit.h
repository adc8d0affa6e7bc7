// The JIT engine: IR compiled through LLVM ORC (LLJIT, O2 new-pass-manager pipeline).
// The runtime's entry points (runtime/abi.def) are registered explicitly as absolute
// symbols; generated code resolves nothing from the process. Each compile() is one
// unit with its own ResourceTracker: its code lives as long as the returned object.
#pragma once

#include <chrono>

#include "backend/codegen/expr_codegen.h"
#include "ir/ir.h"

struct FgsgProgram;

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace fgsg::backend::jit {

using codegen::NumFn;
using codegen::VecFn;

// The functions of one compiled unit, in the order of the expressions given. Must
// not outlive the Jit that made it.
class CompiledExprs {
 public:
  size_t size() const { return fns_.size(); }
  bool isVec(size_t i) const { return vec_[i]; }
  NumFn num(size_t i) const { return isVec(i) ? nullptr : reinterpret_cast<NumFn>(fns_[i]); }
  VecFn vec(size_t i) const { return isVec(i) ? reinterpret_cast<VecFn>(fns_[i]) : nullptr; }

 private:
  friend class Jit;
  std::vector<void*> fns_;
  std::vector<bool> vec_;
  std::shared_ptr<void> unit_;  // releases the unit's ResourceTracker
};

// A whole grammar compiled for deriveCompiled (backend/interp/interpreter.h). Must not
// outlive the Jit that made it.
class CompiledProgram {
 public:
  const FgsgProgram& program() const { return *program_; }
  bool fromCache() const { return fromCache_; }
  bool optimized() const { return optimized_; }  // false: the first tier's machine code
  double seconds() const { return seconds_; }  // compiling (or loading) and linking

 private:
  friend class Jit;
  const FgsgProgram* program_ = nullptr;
  bool fromCache_ = false;
  bool optimized_ = true;
  double seconds_ = 0.0;
  std::shared_ptr<void> unit_;  // releases the unit's JITDylib and ResourceTracker
};

class ObjectCache;

// Background compiles abandoned by a Jit destroyed before they ended (stopWaitingAt). A
// process with any must end with std::_Exit after flushing its output: their threads
// still use LLVM, whose static objects an ordinary exit would destroy under them.
int abandonedCompiles();

class Jit {
 public:
  Jit();  // throws std::runtime_error when no native target can be set up
  ~Jit();
  Jit(const Jit&) = delete;
  Jit& operator=(const Jit&) = delete;

  // Compiles every expression into one unit (one function each, see expr_codegen.h).
  CompiledExprs compile(const std::vector<const ir::Expr*>& exprs);

  // How a grammar missing from the cache is compiled. Tiered: its code is linked as
  // soon as the first tier is ready (CodeQuality::Baseline) while the optimised object
  // is compiled on another thread and stored in the cache for the next run (the Jit's
  // destructor waits for it). Optimized: the optimised object at once. Baseline: the
  // first tier only, never cached (to measure it).
  enum class Tiering { Tiered, Optimized, Baseline };

  // Compiles a grammar (see backend/codegen/program_codegen.h) into a unit of its own,
  // or loads its object from `cache` when it holds one for this grammar and machine.
  // `source` is the grammar's text (part of the cache key). Without a cache folder the
  // optimised code is compiled at once. Throws std::runtime_error.
  CompiledProgram compileProgram(const ir::Module& m, const std::string& source, const ObjectCache& cache,
                                 Tiering tiering = Tiering::Tiered);

  // Waits until the optimising compiles of Tiering::Tiered are in the cache.
  void waitForCache();
  // The destructor waits for those compiles until `limit` at the latest (fgsg run's
  // --max-seconds): one still running then is abandoned, its object never stored (it only
  // fills the cache), and its thread left to the process's end; see abandonedCompiles().
  void stopWaitingAt(std::chrono::steady_clock::time_point limit);

  // The optimised LLVM IR of the last unit compiled, for debugging and tests.
  const std::string& lastIR() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fgsg::backend::jit
