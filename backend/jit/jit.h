// The JIT engine: IR compiled through LLVM ORC (LLJIT, O2 new-pass-manager pipeline).
// The runtime's entry points (runtime/abi.def) are registered explicitly as absolute
// symbols; generated code resolves nothing from the process. Each compile() is one
// unit with its own ResourceTracker: its code lives as long as the returned object.
#pragma once

#include "backend/jit/expr_codegen.h"
#include "ir/ir.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace fgsg::backend::jit {

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

class Jit {
 public:
  Jit();  // throws std::runtime_error when no native target can be set up
  ~Jit();
  Jit(const Jit&) = delete;
  Jit& operator=(const Jit&) = delete;

  // Compiles every expression into one unit (one function each, see expr_codegen.h).
  CompiledExprs compile(const std::vector<const ir::Expr*>& exprs);

  // The optimised LLVM IR of the last unit compiled, for debugging and tests.
  const std::string& lastIR() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fgsg::backend::jit
