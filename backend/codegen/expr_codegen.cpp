#include "backend/codegen/expr_codegen.h"

#include "runtime/abi.h"

#include <llvm/IR/BasicBlock.h>
#include <llvm/IR/Constants.h>
#include <llvm/IR/Function.h>
#include <llvm/IR/IRBuilder.h>
#include <llvm/IR/Intrinsics.h>
#include <llvm/IR/Module.h>

#include <array>
#include <cmath>
#include <limits>
#include <type_traits>

namespace fgsg::backend::codegen {
namespace {

using ir::Builtin;
using ir::Expr;
using ir::ExprOp;
using Vec = std::array<llvm::Value*, 3>;

// The LLVM type of a C type of the runtime ABI: enough for runtime/abi.def.
template <class T>
llvm::Type* llvmType(llvm::LLVMContext& c) {
  if constexpr (std::is_same_v<T, void>) return llvm::Type::getVoidTy(c);
  else if constexpr (std::is_same_v<T, double>) return llvm::Type::getDoubleTy(c);
  else if constexpr (std::is_pointer_v<T>) return llvm::PointerType::getUnqual(c);
  else if constexpr (std::is_integral_v<T>) return llvm::Type::getIntNTy(c, 8 * sizeof(T));
  else static_assert(sizeof(T) == 0, "a runtime ABI type without an LLVM mapping");
}

template <class R, class... A>
llvm::FunctionType* llvmFnType(llvm::LLVMContext& c, R (*)(A...) noexcept) {
  return llvm::FunctionType::get(llvmType<R>(c), {llvmType<A>(c)...}, false);
}

llvm::Function* declare(llvm::Module& m, const char* name, llvm::FunctionType* type, bool pure) {
  if (llvm::Function* f = m.getFunction(name)) return f;
  auto* f = llvm::Function::Create(type, llvm::Function::ExternalLinkage, name, m);
  f->addFnAttr(llvm::Attribute::NoUnwind);
  if (pure) {
    f->setDoesNotAccessMemory();
    f->addFnAttr(llvm::Attribute::WillReturn);
  }
  return f;
}

class ExprCodegen {
 public:
  ExprCodegen(llvm::Module& m, const Expr& e, const std::string& name)
      : m_(m), c_(m.getContext()), b_(c_), root_(&e) {
    declareRuntime(m);
    isVec_ = e.type == ir::Type::Vec3;
    llvm::Type* ptr = llvm::PointerType::getUnqual(c_);
    llvm::Type* f64 = llvm::Type::getDoubleTy(c_);
    auto* type = isVec_
        ? llvm::FunctionType::get(llvm::Type::getVoidTy(c_), {ptr, ptr, ptr, ptr}, false)
        : llvm::FunctionType::get(f64, {ptr, ptr, ptr}, false);
    fn_ = llvm::Function::Create(type, llvm::Function::ExternalLinkage, name, m);
    fn_->addFnAttr(llvm::Attribute::NoUnwind);
    params_ = fn_->getArg(0);
    attrs_ = fn_->getArg(1);
    ctx_ = fn_->getArg(2);
    params_->setName("params");
    attrs_->setName("attrs");
    ctx_->setName("ctx");
    for (int i = 0; i < 3; ++i) fn_->addParamAttr(i, llvm::Attribute::NoAlias);
    entry_ = llvm::BasicBlock::Create(c_, "entry", fn_);
    b_.SetInsertPoint(entry_);
  }

  // Inline: the code goes where `outer` stands, in its function; an error branches to
  // `fail` once reported; allocas go to `allocas` (the function's entry block).
  ExprCodegen(llvm::Module& m, llvm::IRBuilderBase& outer, const InlineSite& site)
      : m_(m), c_(m.getContext()), b_(c_), root_(nullptr), outer_(&outer) {
    declareRuntime(m);
    fn_ = outer.GetInsertBlock()->getParent();
    entry_ = site.allocas;
    fail_ = site.fail;
    params_ = site.params;
    attrs_ = site.attrs;
    ctx_ = site.ctx;
    b_.SetInsertPoint(outer.GetInsertBlock(), outer.GetInsertPoint());
  }

