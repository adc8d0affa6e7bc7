#include "backend/native/runtime_symbols.h"

#include "runtime/abi.h"

#include <cmath>
#include <cstring>

namespace fgsg::backend::native {

const std::vector<RuntimeSymbol>& runtimeSymbols() {
  static const std::vector<RuntimeSymbol> symbols = [] {
    std::vector<RuntimeSymbol> s;
    auto add = [&](const char* name, auto* fn) { s.push_back({name, reinterpret_cast<void*>(fn)}); };
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
    return s;
  }();
  return symbols;
}

}  // namespace fgsg::backend::native
