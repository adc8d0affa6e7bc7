// What the parts of the program code generator share, private to backend/codegen: the
// ProgramCodegen class (the module, the builder, the function being emitted and its
// arguments) and the small helpers every part uses. Its members are defined by concept,
// one file each:
//   program_codegen.cpp  the program: a function per block, guard, weight and direct
//                        symbol, and the FgsgProgram table that lists them
//   block_codegen.cpp    a block's function: its ops calling the runtime's entry points
//   direct_symbols.cpp   which symbols get direct code (findDirectSymbols)
//   direct_codegen.cpp   a direct symbol's function: the depth and stack-floor checks,
//                        the successor's ops on a scope in the frame, child shapes
//   direct_choice.cpp    a direct symbol's choice among its rules' alternatives
// program_object.cpp turns the module into optimised LLVM IR text or an object file.
#pragma once

#include "backend/codegen/expr_codegen.h"
#include "backend/codegen/program_codegen.h"
#include "ir/ir.h"
#include "ir/program_layout.h"
#include "runtime/scope.h"

#include <llvm/IR/Constants.h>
#include <llvm/IR/Function.h>
#include <llvm/IR/IRBuilder.h>
#include <llvm/IR/LLVMContext.h>
#include <llvm/IR/Module.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

namespace fgsg::backend::codegen::detail {

// Only queries report errors at run time (the IR is type-checked and verified, so the
// code generator's internal-error paths are unreachable); anything else cannot fail.
inline bool cannotFail(const ir::Expr& e) {
  if (e.op == ir::ExprOp::Query) return false;
  for (const auto& a : e.args)
    if (!cannotFail(a)) return false;
  return true;
}

// Rules that a sequential derivation can choose: those without context.
inline bool choosable(const ir::Rule& r) { return r.left.empty() && r.right.empty(); }

// The direct symbols (runtime/abi.h, FgsgDirectFn), by symbol; `places`: the symbol's
// shapes may place instances (direct_symbols.cpp).
std::vector<bool> findDirectSymbols(const ir::Module& m, std::vector<bool>& places);

class ProgramCodegen {
 public:
  ProgramCodegen(llvm::Module& out, const ir::Module& m, const ProgramCodegenOptions& o);

  void run();

 private:
  // ------------------------------------------------------------ program_codegen.cpp
  llvm::Constant* nullPtr() { return llvm::ConstantPointerNull::get(ptr_); }
  llvm::Function* value(const ir::Expr& e, const std::string& name);
  llvm::Constant* array(const std::vector<llvm::Constant*>& items, const char* name);
  llvm::Constant* string(const std::string& s, const char* name);
  void table(const std::vector<llvm::Constant*>& blocks, const std::vector<llvm::Constant*>& guards,
             const std::vector<llvm::Constant*>& weights, const std::vector<llvm::Constant*>& direct,
             const std::vector<llvm::Constant*>& placing);

  // ------------------------------------------------------------ block_codegen.cpp
  llvm::Function* block(uint32_t id);
  void op(const ir::Op& op);
  llvm::Value* emitSlots(const ir::Op& op);  // direct code's Emit uses it too

  // Helpers of block and direct code alike.

  // A buffer of n doubles in the entry block (stack slots for arguments).
  llvm::Value* buffer(uint32_t n) {
    llvm::IRBuilderBase::InsertPointGuard guard(b_);
    b_.SetInsertPoint(entry_, entry_->begin());
    return b_.CreateAlloca(b_.getDoubleTy(), b_.getInt32(std::max(n, 1u)));
  }

  llvm::Value* call(const char* name, std::initializer_list<llvm::Value*> args) {
    return b_.CreateCall(m_.getFunction(name), args);
  }

  // Returns from the block when the engine or an expression asked it to stop.
  void checkStop() {
    llvm::Value* stop = b_.CreateLoad(b_.getInt32Ty(), ctx_, "stop");
    llvm::BasicBlock* go = llvm::BasicBlock::Create(c_, "go", fn_, exit_);
    b_.CreateCondBr(b_.CreateICmpNE(stop, b_.getInt32(0)), exit_, go);
    b_.SetInsertPoint(go);
  }

  // Expressions are emitted in place; an error they report makes the block return.
  InlineSite site() { return {params_, attrs_, ctx_, entry_, exit_}; }