  llvm::Function* run() {
    if (isVec_) {
      llvm::Value* out = fn_->getArg(3);
      out->setName("out");
      Vec v = vec(*root_);
      for (int k = 0; k < 3; ++k) b_.CreateStore(v[k], gep(out, k));
      b_.CreateRetVoid();
    } else {
      b_.CreateRet(num(*root_));
    }
    return fn_;
  }

  llvm::Value* inlineNum(const Expr& e) {
    llvm::Value* v = num(e);
    outer_->SetInsertPoint(b_.GetInsertBlock(), b_.GetInsertPoint());
    return v;
  }

  void inlineStore(const Expr& e, llvm::Value* out) {
    if (e.type == ir::Type::Vec3) {
      Vec v = vec(e);
      for (int k = 0; k < 3; ++k) b_.CreateStore(v[k], gep(out, k));
    } else {
      b_.CreateStore(num(e), out);
    }
    outer_->SetInsertPoint(b_.GetInsertBlock(), b_.GetInsertPoint());
  }

 private:
  llvm::Value* f64(double v) { return llvm::ConstantFP::get(llvm::Type::getDoubleTy(c_), v); }
  llvm::Value* i32(int64_t v) { return b_.getInt32(static_cast<uint32_t>(v)); }
  llvm::Value* gep(llvm::Value* base, uint64_t i) {
    return b_.CreateConstInBoundsGEP1_64(b_.getDoubleTy(), base, i);
  }
  llvm::Value* load(llvm::Value* base, uint64_t i) { return b_.CreateLoad(b_.getDoubleTy(), gep(base, i)); }
  llvm::Value* fromBool(llvm::Value* bit) { return b_.CreateSelect(bit, f64(1.0), f64(0.0)); }
  llvm::Function* rt(const char* name) { return m_.getFunction(name); }
  llvm::Value* call(const char* name, std::initializer_list<llvm::Value*> args) {
    return b_.CreateCall(rt(name), args);
  }
  llvm::Value* intrinsic(llvm::Intrinsic::ID id, llvm::Value* x) {
    return b_.CreateUnaryIntrinsic(id, x);
  }

  // The block every error leaves through: the function returns at once.
  llvm::BasicBlock* failBlock() {
    if (!fail_) {
      llvm::IRBuilderBase::InsertPointGuard guard(b_);
      fail_ = llvm::BasicBlock::Create(c_, "fail", fn_);
      b_.SetInsertPoint(fail_);
      if (isVec_) b_.CreateRetVoid();
      else b_.CreateRet(f64(std::numeric_limits<double>::quiet_NaN()));
    }
    return fail_;
  }

  // An error known at compile time: reported when control gets here, as the
  // interpreter throws only when it evaluates the expression.
  void raise(FgsgErrorCode code, const ir::Loc& at) {
    call("fgsg_rt_error", {ctx_, i32(code), i32(at.line), i32(at.col)});
    b_.CreateBr(failBlock());
    b_.SetInsertPoint(llvm::BasicBlock::Create(c_, "dead", fn_));  // no predecessors
  }
  llvm::Value* raiseNum(FgsgErrorCode code, const ir::Loc& at) {
    raise(code, at);
    return llvm::PoisonValue::get(b_.getDoubleTy());
  }
  Vec raiseVec(const ir::Loc& at) {
    raise(FGSG_E_VEC_UNAVAILABLE, at);
    llvm::Value* p = llvm::PoisonValue::get(b_.getDoubleTy());
    return {p, p, p};
  }

  llvm::Value* truth(const Expr& e) { return b_.CreateFCmpUNE(num(e), f64(0.0)); }

