#include "backend/jit/jit.h"

#include "backend/codegen/program_codegen.h"
#include "backend/jit/object_cache.h"
#include "runtime/abi.h"

#include <llvm/ExecutionEngine/Orc/Core.h>
#include <llvm/ExecutionEngine/Orc/JITTargetMachineBuilder.h>
#include <llvm/ExecutionEngine/Orc/LLJIT.h>
#include <llvm/ExecutionEngine/Orc/ThreadSafeModule.h>
#include <llvm/IR/LLVMContext.h>
#include <llvm/IR/Module.h>
#include <llvm/IR/Verifier.h>
#include <llvm/Passes/PassBuilder.h>
#include <llvm/Support/TargetSelect.h>
#include <llvm/Support/MemoryBuffer.h>
#include <llvm/Support/raw_ostream.h>
#include <llvm/Target/TargetMachine.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace fgsg::backend::jit {
namespace {

template <class T>
T orThrow(llvm::Expected<T> value, const char* what) {
  if (!value) throw std::runtime_error(std::string(what) + ": " + llvm::toString(value.takeError()));
  return std::move(*value);
}

void orThrow(llvm::Error err, const char* what) {
  if (err) throw std::runtime_error(std::string(what) + ": " + llvm::toString(std::move(err)));
}

void initNativeTarget() {
  static std::once_flag once;
  std::call_once(once, [] {
    llvm::InitializeNativeTarget();
    llvm::InitializeNativeTargetAsmPrinter();
  });
}

}  // namespace

// What a background compile and the Jit waiting for it share.
struct BackgroundState {
  std::mutex mutex;
  std::condition_variable ended;
  bool done = false;       // the compile (and its store) is over
  bool abandoned = false;  // nobody waits any more: do not store
};

static std::atomic<int> abandonedCount{0};

struct Jit::Impl {
  std::unique_ptr<llvm::orc::LLJIT> lljit;
  std::unique_ptr<llvm::TargetMachine> tm;  // for the optimisation pipeline
  uint64_t units = 0;
  std::string lastIR;
  // An optimising compile for the cache (Tiering::Tiered), on its own thread.
  struct Background {
    std::thread thread;
    std::shared_ptr<BackgroundState> state;
  };
  std::vector<Background> background;
  std::chrono::steady_clock::time_point waitLimit = std::chrono::steady_clock::time_point::max();

  ~Impl() {
    for (auto& job : background) {
      bool done;
      {
        std::unique_lock<std::mutex> lock(job.state->mutex);
        done = job.state->ended.wait_until(lock, waitLimit, [&] { return job.state->done; });
        if (!done) job.state->abandoned = true;  // checked before storing, under the lock
      }
      if (done) {
        job.thread.join();
      } else {
        job.thread.detach();
        ++abandonedCount;
      }
    }
  }

  void defineRuntimeSymbols() {
    llvm::orc::SymbolMap symbols;
    auto add = [&](const char* name, auto* fn) {
      symbols[lljit->mangleAndIntern(name)] = {llvm::orc::ExecutorAddr::fromPtr(fn),
                                               llvm::JITSymbolFlags::Exported |
                                                   llvm::JITSymbolFlags::Callable};
    };
#define FGSG_RT_FN(name, ret, ...) add(#name, &name);
#include "runtime/abi.def"
    // libm functions the code generator itself may call for intrinsics on CPUs
    // without SSE4.1 (llvm.floor / llvm.ceil).
    add("floor", static_cast<double (*)(double)>(&::floor));
    add("ceil", static_cast<double (*)(double)>(&::ceil));
    // ... and the C library's block moves, which it may call for large copies (a scope
    // saved by '[' in direct derivation) instead of expanding them inline.
    add("memcpy", &::memcpy);
    add("memmove", &::memmove);
    add("memset", &::memset);
    orThrow(lljit->getMainJITDylib().define(llvm::orc::absoluteSymbols(std::move(symbols))),
            "JIT: runtime symbols");
  }

  // Links a grammar's object into a JITDylib of its own (so every unit can name its
  // table `fgsg_program`; the runtime's symbols come from the main JITDylib). False when
  // the object cannot be linked or lacks the table.
  bool link(const std::string& object, CompiledProgram& out) {
    auto& session = lljit->getExecutionSession();
    auto created = lljit->createJITDylib("fgsg_unit_" + std::to_string(units++));
    if (!created) throw std::runtime_error("JIT: unit: " + llvm::toString(created.takeError()));
    llvm::orc::JITDylib& unit = *created;
    unit.addToLinkOrder(lljit->getMainJITDylib());
    llvm::orc::ResourceTrackerSP tracker = unit.createResourceTracker();
    out.unit_ = std::shared_ptr<void>(nullptr, [&session, &unit, tracker](void*) {
      if (llvm::Error err = tracker->remove()) llvm::consumeError(std::move(err));
      if (llvm::Error err = session.removeJITDylib(unit)) llvm::consumeError(std::move(err));
    });
    llvm::Error added = lljit->addObjectFile(tracker, llvm::MemoryBuffer::getMemBufferCopy(object, "fgsg_program.o"));
    if (added) {
      llvm::consumeError(std::move(added));
      out.unit_.reset();
      return false;
    }
    auto table = lljit->lookup(unit, "fgsg_program");
    if (!table) {
      llvm::consumeError(table.takeError());
      out.unit_.reset();
      return false;
    }
    out.program_ = table->toPtr<const FgsgProgram*>();
    return true;
  }

