// The LLVM half of fgsg: the code generator and the JIT (backend/codegen, backend/jit)
// built as lib/libfgsg_llvm.so and opened with dlopen the first time a command needs to
// compile. libLLVM costs every process that loads it tens of milliseconds (relocations,
// page faults, static constructors): `fgsg --version`, `check`, `synth` and runs whose
// code is cached (object_cache.h) never load it (issue #18).
//
// The plugin resolves the rest of fgsg (the IR, the cache, the runtime's entry points)
// from the executable, which exports them (CMake: fgsg_export_for_plugins).
#pragma once

#include "backend/codegen/program_codegen.h"
#include "backend/native/program_compiler.h"
#include "backend/native/runtime_symbols.h"

#include <memory>
#include <string>
#include <vector>

namespace fgsg::backend::native {

// Bump with any change to this table or to the types it passes.
constexpr int kLlvmPluginVersion = 1;

struct LlvmPlugin {
  int version;
  // A JIT calling `runtime` (throws std::runtime_error when no native target can be set up).
  std::unique_ptr<ProgramCompiler> (*makeCompiler)(const std::vector<RuntimeSymbol>& runtime);
  // codegen::compileProgramObject and programLLVMText (`fgsg compile`, `fgsg ir --llvm`).
  std::string (*compileProgramObject)(const ir::Module& m, const codegen::ProgramCodegenOptions& options,
                                      codegen::CpuTarget cpu);
  std::string (*programLLVMText)(const ir::Module& m);
  // jit::abandonedCompiles: background compiles still running LLVM at exit.
  int (*abandonedCompiles)();
};

// The plugin's table, loading it on first use. Throws rt::PluginError naming the library
// and why it cannot be used (missing, not loadable, another version).
const LlvmPlugin& llvmPlugin();

// Whether llvmPlugin() has loaded it (commands ask before touching abandoned compiles).
bool llvmPluginLoaded();

// The extern "C" function the plugin exports; it returns its table.
inline constexpr const char* kLlvmPluginEntry = "fgsg_llvm_plugin";

}  // namespace fgsg::backend::native
