// Which symbols get direct code (direct_codegen.cpp): an analysis of the IR alone, which
// emits nothing.
#include "backend/codegen/program_codegen_internal.h"

namespace fgsg::backend::codegen::detail {

using ir::OpKind;

namespace {

bool hasQuery(const ir::Expr& e) {
  if (e.op == ir::ExprOp::Query) return true;
  for (const auto& a : e.args)
    if (hasQuery(a)) return true;
  return false;
}

}  // namespace

// The direct symbols (runtime/abi.h, FgsgDirectFn): the largest set whose successors
// only use scope commands, place plain instances and create shapes of ruleless (not in
// a CGA grammar) or direct symbols, with brackets that balance, and no query anywhere. Sequential
// derivations only. `places`: the symbol's shapes may place instances.
std::vector<bool> findDirectSymbols(const ir::Module& m, std::vector<bool>& places) {
  std::vector<bool> direct(m.symbols.size(), false);
  places.assign(m.symbols.size(), false);
  if (m.mode == ir::DeriveMode::Parallel) return direct;
  // In a CGA grammar a ruleless shape outputs its own geometry, which direct code, given
  // only a scope, cannot build: its creators are left to the engine.
  const bool leavesOutput = ir::leavesOutputGeometry(m);
  for (size_t s = 0; s < m.symbols.size(); ++s) {
    const ir::Symbol& sym = m.symbols[s];
    bool ok = !sym.rules.empty() && sym.name != "F";  // F draws when no rule applies
    for (uint32_t ri : sym.rules) {
      const ir::Rule& r = m.rules[ri];
      if (!choosable(r)) continue;
      if (r.hasGuard && hasQuery(r.guard)) ok = false;
      for (const auto& alt : r.alternatives) {
        if (hasQuery(alt.probability)) ok = false;
        int depth = 0;
        for (size_t k = 0; k < alt.ops.size(); ++k) {
          const ir::Op& op = alt.ops[k];
          switch (op.kind) {
            case OpKind::Translate:
            case OpKind::Rotate:
            case OpKind::RotateNormal:
            case OpKind::Scale: break;
            case OpKind::Emit: ok &= !(leavesOutput && m.symbols[op.index].rules.empty()); break;
            case OpKind::Instance:
              ok &= op.mode == ir::InstanceMode::Plain;
              // A .cga i() whose shape goes on only gives the shape the asset, which the
              // leaf ending it outputs (Derivation::carryInsert): the engine's to do.
              ok &= !(leavesOutput && m.cityEngineLots && k + 1 < alt.ops.size() && alt.ops[k + 1].kind != OpKind::Pop);
              places[s] = true;
              break;
            case OpKind::Push: ++depth; break;
            case OpKind::Pop: ok &= --depth >= 0; break;
            default: ok = false;
          }
          for (const auto& a : op.args) ok &= !hasQuery(a);
          for (const auto& sz : op.sizes) ok &= !hasQuery(sz.value);
        }
        ok &= depth == 0;
      }
    }
    direct[s] = ok;
  }
  // A symbol creating a shape that is neither ruleless nor direct is not direct.
  for (bool changed = true; changed;) {
    changed = false;
    for (size_t s = 0; s < m.symbols.size(); ++s) {
      if (!direct[s]) continue;
      for (uint32_t ri : m.symbols[s].rules)
        for (const auto& alt : m.rules[ri].alternatives)
          for (const ir::Op& op : alt.ops)
            if (op.kind == OpKind::Emit && !m.symbols[op.index].rules.empty() && !direct[op.index] &&
                direct[s]) {
              direct[s] = false;
              changed = true;
            }
    }
  }
  // Placing spreads to the symbols whose shapes create placing ones.
  for (bool changed = true; changed;) {
    changed = false;
    for (size_t s = 0; s < m.symbols.size(); ++s) {
      if (!direct[s] || places[s]) continue;
      for (uint32_t ri : m.symbols[s].rules)
        for (const auto& alt : m.rules[ri].alternatives)
          for (const ir::Op& op : alt.ops)
            if (op.kind == OpKind::Emit && direct[op.index] && places[op.index] && !places[s]) {
              places[s] = true;
              changed = true;
            }
    }
  }
  return direct;
}

}  // namespace fgsg::backend::codegen::detail
