// The JIT engine: IR compiled through LLVM ORC (LLJIT, O2 new-pass-manager pipeline).
// The runtime's entry points (native/runtime_symbols.h) are registered explicitly as
// absolute symbols; generated code resolves nothing from the process. Each compile() is one
// unit with its own ResourceTracker: its code lives as long as the returned object.
#pragma once

#include "backend/codegen/expr_codegen.h"
#include "backend/native/program_compiler.h"
#include "backend/native/runtime_symbols.h"
#include "ir/ir.h"

#include <chrono>
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

using native::CompiledProgram;
using native::ObjectCache;
using native::Tiering;

// Background compiles abandoned by a Jit destroyed before they ended (stopWaitingAt). A
// process with any must end with std::_Exit after flushing its output: their threads
// still use LLVM, whose static objects an ordinary exit would destroy under them.
int abandonedCompiles();

class Jit : public native::ProgramCompiler {
 public:
  // Throws std::runtime_error when no native target can be set up.
  explicit Jit(const std::vector<native::RuntimeSymbol>& runtime = native::runtimeSymbols());
  ~Jit() override;
  Jit(const Jit&) = delete;
  Jit& operator=(const Jit&) = delete;

  // Compiles every expression into one unit (one function each, see expr_codegen.h).
  CompiledExprs compile(const std::vector<const ir::Expr*>& exprs);

  // native::ProgramCompiler
  CompiledProgram compileProgram(const ir::Module& m, const std::string& source, const ObjectCache& cache,
                                 Tiering tiering = Tiering::Tiered) override;
  void waitForCache() override;
  void stopWaitingAt(std::chrono::steady_clock::time_point limit) override;

  // The optimised LLVM IR of the last unit compiled, for debugging and tests.
  const std::string& lastIR() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fgsg::backend::jit
