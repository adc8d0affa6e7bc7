// Which engine derives a grammar: the interpreter (the reference) or the JIT, which
// compiles the grammar through LLVM first (cached on disk, backend/jit/object_cache.h)
// and gives the same results bit for bit. `fgsg run --engine=interp|jit`; JIT default.
#pragma once

#include "ir/ir.h"
#include "runtime/assets.h"
#include "runtime/derivation.h"

#include <optional>
#include <string>

namespace fgsg::backend {

namespace jit {
class Jit;
}

enum class Engine { Interpreter, Jit };

// "interp" / "jit"; nullopt for anything else.
std::optional<Engine> parseEngine(const std::string& name);

struct EngineReport {
  double compileSeconds = 0.0;  // JIT: compiling or loading the code, and linking it
  bool fromCache = false;       // JIT: the object came from the cache
};

// `source` is the grammar's text (the JIT's cache key includes it). `jit`: the JIT to
// compile with, which then finishes its background work when the caller destroys it
// (null: one of the call's own, which waits before returning).
rt::DeriveResult derive(Engine engine, const ir::Module& module, const std::string& source,
                        const rt::DeriveOptions& options, rt::AssetLibrary& assets,
                        EngineReport* report = nullptr, jit::Jit* jit = nullptr);

}  // namespace fgsg::backend
