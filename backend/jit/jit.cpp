#include "backend/jit/jit.h"

#include "backend/codegen/program_codegen.h"
#include "backend/native/object_cache.h"

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
#include <optional>
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

  void defineRuntimeSymbols(const std::vector<native::RuntimeSymbol>& table) {
    llvm::orc::SymbolMap symbols;
    for (const native::RuntimeSymbol& s : table)
      symbols[lljit->mangleAndIntern(s.name)] = {llvm::orc::ExecutorAddr::fromPtr(s.address),
                                                 llvm::JITSymbolFlags::Exported | llvm::JITSymbolFlags::Callable};
    orThrow(lljit->getMainJITDylib().define(llvm::orc::absoluteSymbols(std::move(symbols))),
            "JIT: runtime symbols");
  }

  // Links a grammar's object into a JITDylib of its own (so every unit can name its
  // table `fgsg_program`; the runtime's symbols come from the main JITDylib). Nothing
  // when the object cannot be linked or lacks the table.
  std::optional<CompiledProgram> link(const std::string& object, bool fromCache, bool optimized) {
    auto& session = lljit->getExecutionSession();
    auto created = lljit->createJITDylib("fgsg_unit_" + std::to_string(units++));
    if (!created) throw std::runtime_error("JIT: unit: " + llvm::toString(created.takeError()));
    llvm::orc::JITDylib& unit = *created;
    unit.addToLinkOrder(lljit->getMainJITDylib());
    llvm::orc::ResourceTrackerSP tracker = unit.createResourceTracker();
    std::shared_ptr<void> release(nullptr, [&session, &unit, tracker](void*) {
      if (llvm::Error err = tracker->remove()) llvm::consumeError(std::move(err));
      if (llvm::Error err = session.removeJITDylib(unit)) llvm::consumeError(std::move(err));
    });
    llvm::Error added = lljit->addObjectFile(tracker, llvm::MemoryBuffer::getMemBufferCopy(object, "fgsg_program.o"));
    if (added) {
      llvm::consumeError(std::move(added));
      return std::nullopt;
    }
    auto table = lljit->lookup(unit, "fgsg_program");
    if (!table) {
      llvm::consumeError(table.takeError());
      return std::nullopt;
    }
    return CompiledProgram(table->toPtr<const FgsgProgram*>(), std::move(release), fromCache, optimized);
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

Jit::Jit(const std::vector<native::RuntimeSymbol>& runtime) : impl_(std::make_unique<Impl>()) {
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
  impl_->defineRuntimeSymbols(runtime);
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
  std::optional<CompiledProgram> out;
  if (tiering != Tiering::Baseline) {
    // An unusable object is compiled afresh below (and replaced).
    if (std::optional<std::string> cached = cache.load(key)) out = impl_->link(*cached, true, true);
  }
  if (!out) {
    const bool tiered = tiering == Tiering::Tiered && !cache.folder().empty();
    const bool firstTier = tiered || tiering == Tiering::Baseline;
    const std::string object = codegen::compileProgramObject(
        m, {}, codegen::CpuTarget::Host, firstTier ? codegen::CodeQuality::Baseline : codegen::CodeQuality::Optimized);
    out = impl_->link(object, false, !firstTier);
    if (!out) throw std::logic_error("internal: the JIT cannot link a grammar it compiled");
    if (tiered) {
      auto state = std::make_shared<BackgroundState>();
      std::thread thread([m, cache, key, state] {
        try {
          const std::string object =
              codegen::compileProgramObject(m, {}, codegen::CpuTarget::Host, codegen::CodeQuality::Optimized);
          bool stored = false;
          {
            std::lock_guard<std::mutex> lock(state->mutex);
            if (!state->abandoned) stored = cache.store(key, object);
          }
          // Linked outside the lock: a waiter past its limit abandons the link, not itself.
          if (stored) cache.storeLibrary(key, object);
        } catch (...) {
          // The next run compiles again; nothing is lost but time.
        }
        std::lock_guard<std::mutex> lock(state->mutex);
        state->done = true;
        state->ended.notify_all();
      });
      impl_->background.push_back({std::move(thread), std::move(state)});
    } else if (!firstTier) {
      if (cache.store(key, object)) cache.storeLibrary(key, object);
    }
  }
  out->setSeconds(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return std::move(*out);
}

}  // namespace fgsg::backend::jit
