// Which engine derives a grammar: the interpreter (the reference) or the JIT, which
// compiles the grammar through LLVM first (cached on disk, backend/native/object_cache.h)
// and gives the same results bit for bit. `fgsg run --engine=interp|jit`; JIT default.
#pragma once

#include "ir/ir.h"
#include "runtime/assets.h"
#include "runtime/derivation.h"

#include <optional>
#include <string>

namespace fgsg::backend {

namespace native {
class CodeLoader;
}

enum class Engine { Interpreter, Jit };

// "interp" / "jit"; nullopt for anything else.
std::optional<Engine> parseEngine(const std::string& name);

struct EngineReport {
  double compileSeconds = 0.0;  // JIT: compiling or loading the code, and linking it
  bool fromCache = false;       // JIT: the code came from the cache
};

// `source` is the grammar's text (the JIT's cache key includes it). `loader`: where the
// JIT's code comes from, which then finishes its background work when the caller
// destroys it (null: one of the call's own, which waits before returning).
rt::DeriveResult derive(Engine engine, const ir::Module& module, const std::string& source,
                        const rt::DeriveOptions& options, rt::AssetLibrary& assets,
                        EngineReport* report = nullptr, native::CodeLoader* loader = nullptr);

}  // namespace fgsg::backend