  void optimize(llvm::Module& m) {
    llvm::LoopAnalysisManager lam;
    llvm::FunctionAnalysisManager fam;
    llvm::CGSCCAnalysisManager cgam;
    llvm::ModuleAnalysisManager mam;
    llvm::PassBuilder pb(tm.get());
    pb.registerModuleAnalyses(mam);
    pb.registerCGSCCAnalyses(cgam);
    pb.registerFunctionAnalyses(fam);
    pb.registerLoopAnalyses(lam);
    pb.crossRegisterProxies(lam, fam, cgam, mam);
    llvm::ModulePassManager mpm = pb.buildPerModuleDefaultPipeline(llvm::OptimizationLevel::O2);
    mpm.run(m, mam);
  }
};

Jit::Jit() : impl_(std::make_unique<Impl>()) {
  initNativeTarget();
  auto jtmb = orThrow(llvm::orc::JITTargetMachineBuilder::detectHost(), "JIT: host target");
  jtmb.setCodeGenOptLevel(llvm::CodeGenOptLevel::Default);
  impl_->tm = orThrow(jtmb.createTargetMachine(), "JIT: target machine");
  impl_->lljit = orThrow(llvm::orc::LLJITBuilder()
                             .setJITTargetMachineBuilder(jtmb)
                             .setLinkProcessSymbolsByDefault(false)
                             .setPlatformSetUp(llvm::orc::setUpInactivePlatform)
                             .create(),
                         "JIT: LLJIT");
  impl_->defineRuntimeSymbols();
}

Jit::~Jit() = default;

const std::string& Jit::lastIR() const { return impl_->lastIR; }

void Jit::waitForCache() {
  for (auto& job : impl_->background) job.thread.join();
  impl_->background.clear();
}

void Jit::stopWaitingAt(std::chrono::steady_clock::time_point limit) { impl_->waitLimit = limit; }

int abandonedCompiles() { return abandonedCount.load(); }

CompiledExprs Jit::compile(const std::vector<const ir::Expr*>& exprs) {
  Impl& j = *impl_;
  const std::string prefix = "fgsg_expr_u" + std::to_string(j.units++) + "_";
  auto context = std::make_unique<llvm::LLVMContext>();
  auto module = std::make_unique<llvm::Module>(prefix + "module", *context);
  module->setDataLayout(j.lljit->getDataLayout());
  module->setTargetTriple(j.lljit->getTargetTriple().str());

  CompiledExprs out;
  for (size_t i = 0; i < exprs.size(); ++i) {
    codegen::emitExpr(*module, *exprs[i], prefix + std::to_string(i));
    out.vec_.push_back(exprs[i]->type == ir::Type::Vec3);
  }
  std::string problems;
  llvm::raw_string_ostream problemStream(problems);
  if (llvm::verifyModule(*module, &problemStream))
    throw std::logic_error("internal: the JIT generated invalid LLVM IR: " + problems);
  j.optimize(*module);
  j.lastIR.clear();
  llvm::raw_string_ostream irStream(j.lastIR);
  module->print(irStream, nullptr);

  auto& dylib = j.lljit->getMainJITDylib();
  llvm::orc::ResourceTrackerSP tracker = dylib.createResourceTracker();
  orThrow(j.lljit->addIRModule(tracker, llvm::orc::ThreadSafeModule(std::move(module), std::move(context))),
          "JIT: add module");
  out.unit_ = std::shared_ptr<void>(nullptr, [tracker](void*) {
    if (llvm::Error err = tracker->remove()) llvm::consumeError(std::move(err));
  });
  for (size_t i = 0; i < exprs.size(); ++i) {
    auto addr = orThrow(j.lljit->lookup(prefix + std::to_string(i)), "JIT: lookup");
    out.fns_.push_back(addr.toPtr<void*>());
  }
  return out;
}

CompiledProgram Jit::compileProgram(const ir::Module& m, const std::string& source, const ObjectCache& cache,
                                    Tiering tiering) {
  const auto start = std::chrono::steady_clock::now();
  const std::string key = ObjectCache::key(m, source);
  CompiledProgram out;
  if (tiering != Tiering::Baseline) {
    if (std::optional<std::string> cached = cache.load(key)) {
      out.fromCache_ = true;
      if (!impl_->link(*cached, out)) out.fromCache_ = false;  // unusable: compiled afresh below
    }
  }
  if (!out.fromCache_) {
    const bool tiered = tiering == Tiering::Tiered && !cache.folder().empty();
    const bool firstTier = tiered || tiering == Tiering::Baseline;
    const std::string object = codegen::compileProgramObject(
        m, {}, codegen::CpuTarget::Host, firstTier ? codegen::CodeQuality::Baseline : codegen::CodeQuality::Optimized);
    if (!impl_->link(object, out)) throw std::logic_error("internal: the JIT cannot link a grammar it compiled");
    out.optimized_ = !firstTier;
    if (tiered) {
      auto state = std::make_shared<BackgroundState>();
      std::thread thread([m, cache, key, state] {
        try {
          const std::string object =
              codegen::compileProgramObject(m, {}, codegen::CpuTarget::Host, codegen::CodeQuality::Optimized);
          std::lock_guard<std::mutex> lock(state->mutex);
          if (!state->abandoned) cache.store(key, object);
        } catch (...) {
          // The next run compiles again; nothing is lost but time.
        }
        std::lock_guard<std::mutex> lock(state->mutex);
        state->done = true;
        state->ended.notify_all();
      });
      impl_->background.push_back({std::move(thread), std::move(state)});
    } else if (!firstTier) {
      cache.store(key, object);
    }
  }
  out.seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace fgsg::backend::jit