  // cond ? then() : otherwise(), with real branches so that only one side runs.
  template <class T, class Then, class Else>
  T branch(llvm::Value* cond, Then then, Else otherwise) {
    auto* thenBB = llvm::BasicBlock::Create(c_, "then", fn_);
    auto* elseBB = llvm::BasicBlock::Create(c_, "else", fn_);
    auto* joinBB = llvm::BasicBlock::Create(c_, "join", fn_);
    b_.CreateCondBr(cond, thenBB, elseBB);
    b_.SetInsertPoint(thenBB);
    T a = then();
    llvm::BasicBlock* thenEnd = b_.GetInsertBlock();
    b_.CreateBr(joinBB);
    b_.SetInsertPoint(elseBB);
    T c = otherwise();
    llvm::BasicBlock* elseEnd = b_.GetInsertBlock();
    b_.CreateBr(joinBB);
    b_.SetInsertPoint(joinBB);
    auto phi = [&](llvm::Value* x, llvm::Value* y) {
      llvm::PHINode* p = b_.CreatePHI(x->getType(), 2);
      p->addIncoming(x, thenEnd);
      p->addIncoming(y, elseEnd);
      return p;
    };
    if constexpr (std::is_same_v<T, Vec>) return Vec{phi(a[0], c[0]), phi(a[1], c[1]), phi(a[2], c[2])};
    else return phi(a, c);
  }

  llvm::Value* num(const Expr& e) {
    auto a = [&](int k) { return num(e.args[k]); };
    switch (e.op) {
      case ExprOp::Const: return f64(e.num);
      case ExprOp::Param: return load(params_, e.index);
      case ExprOp::Attr: return load(attrs_, 3ull * e.index);
      case ExprOp::Neg: return b_.CreateFNeg(a(0));
      case ExprOp::Not: return fromBool(b_.CreateFCmpOEQ(a(0), f64(0.0)));
      // Operands are evaluated left to right everywhere (docs/language.md): it fixes
      // which Rand gets which draw.
      case ExprOp::Add: { llvm::Value* x = a(0); return b_.CreateFAdd(x, a(1)); }
      case ExprOp::Sub: { llvm::Value* x = a(0); return b_.CreateFSub(x, a(1)); }
      case ExprOp::Mul: { llvm::Value* x = a(0); return b_.CreateFMul(x, a(1)); }
      case ExprOp::Div: { llvm::Value* x = a(0); return b_.CreateFDiv(x, a(1)); }
      case ExprOp::Mod: { llvm::Value* x = a(0); return call("fgsg_rt_fmod", {x, a(1)}); }
      case ExprOp::Pow: { llvm::Value* x = a(0); return call("fgsg_rt_pow", {x, a(1)}); }
      case ExprOp::Eq:
      case ExprOp::Ne: {
        llvm::Value* eq;
        if (e.args[0].type == ir::Type::Vec3) {
          Vec x = vec(e.args[0]);
          Vec y = vec(e.args[1]);
          eq = b_.CreateAnd(b_.CreateAnd(b_.CreateFCmpOEQ(x[0], y[0]), b_.CreateFCmpOEQ(x[1], y[1])),
                            b_.CreateFCmpOEQ(x[2], y[2]));
        } else {
          llvm::Value* x = a(0);
          eq = b_.CreateFCmpOEQ(x, a(1));
        }
        return fromBool(e.op == ExprOp::Eq ? eq : b_.CreateNot(eq));
      }
      case ExprOp::Lt: { llvm::Value* x = a(0); return fromBool(b_.CreateFCmpOLT(x, a(1))); }
      case ExprOp::Le: { llvm::Value* x = a(0); return fromBool(b_.CreateFCmpOLE(x, a(1))); }
      case ExprOp::Gt: { llvm::Value* x = a(0); return fromBool(b_.CreateFCmpOGT(x, a(1))); }
      case ExprOp::Ge: { llvm::Value* x = a(0); return fromBool(b_.CreateFCmpOGE(x, a(1))); }
      case ExprOp::And:
        return branch<llvm::Value*>(
            truth(e.args[0]), [&] { return fromBool(truth(e.args[1])); }, [&] { return f64(0.0); });
      case ExprOp::Or:
        return branch<llvm::Value*>(
            truth(e.args[0]), [&] { return f64(1.0); }, [&] { return fromBool(truth(e.args[1])); });
      case ExprOp::Select:
        return branch<llvm::Value*>(
            truth(e.args[0]), [&] { return a(1); }, [&] { return a(2); });
      case ExprOp::Call: return builtin(e);
      case ExprOp::Rand: {
        // Bounds first, then the draw.
        llvm::Value* lo = a(0);
        llvm::Value* hi = a(1);
        return call("fgsg_rt_rand", {ctx_, lo, hi});
      }
      case ExprOp::Query: return query(e);
      case ExprOp::VecElem: return vec(e.args[0])[e.index];
      case ExprOp::Join: {
        llvm::Value* x = a(0);
        llvm::Value* y = a(1);
        return call("fgsg_rt_join", {ctx_, x, i32(static_cast<uint32_t>(e.args[0].type)), y,
                                     i32(static_cast<uint32_t>(e.args[1].type))});
      }
      case ExprOp::MakeVec: break;
    }
    return raiseNum(FGSG_E_INTERNAL, e.loc);
  }

