// The derivation entry points: the grammar's attribute overrides applied, one
// Derivation (backend/engine/) run, and whatever escapes it turned into one error.
#include "backend/interp/interpreter.h"

#include "backend/engine/derivation.h"
#include "runtime/out_of_resources.h"
#include "runtime/plugins/plugin_library.h"

#include <chrono>
#include <exception>
#include <memory>
#include <new>

namespace fgsg::backend {
namespace {

// The module as one derivation reads it (--set and lots may add strings to its table) and
// the attribute slots, the whole derivation's and each lot's; false with the error in
// `failed`.
bool prepare(const ir::Module& module, const rt::DeriveOptions& options, ir::Module& local,
             std::vector<double>& attrs, std::vector<std::vector<double>>& lotAttrs, rt::DeriveResult& failed) {
  local = module;
  try {
    attrs = attributeSlots(local, options.attrOverrides, attributeRandomKey(options.seed, 0));
    lotAttrs = lotAttributeSlots(local, options);
    return true;
  } catch (const DeriveError& e) {
    failed.messages.push_back({true, e.code, e.loc.line, e.loc.col, e.message});
    return false;
  }
}

// What escapes a derivation (no memory; a bug) becomes its one error here, so every
// caller — fgsg run, the REPL, the C API — reports it alike and none aborts.
rt::DeriveResult escapedFailure(std::exception_ptr thrown) {
  rt::DeriveResult failed;
  try {
    std::rethrow_exception(thrown);
  } catch (const std::bad_alloc&) {
    failed.messages.push_back({true, "R020", 0, 0,
                               "out of memory while deriving: the grammar needs more memory than this "
                               "machine gives it (--max-memory stops a derivation earlier and keeps its "
                               "shapes); nothing is written"});
  } catch (const std::exception& e) {
    if (const std::string why = rt::outOfResources(e); !why.empty())
      failed.messages.push_back({true, "R020", 0, 0,
                                 "out of memory while deriving (" + why +
                                     "): the machine gives this process too little memory; nothing is written"});
    else if (dynamic_cast<const rt::PluginError*>(&e))
      failed.messages.push_back({true, "R900", 0, 0, std::string("this grammar needs a part of fgsg that cannot be loaded: ") + e.what()});
    else
      failed.messages.push_back({true, "R900", 0, 0, std::string("internal error while deriving: ") + e.what()});
  } catch (...) {
    failed.messages.push_back({true, "R900", 0, 0, "internal error while deriving"});
  }
  return failed;
}

// Runs the derivation `make` builds; a grammar that asks context queries twice, as
// CityEngine does: the first with the queries at their defaults records the labelled
// shapes and occluders, the second answers from them (context_queries.cpp). An error in
// the first is the result.
template <class Make>
rt::DeriveResult runWithContext(const ir::Module& module, Make make) {
  if (!usesContextQueries(module)) return make()->run();
  std::shared_ptr<const ContextWorld> world;
  {
    auto first = make();
    first->recordContext();
    rt::DeriveResult recorded = first->run();
    if (!recorded.ok) return recorded;
    world = first->takeContextWorld();
  }
  auto second = make();
  second->answerContextFrom(std::move(world));
  return second->run();
}

}  // namespace

rt::DeriveResult interpret(const ir::Module& module, const rt::DeriveOptions& options,
                           rt::AssetLibrary& assets) {
  try {
    ir::Module local;
    std::vector<double> attrs;
    std::vector<std::vector<double>> lotAttrs;
    rt::DeriveResult failed;
    if (!prepare(module, options, local, attrs, lotAttrs, failed)) return failed;
    return runWithContext(local, [&] {
      auto d = std::make_unique<Derivation>(local, options, assets, attrs);
      d->setLotAttributes(lotAttrs);
      return d;
    });
  } catch (...) {
    return escapedFailure(std::current_exception());
  }
}

rt::DeriveResult deriveCompiled(const ir::Module& module, const FgsgProgram& program,
                                const rt::DeriveOptions& options, rt::AssetLibrary& assets) {
  try {
    ir::Module local;
    std::vector<double> attrs;
    std::vector<std::vector<double>> lotAttrs;
    rt::DeriveResult failed;
    if (!prepare(module, options, local, attrs, lotAttrs, failed)) return failed;
    // Direct derivation first; where it could not be exact, the engine's own order, within
    // the same --max-seconds.
    rt::DeriveOptions timed = options;
    if (timed.startedAt == std::chrono::steady_clock::time_point{}) timed.startedAt = std::chrono::steady_clock::now();
    // Context queries need every shape to pass through the engine (direct code writes
    // none of its tree), so their grammars go the engine's own way at once.
    if (!usesContextQueries(local)) {
      Derivation fast(local, timed, assets, attrs, &program, true);
      fast.setLotAttributes(lotAttrs);
      rt::DeriveResult result = fast.run();
      if (!fast.needsExactRun()) return result;
    }
    return runWithContext(local, [&] {
      auto exact = std::make_unique<Derivation>(local, timed, assets, attrs, &program, false);
      exact->setLotAttributes(lotAttrs);
      return exact;
    });
  } catch (...) {
    return escapedFailure(std::current_exception());
  }
}

}  // namespace fgsg::backend

