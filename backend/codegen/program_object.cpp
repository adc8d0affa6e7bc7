// From the emitted module to machine code: the target machine (this CPU for the JIT,
// the architecture's baseline for libraries), the pass pipelines of the two code
// qualities, and the entry points that print the optimised LLVM IR or return an object.
#include "backend/codegen/program_codegen.h"

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
#include <llvm/Transforms/InstCombine/InstCombine.h>
#include <llvm/Transforms/Scalar/EarlyCSE.h>
#include <llvm/Transforms/Scalar/SROA.h>
#include <llvm/Transforms/Scalar/SimplifyCFG.h>

#include <chrono>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

namespace fgsg::backend::codegen {
namespace {

void initTargets() {
  static std::once_flag once;
  std::call_once(once, [] {
    llvm::InitializeNativeTarget();
    llvm::InitializeNativeTargetAsmPrinter();
  });
}

std::unique_ptr<llvm::TargetMachine> targetMachine(CpuTarget cpu, CodeQuality quality) {
  initTargets();
  const std::string triple = llvm::sys::getProcessTriple();
  std::string error;
  const llvm::Target* target = llvm::TargetRegistry::lookupTarget(triple, error);
  if (!target) throw std::runtime_error("LLVM has no target for " + triple + ": " + error);
  std::string name = "generic", features;
  if (cpu == CpuTarget::Host) {
    name = llvm::sys::getHostCPUName().str();
    for (const auto& [feature, on] : llvm::sys::getHostCPUFeatures()) {
      if (!features.empty()) features += ',';
      features += on ? '+' : '-';
      features += feature.str();
    }
  } else if (llvm::Triple(triple).getArch() == llvm::Triple::x86_64) {
    name = "x86-64";
  }
  std::unique_ptr<llvm::TargetMachine> tm(target->createTargetMachine(
      triple, name, features, llvm::TargetOptions(), llvm::Reloc::PIC_, std::nullopt,
      quality == CodeQuality::Baseline ? llvm::CodeGenOptLevel::None : llvm::CodeGenOptLevel::Default));
  if (!tm) throw std::runtime_error("LLVM cannot make a target machine for " + triple);
  return tm;
}

// Optimized: the O2 pipeline. Baseline: what the generated code needs most, in one
// pass over each function (stack slots into registers, redundant loads and constant
// branches gone), for a first tier that compiles in a fraction of O2's time.
void optimize(llvm::Module& m, llvm::TargetMachine& tm, CodeQuality quality) {
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
  if (quality == CodeQuality::Optimized) {
    pb.buildPerModuleDefaultPipeline(llvm::OptimizationLevel::O2).run(m, mam);
    return;
  }
  llvm::FunctionPassManager fpm;
  fpm.addPass(llvm::SROAPass(llvm::SROAOptions::ModifyCFG));
  fpm.addPass(llvm::EarlyCSEPass());
  fpm.addPass(llvm::InstCombinePass());
  fpm.addPass(llvm::SimplifyCFGPass());
  llvm::ModulePassManager mpm;
  mpm.addPass(llvm::createModuleToFunctionPassAdaptor(std::move(fpm)));
  mpm.run(m, mam);
}

}  // namespace

std::string programLLVMText(const ir::Module& m) {
  std::unique_ptr<llvm::TargetMachine> tm = targetMachine(CpuTarget::Host, CodeQuality::Optimized);
  llvm::LLVMContext context;
  llvm::Module module("fgsg_program", context);
  module.setDataLayout(tm->createDataLayout());
  module.setTargetTriple(tm->getTargetTriple().str());
  emitProgram(module, m, {});
  optimize(module, *tm, CodeQuality::Optimized);
  std::string text;
  llvm::raw_string_ostream out(text);
  module.print(out, nullptr);
  return text;
}

std::string compileProgramObject(const ir::Module& m, const ProgramCodegenOptions& options,
                                 CpuTarget cpu, CodeQuality quality, ObjectCompileTimes* times) {
  using Clock = std::chrono::steady_clock;
  auto t = Clock::now();
  auto lap = [&t](double* into) {
    const auto now = Clock::now();
    if (into) *into = std::chrono::duration<double>(now - t).count();
    t = now;
  };
  std::unique_ptr<llvm::TargetMachine> tm = targetMachine(cpu, quality);
  llvm::LLVMContext context;
  llvm::Module module("fgsg_program", context);
  module.setDataLayout(tm->createDataLayout());
  module.setTargetTriple(tm->getTargetTriple().str());
  emitProgram(module, m, options);
  std::string problems;
  llvm::raw_string_ostream problemStream(problems);
  if (llvm::verifyModule(module, &problemStream))
    throw std::logic_error("internal: the code generator made invalid LLVM IR: " + problems);
  lap(times ? &times->emit : nullptr);
  optimize(module, *tm, quality);
  lap(times ? &times->optimize : nullptr);
  llvm::SmallVector<char, 0> object;
  llvm::raw_svector_ostream stream(object);
  llvm::legacy::PassManager passes;
  if (tm->addPassesToEmitFile(passes, stream, nullptr, llvm::CodeGenFileType::ObjectFile))
    throw std::runtime_error("LLVM cannot emit object files for " + module.getTargetTriple());
  passes.run(module);
  lap(times ? &times->machine : nullptr);
  return std::string(object.begin(), object.end());
}

}  // namespace fgsg::backend::codegen
