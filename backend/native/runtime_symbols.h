// The functions generated code calls, by name: the runtime's entry points
// (runtime/abi.def) and the few C library functions LLVM may emit calls to. The JIT
// defines them as absolute symbols, so its code resolves nothing from the process; the
// executable passes this table to the LLVM plugin, which makes the linker keep every
// entry point in it (and export it, for the JIT cache's libraries).
#pragma once

#include <vector>

namespace fgsg::backend::native {

struct RuntimeSymbol {
  const char* name;
  void* address;
};

const std::vector<RuntimeSymbol>& runtimeSymbols();

}  // namespace fgsg::backend::native
