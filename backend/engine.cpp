#include "backend/engine.h"

#include "backend/interp/interpreter.h"
#include "backend/native/code_loader.h"
#include "runtime/out_of_resources.h"

#include <memory>
#include <optional>
#include <stdexcept>

namespace fgsg::backend {

std::optional<Engine> parseEngine(const std::string& name) {
  if (name == "interp") return Engine::Interpreter;
  if (name == "jit") return Engine::Jit;
  return std::nullopt;
}

rt::DeriveResult derive(Engine engine, const ir::Module& module, const std::string& source,
                        const rt::DeriveOptions& options, rt::AssetLibrary& assets,
                        EngineReport* report, native::CodeLoader* loader) {
  if (engine == Engine::Interpreter) return interpret(module, options, assets);
  // Only a failure to compile is the JIT's: what deriving throws is reported by
  // deriveCompiled like the interpreter's.
  std::unique_ptr<native::CodeLoader> own;
  std::optional<native::CompiledProgram> code;
  try {
    if (!loader) loader = (own = std::make_unique<native::CodeLoader>()).get();
    code.emplace(loader->load(module, source));
  } catch (const std::exception& e) {
    rt::DeriveResult failed;
    if (const std::string why = rt::outOfResources(e); !why.empty())  // as deriving reports it
      failed.messages.push_back({true, "R020", 0, 0,
                                 "out of memory while compiling (" + why +
                                     "): the machine gives this process too little memory; nothing is written"});
    else
      failed.messages.push_back({true, "R900", 0, 0,
                                 std::string("the JIT cannot compile this grammar: ") + e.what() +
                                     " (--engine=interp runs it without compiling)"});
    return failed;
  }
  if (report) {
    report->compileSeconds = code->seconds();
    report->fromCache = code->fromCache();
  }
  return deriveCompiled(module, code->program(), options, assets);
}

}  // namespace fgsg::backend
