// The entry point of lib/libfgsg_llvm.so (backend/native/llvm_plugin.h): the table the
// executable calls the code generator and the JIT through.
#include "backend/codegen/program_codegen.h"
#include "backend/jit/jit.h"
#include "backend/native/llvm_plugin.h"

namespace {

using namespace fgsg::backend;

const native::LlvmPlugin kPlugin{
    native::kLlvmPluginVersion,
    [](const std::vector<native::RuntimeSymbol>& runtime) -> std::unique_ptr<native::ProgramCompiler> {
      return std::make_unique<jit::Jit>(runtime);
    },
    [](const fgsg::ir::Module& m, const codegen::ProgramCodegenOptions& options, codegen::CpuTarget cpu) {
      return codegen::compileProgramObject(m, options, cpu);
    },
    [](const fgsg::ir::Module& m) { return codegen::programLLVMText(m); },
    []() { return jit::abandonedCompiles(); },
};

}  // namespace

extern "C" __attribute__((visibility("default"))) const native::LlvmPlugin* fgsg_llvm_plugin() { return &kPlugin; }