  llvm::Value* num(const ir::Expr& e) { return emitNumInline(m_, b_, site(), e); }

  // Writes e (1 or 3 slots) at out[slot].
  void store(const ir::Expr& e, llvm::Value* out, uint32_t slot) {
    emitStoreInline(m_, b_, site(), e, b_.CreateConstInBoundsGEP1_64(b_.getDoubleTy(), out, slot));
  }

  llvm::Value* u32(uint32_t v) { return b_.getInt32(v); }

  // ------------------------------------------------------------ direct code

  // Fields of FgsgContext generated code uses (offsets checked in runtime/abi.h).
  enum ContextField : uint64_t { kStop = 0, kInexact = 4, kShapes = 8, kRewrites = 16,
                                 kTerminals = 24, kShapeBudget = 32, kDepthLimit = 40, kDepthLimitQuiet = 44, kRng = 48,
                                 kVisits = 56, kStackFloor = 64 };
  llvm::Value* field(uint64_t offset) { return b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), ctx_, offset); }
  llvm::Value* loadU64(uint64_t offset) { return b_.CreateLoad(b_.getInt64Ty(), field(offset)); }
  void bump(uint64_t offset) { b_.CreateStore(b_.CreateAdd(loadU64(offset), b_.getInt64(1)), field(offset)); }
  llvm::Value* zero() { return llvm::ConstantFP::get(b_.getDoubleTy(), 0.0); }
  llvm::BasicBlock* newBlock(const char* name) { return llvm::BasicBlock::Create(c_, name, fn_, exit_); }

  // direct_codegen.cpp
  void giveUpIf(llvm::Value* cond);
  llvm::Value* frameSlots(llvm::Type* type, size_t n);
  void directSymbol(uint32_t s);
  void directSuccessor(const ir::Block& ops);
  // The frame scope's doubles: P (0..2), then axes column by column (3 + 3 column + row).
  static_assert(offsetof(rt::Scope, P) == 0 && offsetof(rt::Scope, axes) == 24, "rt::Scope's layout");
  llvm::Value* scopeSlot(uint32_t index) { return b_.CreateConstInBoundsGEP1_64(b_.getDoubleTy(), scope_, index); }
  llvm::Value* scopeLoad(uint32_t index) { return b_.CreateLoad(b_.getDoubleTy(), scopeSlot(index)); }
  void translateLocal(llvm::Value* x, llvm::Value* y, llvm::Value* z);
  void rotateLocal(uint32_t axis, llvm::Value* degrees);
  llvm::Value* childKey(llvm::Value* parent, uint64_t index);

  // direct_choice.cpp
  bool constantChoice(const ir::Symbol& sym) const;
  void chooseStatic(const ir::Symbol& sym, llvm::Value* chosen, llvm::BasicBlock* apply);
  void chooseDynamic(const ir::Symbol& sym, llvm::Value* chosen, llvm::BasicBlock* apply,
                     size_t alternatives);

  llvm::Module& m_;
  llvm::LLVMContext& c_;
  llvm::IRBuilder<> b_;
  const ir::Module& ir_;
  const ProgramCodegenOptions& opt_;
  ir::ProgramLayout layout_;
  llvm::PointerType* ptr_ = nullptr;
  llvm::Function* fn_ = nullptr;
  llvm::Value* ctx_ = nullptr;
  llvm::Value* params_ = nullptr;
  llvm::Value* attrs_ = nullptr;
  llvm::BasicBlock* entry_ = nullptr;
  llvm::BasicBlock* exit_ = nullptr;
  std::vector<llvm::Function*> directFns_;  // by symbol: null unless direct
  llvm::Value* key_ = nullptr;    // direct code: the shape's key, depth, stream and scope
  llvm::Value* depth_ = nullptr;
  llvm::Value* rng_ = nullptr;
  llvm::Value* scope_ = nullptr;
  llvm::BasicBlock* giveUp_ = nullptr;  // direct code: where an inexact derivation leaves
  uint32_t symbol_ = 0;                  // direct code: the symbol derived
  llvm::Value* cosSin_ = nullptr;        // direct code: the memo's answer for a turn
  llvm::Value* preorder_ = nullptr;      // ... and the shape's preorder number
};

}  // namespace fgsg::backend::codegen::detail
