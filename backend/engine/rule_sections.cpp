// lpfg's decomposition and homomorphism sections (L-Py's decomposition and
// interpretation rules) in a parallel derivation: passes of their own rules over the
// string, pass after pass while a rule applies, at most `maximum depth` passes (as
// L-Py's derive and its recursive interpretation do; the rules are context-free, so a
// module no rule rewrote in one pass is not rewritten in the next). Decomposition runs
// after each step and its result is the string the next step rewrites; homomorphism
// runs once on the final string, and only the turtle reads its result.
#include "backend/engine/derivation.h"

#include <algorithm>

namespace fgsg::backend {

// From `str` into `out`: whether a rule of `section` applied (`out` is then the result;
// `str` is never changed). --max-shapes and the other limits end the passes as they end a
// step: the rest of the string is kept as it is.
bool Derivation::rewriteSection(ir::RuleSection section, const ModuleString& str, ModuleString& out, uint32_t step,
                                bool& limitHit, std::optional<LimitReached>& stopped) {
  if (std::none_of(m_.rules.begin(), m_.rules.end(), [&](const ir::Rule& r) { return r.section == section; }))
    return false;
  const int depth = section == ir::RuleSection::Decomposition ? m_.decompositionDepth : m_.homomorphismDepth;
  out.clear();
  if (!sectionPass(section, str, out, step, limitHit, stopped)) return false;
  cutBranches(out);
  ModuleString next;
  for (int pass = 1; pass < depth && !limitHit; ++pass) {
    next.clear();
    if (!sectionPass(section, out, next, step, limitHit, stopped)) break;
    cutBranches(next);
    out.swap(next);
  }
  return true;
}

// One pass: each symbol module that a rule of `section` applies to is replaced by the
// chosen successor, every other module copied. Whether any was replaced.
bool Derivation::sectionPass(ir::RuleSection section, const ModuleString& str, ModuleString& next, uint32_t step,
                             bool& limitHit, std::optional<LimitReached>& stopped) {
  bool rewrote = false;
  for (size_t i = 0; i < str.size(); ++i) {
    const StringModule& mod = str.modules[i];
    const StringOp& so = plan_[mod.op];
    if (limitHit || so.kind != ir::OpKind::Emit) {
      copyModule(str, i, next);
      continue;
    }
    const ir::Symbol& sym = m_.symbols[so.op->index];
    rt::RandomStream modRng{mod.key, 0};
    const bool hasRules =
        !(section == ir::RuleSection::Decomposition ? sym.decompositions : sym.homomorphisms).empty();
    const ir::Alternative* alt = hasRules ? chooseInString(sym, section, str, i, modRng, step) : nullptr;
    if (!alt) {
      copyModule(str, i, next);
      continue;
    }
    rewrote = true;
    ++stats_.rewrites;
    ++ruleUses_[chosenRule_];
    Frame rf{params_.data(), &modRng, nullptr, step, so.childIndex, this};
    appendModules(blockOf(alt), alt->ops, rf, mod.key, next, so.op->index);
    if (next.size() >= opt_.maxShapes) limitHit = true;
    if (!limitHit && (stopped = limitsReached())) limitHit = true;
  }
  return rewrote;
}

}  // namespace fgsg::backend