  llvm::Value* builtin(const Expr& e) {
    auto a = [&](int k) { return num(e.args[k]); };
    auto less = [&](llvm::Value* x, llvm::Value* y) { return b_.CreateFCmpOLT(x, y); };
    // std::min(x, y) = y < x ? y : x; std::max(x, y) = x < y ? y : x.
    auto min = [&](llvm::Value* x, llvm::Value* y) { return b_.CreateSelect(less(y, x), y, x); };
    auto max = [&](llvm::Value* x, llvm::Value* y) { return b_.CreateSelect(less(x, y), y, x); };
    switch (static_cast<Builtin>(e.index)) {
      case Builtin::Sin: return call("fgsg_rt_sin_deg", {a(0)});
      case Builtin::Cos: return call("fgsg_rt_cos_deg", {a(0)});
      case Builtin::Tan: return call("fgsg_rt_tan_deg", {a(0)});
      case Builtin::Asin: return call("fgsg_rt_asin_deg", {a(0)});
      case Builtin::Acos: return call("fgsg_rt_acos_deg", {a(0)});
      case Builtin::Atan: return call("fgsg_rt_atan_deg", {a(0)});
      case Builtin::Atan2: { llvm::Value* y = a(0); return call("fgsg_rt_atan2_deg", {y, a(1)}); }
      case Builtin::Sqrt: return intrinsic(llvm::Intrinsic::sqrt, a(0));
      case Builtin::Abs: return intrinsic(llvm::Intrinsic::fabs, a(0));
      case Builtin::Min: { llvm::Value* x = a(0); return min(x, a(1)); }
      case Builtin::Max: { llvm::Value* x = a(0); return max(x, a(1)); }
      case Builtin::Floor: return intrinsic(llvm::Intrinsic::floor, a(0));
      case Builtin::Ceil: return intrinsic(llvm::Intrinsic::ceil, a(0));
      case Builtin::Round: return call("fgsg_rt_round", {a(0)});
      case Builtin::Clamp: {
        llvm::Value* x = a(0);
        llvm::Value* lo = a(1);
        llvm::Value* hi = a(2);
        return min(max(x, lo), hi);
      }
      case Builtin::Lerp: {
        llvm::Value* x = a(0);
        llvm::Value* y = a(1);
        llvm::Value* t = a(2);
        return b_.CreateFAdd(x, b_.CreateFMul(b_.CreateFSub(y, x), t));
      }
      case Builtin::Pow: { llvm::Value* x = a(0); return call("fgsg_rt_pow", {x, a(1)}); }
      case Builtin::Exp: return call("fgsg_rt_exp", {a(0)});
      case Builtin::Log: return call("fgsg_rt_log", {a(0)});
      case Builtin::Sign: {
        // (x > 0) - (x < 0) as an int converted to double: +1, -1 or +0 (NaN too).
        llvm::Value* x = a(0);
        return b_.CreateSelect(b_.CreateFCmpOGT(x, f64(0.0)), f64(1.0),
                               b_.CreateSelect(less(x, f64(0.0)), f64(-1.0), f64(0.0)));
      }
      case Builtin::Length: {
        Vec v = vec(e.args[0]);
        return call("fgsg_rt_vec_length", {v[0], v[1], v[2]});
      }
      case Builtin::Dot: {
        Vec x = vec(e.args[0]);
        Vec y = vec(e.args[1]);
        return call("fgsg_rt_vec_dot", {x[0], x[1], x[2], y[0], y[1], y[2]});
      }
      case Builtin::Normalize: break;
    }
    return raiseNum(FGSG_E_INTERNAL, e.loc);
  }

