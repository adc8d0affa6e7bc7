#include "backend/codegen/program_codegen.h"

#include "backend/codegen/expr_codegen.h"
#include "ir/program_layout.h"
#include "runtime/abi.h"

#include <llvm/IR/Constants.h>
#include <llvm/IR/Function.h>
#include <llvm/IR/IRBuilder.h>
#include <llvm/IR/LLVMContext.h>
#include <llvm/IR/LegacyPassManager.h>
#include <llvm/IR/Module.h>
#include <llvm/IR/Verifier.h>
#include <llvm/MC/TargetRegistry.h>
#include <llvm/Passes/PassBuilder.h>
#include <llvm/Support/TargetSelect.h>
#include <llvm/Support/raw_ostream.h>
#include <llvm/Target/TargetMachine.h>
#include <llvm/TargetParser/Host.h>

#include <mutex>
#include <stdexcept>

namespace fgsg::backend::codegen {
namespace {

using ir::OpKind;

// Expressions that read a value without any call cannot report an error.
bool cannotFail(const ir::Expr& e) {
  return e.op == ir::ExprOp::Const || e.op == ir::ExprOp::Param || e.op == ir::ExprOp::Attr;
}

class ProgramCodegen {
 public:
  ProgramCodegen(llvm::Module& out, const ir::Module& m, const ProgramCodegenOptions& o)
      : m_(out), c_(out.getContext()), b_(c_), ir_(m), opt_(o), layout_(ir::layoutProgram(m)) {
    declareRuntime(out);
    ptr_ = llvm::PointerType::getUnqual(c_);
  }

  void run() {
    std::vector<llvm::Constant*> blocks, guards, weights;
    for (uint32_t id = 0; id < layout_.blocks.size(); ++id) blocks.push_back(block(id));
    for (size_t r = 0; r < ir_.rules.size(); ++r) {
      const ir::Rule& rule = ir_.rules[r];
      guards.push_back(rule.hasGuard ? value(rule.guard, "fgsg_guard_" + std::to_string(r)) : nullPtr());
      for (size_t a = 0; a < rule.alternatives.size(); ++a) {
        const ir::Expr& p = rule.alternatives[a].probability;
        weights.push_back(p.isConst() ? nullPtr()
                                      : value(p, "fgsg_weight_" + std::to_string(r) + "_" + std::to_string(a)));
      }
    }
    table(blocks, guards, weights);
  }

 private:
  llvm::Constant* nullPtr() { return llvm::ConstantPointerNull::get(ptr_); }

  // A guard or probability: an expression function of its own, internal to the unit.
  llvm::Function* value(const ir::Expr& e, const std::string& name) {
    llvm::Function* f = emitExpr(m_, e, name);
    f->setLinkage(llvm::GlobalValue::InternalLinkage);
    return f;
  }

  llvm::Function* block(uint32_t id) {
    auto* type = llvm::FunctionType::get(b_.getVoidTy(), {ptr_, ptr_, ptr_}, false);
    fn_ = llvm::Function::Create(type, llvm::Function::InternalLinkage, "fgsg_block_" + std::to_string(id), m_);
    fn_->addFnAttr(llvm::Attribute::NoUnwind);
    ctx_ = fn_->getArg(0);
    params_ = fn_->getArg(1);
    attrs_ = fn_->getArg(2);
    ctx_->setName("ctx");
    params_->setName("params");
    attrs_->setName("attrs");
    entry_ = llvm::BasicBlock::Create(c_, "entry", fn_);
    exit_ = llvm::BasicBlock::Create(c_, "return", fn_);
    llvm::BasicBlock* body = llvm::BasicBlock::Create(c_, "ops", fn_, exit_);
    b_.SetInsertPoint(exit_);
    b_.CreateRetVoid();
    b_.SetInsertPoint(body);
    for (const ir::Op& op : *layout_.blocks[id]) this->op(op);
    b_.CreateBr(exit_);
    b_.SetInsertPoint(entry_);
    b_.CreateBr(body);
    return fn_;
  }

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

  llvm::Value* num(const ir::Expr& e) {
    llvm::Function* f = emitExpr(m_, e, "fgsg_expr_" + std::to_string(exprs_++));
    f->setLinkage(llvm::GlobalValue::InternalLinkage);
    return b_.CreateCall(f, {params_, attrs_, ctx_});
  }

