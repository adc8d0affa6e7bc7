// Rule choice: which rules of a symbol apply (guards; context in a parallel string,
// parallel_rewriter.cpp, or in a sequential one, sequential_string.h), specific rules
// before general ones, and one alternative drawn by weight from the shape's own random
// stream.
#include "backend/engine/derivation.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace fgsg::backend {

// A rule with a guard or a context is specific; one without is general. Specific rules
// that apply are preferred (ABOP's precedence of context-sensitive productions; CGA's
// guarded rule before its fallback); general rules are candidates only otherwise.
bool Derivation::isSpecific(const ir::Rule& r) {
  return r.hasGuard || !r.left.empty() || !r.right.empty();
}

// Picks one alternative among the rules whose guard holds, weights normalised.
const ir::Alternative* Derivation::choose(const ir::Symbol& sym, const Frame& f, uint32_t node, double* params) {
  // The common case: one unguarded rule with one branch of constant positive weight.
  if (sym.rules.size() == 1) {
    const ir::Rule& only = m_.rules[sym.rules[0]];
    if (!isSpecific(only) && only.alternatives.size() == 1 &&
        only.alternatives[0].probability.isConst() && only.alternatives[0].probability.num > 0) {
      chosenRule_ = sym.rules[0];
      return &only.alternatives[0];
    }
  }
  candidates_.clear();
  double total = 0;
  for (int pass = 0; pass < 2 && candidates_.empty(); ++pass) {
    uint32_t taken = UINT32_MAX;
    for (uint32_t ri : sym.rules) {
      const ir::Rule& r = m_.rules[ri];
      if (isSpecific(r) != (pass == 0)) continue;
      if (!contextHolds(r, node, params)) continue;
      if (r.hasGuard && !guardHolds(ri, f)) continue;
      if (pass == 0 && !takesPart(sym.firstApplicable, ri, taken)) continue;
      addCandidates(r, ri, f, total);
    }
  }
  if (candidates_.empty()) return nullptr;
  const Candidate& pick = pickCandidate(*f.rng, total);
  chosenRule_ = pick.rule;
  contextHolds(m_.rules[pick.rule], node, params);  // its context's parameters again: another rule's may be there
  return pick.alt;
}

// Whether specific rule `ri`, which applies, joins the candidates. Of a symbol whose
// specific rules write no probabilities (ir::Symbol::firstApplicable) only the first
// that applies does; a later one that also applies is an overlap, reported once per
// pair (R029). Every guard is still evaluated, so the random stream does not depend on
// which rule wins.
bool Derivation::takesPart(bool firstApplicable, uint32_t ri, uint32_t& taken) {
  if (!firstApplicable) return true;
  if (taken == UINT32_MAX) {
    taken = ri;
    return true;
  }
  noteOverlap({taken, ri});
  return false;
}

void Derivation::noteOverlap(const std::pair<uint32_t, uint32_t>& rules) {
  if (std::find(overlaps_.begin(), overlaps_.end(), rules) == overlaps_.end()) overlaps_.push_back(rules);
}

// R029 for each pair of rules met applying to one shape, the first one's location.
void Derivation::overlapWarnings(std::vector<rt::DeriveMessage>& messages) const {
  for (const auto& [first, second] : overlaps_) {
    const ir::Rule& a = m_.rules[first];
    const ir::Rule& b = m_.rules[second];
    messages.push_back({false, "R029", a.loc.line, a.loc.col,
                        "rules '" + a.label + "' (line " + std::to_string(a.loc.line) + ") and '" + b.label +
                            "' (line " + std::to_string(b.loc.line) + ") both apply to a '" +
                            m_.symbols[a.symbol].name +
                            "' shape: the first is taken, as CGA's case does (guards that exclude each other "
                            "say which is meant; probabilities on the rules draw one at random)"});
  }
}

// A rule's context around the shape at `node` of the sequential string (always true for a
// rule without one). Contexts are matched in the string a grammar with them keeps.
bool Derivation::contextHolds(const ir::Rule& r, uint32_t node, double* params) const {
  if (r.left.empty() && r.right.empty()) return true;
  if (!sequentialString_ || node == SequentialString::kNone) return false;
  return sequentialString_->matchLeft(r, node, params) && sequentialString_->matchRight(r, node, params);
}

bool Derivation::guardHolds(uint32_t rule, const Frame& f) {
  const FgsgValueFn compiled = program_ ? program_->guards[rule] : nullptr;
  return compiled ? callValue(compiled, f) != 0.0 : eval_.truth(m_.rules[rule].guard, f);
}

// Adds the branches of a rule that applies, with their weights, to the candidates.
void Derivation::addCandidates(const ir::Rule& r, uint32_t ri, const Frame& f, double& total) {
  for (const auto& alt : r.alternatives) {
    const FgsgValueFn compiled =
        program_ ? program_->weights[layout_.firstAlternative[ri] + (&alt - r.alternatives.data())] : nullptr;
    const double w = compiled ? callValue(compiled, f) : eval_.num(alt.probability, f);
    if (!(w >= 0) || !std::isfinite(w))
      throw DeriveError{alt.probability.loc, "R008",
                        "a probability evaluated to " + std::to_string(w) +
                            "; probabilities must be finite and not negative"};
    if (w > 0) {
      candidates_.push_back({&alt, ri, w});
      total += w;
    }
  }
}

// One candidate, chosen with probability proportional to its weight; a single
// candidate takes no random number, so adding an impossible branch changes nothing.
const Derivation::Candidate& Derivation::pickCandidate(rt::RandomStream& rng, double total) const {
  if (candidates_.size() == 1) return candidates_.front();
  double x = rng.next() * total;
  for (const auto& c : candidates_) {
    if (x < c.weight) return c;
    x -= c.weight;
  }
  return candidates_.back();
}

}  // namespace fgsg::backend