  llvm::Value* query(const Expr& e) { return askHost(e, -1); }

  // One call to the query host; `lane` >= 0 asks for that component of a vector field
  // member (passed as the one argument).
  llvm::Value* askHost(const Expr& e, int lane) {
    const auto q = static_cast<ir::Query>(e.index);
    if (!queryOut_) {
      llvm::IRBuilderBase::InsertPointGuard guard(b_);
      b_.SetInsertPoint(entry_, entry_->getFirstInsertionPt());
      queryOut_ = b_.CreateAlloca(b_.getDoubleTy(), nullptr, "query.out");
      queryArgs_ = b_.CreateAlloca(b_.getDoubleTy(), nullptr, "query.args");
    }
    // Only Shape.visible, Feature.label and the context queries' label (a string id) and
    // Geometry.isPlanar read their argument.
    uint32_t nargs = 0;
    if (q == ir::Query::ShapeVisible || q == ir::Query::GeometryIsPlanar || ir::isContextQuery(q) ||
        (q == ir::Query::Feature && !e.args.empty())) {
      b_.CreateStore(num(e.args[0]), queryArgs_);
      nargs = 1;
    } else if (lane >= 0) {
      b_.CreateStore(f64(lane), queryArgs_);
      nargs = 1;
    }
    llvm::Value* status = call("fgsg_rt_query",
                               {ctx_, i32(e.index), i32(e.env), i32(e.extra), queryArgs_,
                                i32(nargs), i32(e.loc.line), i32(e.loc.col), queryOut_});
    auto* ok = llvm::BasicBlock::Create(c_, "query.ok", fn_);
    b_.CreateCondBr(b_.CreateICmpEQ(status, i32(FGSG_OK)), ok, failBlock());
    b_.SetInsertPoint(ok);
    return b_.CreateLoad(b_.getDoubleTy(), queryOut_);
  }