  // Writes e (1 or 3 slots) at out[slot].
  void store(const ir::Expr& e, llvm::Value* out, uint32_t slot) {
    llvm::Value* at = b_.CreateConstInBoundsGEP1_64(b_.getDoubleTy(), out, slot);
    if (e.type != ir::Type::Vec3) {
      b_.CreateStore(num(e), at);
      return;
    }
    llvm::Function* f = emitExpr(m_, e, "fgsg_expr_" + std::to_string(exprs_++));
    f->setLinkage(llvm::GlobalValue::InternalLinkage);
    b_.CreateCall(f, {params_, attrs_, ctx_, at});
  }

  llvm::Value* u32(uint32_t v) { return b_.getInt32(v); }

  void op(const ir::Op& op) {
    const uint32_t id = layout_.opId(op);
    const bool sequential = ir_.mode != ir::DeriveMode::Parallel;
    bool mayFail = false;
    for (const auto& a : op.args) mayFail |= !cannotFail(a);
    for (const auto& s : op.sizes) mayFail |= !cannotFail(s.value);
    switch (op.kind) {
      case OpKind::Emit: {
        const ir::Symbol& target = ir_.symbols[op.index];
        llvm::Value* slots = buffer(target.slotCount);
        uint32_t slot = 0;
        for (const auto& a : op.args) {
          store(a, slots, slot);
          slot += ir::slotWidth(a.type);
        }
        if (mayFail) checkStop();
        call("fgsg_rt_emit", {ctx_, u32(id), slots});
        checkStop();
        return;
      }
      case OpKind::Translate:
        if (!sequential) break;
        {
          llvm::Value* x = num(op.args[0]);
          llvm::Value* y = num(op.args[1]);
          llvm::Value* z = num(op.args[2]);
          if (mayFail) checkStop();
          call("fgsg_rt_translate", {ctx_, x, y, z});
          checkStop();  // on a surface T traces, which can fail
        }
        return;
      case OpKind::Rotate:
        if (!sequential || op.index >= 3) break;
        {
          llvm::Value* degrees = num(op.args[0]);
          if (mayFail) checkStop();
          call("fgsg_rt_rotate", {ctx_, u32(op.index), degrees});
        }
        return;
      case OpKind::Push:
        if (!sequential) break;
        call("fgsg_rt_push", {ctx_});
        return;
      case OpKind::Pop:
        if (!sequential) break;
        call("fgsg_rt_pop", {ctx_, u32(id)});
        checkStop();
        return;
      case OpKind::Unsupported:
        // The engine refuses it before evaluating anything.
        call("fgsg_rt_op", {ctx_, u32(id), llvm::ConstantPointerNull::get(ptr_), u32(0)});
        checkStop();
        return;
      default: break;
    }
    // Every other op: its arguments in IR order, then the engine applies it.
    const uint32_t n = static_cast<uint32_t>(op.args.size() + op.sizes.size());
    llvm::Value* args = n ? buffer(n) : llvm::ConstantPointerNull::get(ptr_);
    uint32_t k = 0;
    for (const auto& a : op.args) store(a, args, k++);
    for (const auto& s : op.sizes) store(s.value, args, k++);
    if (mayFail) checkStop();
    call("fgsg_rt_op", {ctx_, u32(id), args, u32(n)});
    checkStop();
  }

  llvm::Constant* array(const std::vector<llvm::Constant*>& items, const char* name) {
    if (items.empty()) return nullPtr();
    auto* type = llvm::ArrayType::get(ptr_, items.size());
    return new llvm::GlobalVariable(m_, type, true, llvm::GlobalValue::PrivateLinkage,
                                    llvm::ConstantArray::get(type, items), name);
  }

  llvm::Constant* string(const std::string& s, const char* name) {
    auto* init = llvm::ConstantDataArray::getString(c_, s, true);
    return new llvm::GlobalVariable(m_, init->getType(), true, llvm::GlobalValue::PrivateLinkage, init, name);
  }

