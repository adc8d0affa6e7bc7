// IR expressions to LLVM IR: one function per expression, with the interpreter's
// semantics (backend/interp/eval.cpp) operation for operation, so that the compiled
// code gives the same bits and draws the same random numbers in the same order.
//
//   double fn(const double* params, const double* attrs, FgsgContext* ctx)        (Num/Bool/Str)
//   void   fn(const double* params, const double* attrs, FgsgContext* ctx, double* out)  (Vec3)
//
// attrs holds three slots per attribute, as Evaluator's. After an error the function
// has reported it through ctx (fgsg_rt_error) and returns at once (NaN for numbers,
// nothing written for vectors); the engine checks ctx->errorCode.
#pragma once

#include "ir/ir.h"

#include <string>

namespace llvm {
class BasicBlock;
class Function;
class IRBuilderBase;
class Module;
class Value;
}  // namespace llvm

struct FgsgContext;

namespace fgsg::backend::codegen {

using NumFn = double (*)(const double* params, const double* attrs, FgsgContext* ctx);
using VecFn = void (*)(const double* params, const double* attrs, FgsgContext* ctx, double* out);

// Declares every runtime/abi.def function in the module (idempotent).
void declareRuntime(llvm::Module& m);

// Emits the function `name` computing e into m (declaring the runtime as needed).
llvm::Function* emitExpr(llvm::Module& m, const ir::Expr& e, const std::string& name);

// Where an expression is emitted inline, inside a function of the caller's: its
// parameter block, attributes and context, the entry block for stack slots, and the
// block an error branches to once it has been reported through the context.
struct InlineSite {
  llvm::Value* params;
  llvm::Value* attrs;
  llvm::Value* ctx;
  llvm::BasicBlock* allocas;
  llvm::BasicBlock* fail;
};

// e (a number, boolean or string id) computed at b's insert point; b is left after it.
llvm::Value* emitNumInline(llvm::Module& m, llvm::IRBuilderBase& b, const InlineSite& site, const ir::Expr& e);
// e (of any type: 1 or 3 doubles) stored at out.
void emitStoreInline(llvm::Module& m, llvm::IRBuilderBase& b, const InlineSite& site, const ir::Expr& e,
                     llvm::Value* out);

}  // namespace fgsg::backend::codegen