  Vec vec(const Expr& e) {
    switch (e.op) {
      case ExprOp::Const: return {f64(e.vec[0]), f64(e.vec[1]), f64(e.vec[2])};
      case ExprOp::Param: return {load(params_, e.index), load(params_, e.index + 1), load(params_, e.index + 2)};
      case ExprOp::Attr:
        return {load(attrs_, 3ull * e.index), load(attrs_, 3ull * e.index + 1), load(attrs_, 3ull * e.index + 2)};
      case ExprOp::MakeVec: {
        llvm::Value* x = num(e.args[0]);
        llvm::Value* y = num(e.args[1]);
        llvm::Value* z = num(e.args[2]);
        return {x, y, z};
      }
      case ExprOp::Neg: {
        Vec v = vec(e.args[0]);
        return {b_.CreateFNeg(v[0]), b_.CreateFNeg(v[1]), b_.CreateFNeg(v[2])};
      }
      case ExprOp::Add:
      case ExprOp::Sub: {
        Vec x = vec(e.args[0]);
        Vec y = vec(e.args[1]);
        Vec r;
        for (int k = 0; k < 3; ++k)
          r[k] = e.op == ExprOp::Add ? b_.CreateFAdd(x[k], y[k]) : b_.CreateFSub(x[k], y[k]);
        return r;
      }
      case ExprOp::Mul: {
        if (e.args[0].type == ir::Type::Vec3) {
          Vec v = vec(e.args[0]);
          llvm::Value* s = num(e.args[1]);
          return {b_.CreateFMul(v[0], s), b_.CreateFMul(v[1], s), b_.CreateFMul(v[2], s)};
        }
        llvm::Value* s = num(e.args[0]);
        Vec v = vec(e.args[1]);
        return {b_.CreateFMul(s, v[0]), b_.CreateFMul(s, v[1]), b_.CreateFMul(s, v[2])};
      }
      case ExprOp::Div: {
        Vec v = vec(e.args[0]);
        llvm::Value* s = num(e.args[1]);
        return {b_.CreateFDiv(v[0], s), b_.CreateFDiv(v[1], s), b_.CreateFDiv(v[2], s)};
      }
      case ExprOp::Select:
        return branch<Vec>(
            truth(e.args[0]), [&] { return vec(e.args[1]); }, [&] { return vec(e.args[2]); });
      case ExprOp::Call:
        if (static_cast<Builtin>(e.index) == Builtin::Normalize) {
          Vec v = vec(e.args[0]);
          llvm::Value* n = call("fgsg_rt_vec_length", {v[0], v[1], v[2]});
          llvm::Value* positive = b_.CreateFCmpOGT(n, f64(0.0));
          Vec r;
          for (int k = 0; k < 3; ++k) r[k] = b_.CreateSelect(positive, b_.CreateFDiv(v[k], n), v[k]);
          return r;
        }
        break;
      case ExprOp::Query:
        if (static_cast<ir::Query>(e.index) == ir::Query::Field)
          return {askHost(e, 0), askHost(e, 1), askHost(e, 2)};
        break;
      default: break;
    }
    return raiseVec(e.loc);
  }

  llvm::Module& m_;
  llvm::LLVMContext& c_;
  llvm::IRBuilder<> b_;
  const Expr* root_;                       // a function of its own: its expression
  llvm::IRBuilderBase* outer_ = nullptr;     // inline: the caller's builder
  bool isVec_ = false;
  llvm::Function* fn_ = nullptr;
  llvm::Value* params_ = nullptr;
  llvm::Value* attrs_ = nullptr;
  llvm::Value* ctx_ = nullptr;
  llvm::BasicBlock* entry_ = nullptr;
  llvm::BasicBlock* fail_ = nullptr;
  llvm::Value* queryOut_ = nullptr;
  llvm::Value* queryArgs_ = nullptr;
};

}  // namespace

void declareRuntime(llvm::Module& m) {
  llvm::LLVMContext& c = m.getContext();
#define FGSG_RT_MATH(name, ret, ...) declare(m, #name, llvmFnType(c, &name), true);
#define FGSG_RT_FN(name, ret, ...) declare(m, #name, llvmFnType(c, &name), false);
#include "runtime/abi.def"
#undef FGSG_RT_MATH
}

llvm::Function* emitExpr(llvm::Module& m, const ir::Expr& e, const std::string& name) {
  return ExprCodegen(m, e, name).run();
}

llvm::Value* emitNumInline(llvm::Module& m, llvm::IRBuilderBase& b, const InlineSite& site, const ir::Expr& e) {
  return ExprCodegen(m, b, site).inlineNum(e);
}

void emitStoreInline(llvm::Module& m, llvm::IRBuilderBase& b, const InlineSite& site, const ir::Expr& e,
                     llvm::Value* out) {
  ExprCodegen(m, b, site).inlineStore(e, out);
}

}  // namespace fgsg::backend::codegen