  // The FgsgProgram constant (runtime/abi.h), field for field.
  void table(const std::vector<llvm::Constant*>& blocks, const std::vector<llvm::Constant*>& guards,
             const std::vector<llvm::Constant*>& weights) {
    llvm::Type* i32 = b_.getInt32Ty();
    auto* type = llvm::StructType::get(c_, {i32, i32, ptr_, i32, ptr_, i32, ptr_, ptr_, ptr_});
    auto count = [&](size_t n) { return llvm::ConstantInt::get(i32, n); };
    llvm::Constant* init = llvm::ConstantStruct::get(
        type, {count(FGSG_ABI_VERSION), count(blocks.size()), array(blocks, "fgsg_blocks"),
               count(guards.size()), array(guards, "fgsg_guards"), count(weights.size()),
               array(weights, "fgsg_weights"),
               opt_.embedSource ? string(opt_.source, "fgsg_source") : nullPtr(),
               opt_.embedSource ? string(opt_.sourceName, "fgsg_source_name") : nullPtr()});
    new llvm::GlobalVariable(m_, type, true, llvm::GlobalValue::ExternalLinkage, init, opt_.tableSymbol);
  }

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
  uint64_t exprs_ = 0;
};

void initTargets() {
  static std::once_flag once;
  std::call_once(once, [] {
    llvm::InitializeNativeTarget();
    llvm::InitializeNativeTargetAsmPrinter();
  });
}

std::unique_ptr<llvm::TargetMachine> targetMachine(CpuTarget cpu) {
  initTargets();
  const std::string triple = llvm::sys::getProcessTriple();
  std::string error;
  const llvm::Target* target = llvm::TargetRegistry::lookupTarget(triple, error);
  if (!target) throw std::runtime_error("LLVM has no target for " + triple + ": " + error);
  std::string name = "generic", features;
  if (cpu == CpuTarget::Host) {
    name = llvm::sys::getHostCPUName().str();
    for (const auto& [feature, on] : llvm::sys::getHostCPUFeatures())
      features += (features.empty() ? "" : ",") + std::string(on ? "+" : "-") + feature.str();
  } else if (llvm::Triple(triple).getArch() == llvm::Triple::x86_64) {
    name = "x86-64";
  }
  std::unique_ptr<llvm::TargetMachine> tm(target->createTargetMachine(
      triple, name, features, llvm::TargetOptions(), llvm::Reloc::PIC_, std::nullopt,
      llvm::CodeGenOptLevel::Default));
  if (!tm) throw std::runtime_error("LLVM cannot make a target machine for " + triple);
  return tm;
}

void optimize(llvm::Module& m, llvm::TargetMachine& tm) {
  llvm::LoopAnalysisManager lam;
  llvm::FunctionAnalysisManager fam;
  llvm::CGSCCAnalysisManager cgam;
  llvm::ModuleAnalysisManager mam;
  llvm::PassBuilder pb(&tm);
  pb.registerModuleAnalyses(mam);
  pb.registerCGSCCAnalyses(cgam);
  pb.registerFunctionAnalyses(fam);
  pb.registerLoopAnalyses(lam);
  pb.crossRegisterProxies(lam, fam, cgam, mam);
  pb.buildPerModuleDefaultPipeline(llvm::OptimizationLevel::O2).run(m, mam);
}

}  // namespace

void emitProgram(llvm::Module& out, const ir::Module& m, const ProgramCodegenOptions& options) {
  ProgramCodegen(out, m, options).run();
}

std::string compileProgramObject(const ir::Module& m, const ProgramCodegenOptions& options,
                                 CpuTarget cpu) {
  std::unique_ptr<llvm::TargetMachine> tm = targetMachine(cpu);
  llvm::LLVMContext context;
  llvm::Module module("fgsg_program", context);
  module.setDataLayout(tm->createDataLayout());
  module.setTargetTriple(tm->getTargetTriple().str());
  emitProgram(module, m, options);
  std::string problems;
  llvm::raw_string_ostream problemStream(problems);
  if (llvm::verifyModule(module, &problemStream))
    throw std::logic_error("internal: the code generator made invalid LLVM IR: " + problems);
  optimize(module, *tm);
  llvm::SmallVector<char, 0> object;
  llvm::raw_svector_ostream stream(object);
  llvm::legacy::PassManager passes;
  if (tm->addPassesToEmitFile(passes, stream, nullptr, llvm::CodeGenFileType::ObjectFile))
    throw std::runtime_error("LLVM cannot emit object files for " + module.getTargetTriple());
  passes.run(module);
  return std::string(object.begin(), object.end());
}

}  // namespace fgsg::backend::codegen
