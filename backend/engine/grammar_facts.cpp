// What the grammar uses, found once before deriving: queries, collisions, symbols that are
// derived where they are written (FGSG §4.4), and whether direct code may place instances.
#include "backend/engine/derivation.h"
#include "ir/queries_asked.h"

#include <functional>

namespace fgsg::backend {

bool Derivation::moduleUsesQuery(ir::Query q) const {
  return ir::anyQuery(m_, [q](ir::Query asked) { return asked == q; });
}

// FGSG §4.4: "we derive simple rules that only place one shape in a depth-first manner
// to detect collisions". A symbol is simple when each of its successors writes at most
// one shape that has rules, itself simple (a chain C ~> F, F ~> IC(...)), without
// recursion, and something in the chain can collide (IC, I under `collision all`, or
// a line segment). A simple symbol is derived on the spot, where its successor writes
// it; a collision inside counts as its own and culls the rest of that production.
void Derivation::findEagerSymbols() {
  const size_t n = m_.symbols.size();
  enum Mark : uint8_t { Unseen, Visiting, Done };
  std::vector<Mark> mark(n, Unseen);
  std::vector<uint8_t> simple(n, 0), collides(n, 0);
  std::function<void(uint32_t)> visit = [&](uint32_t s) {
    mark[s] = Visiting;
    bool ok = true, hit = false;
    int growing = 0;  // shapes with rules written by the successor being scanned
    std::function<void(const ir::Block&)> scan = [&](const ir::Block& b) {
      for (const auto& op : b) {
        if (op.kind == ir::OpKind::Instance)
          hit |= op.mode == ir::InstanceMode::Collide ||
                 (op.mode == ir::InstanceMode::Plain && collide_.testsEveryInstance());
        if (op.kind == ir::OpKind::LineSeg) hit = true;
        if (op.kind == ir::OpKind::Emit && !m_.symbols[op.index].rules.empty()) {
          if (++growing > 1) ok = false;
          if (mark[op.index] == Unseen) visit(op.index);
          if (mark[op.index] == Visiting || !simple[op.index]) ok = false;  // recursion
          hit |= collides[op.index] != 0;
        }
        for (const auto& body : op.bodies) scan(body);
      }
    };
    for (uint32_t ri : m_.symbols[s].rules)
      for (const auto& alt : m_.rules[ri].alternatives) {
        growing = 0;
        scan(alt.ops);
      }
    simple[s] = ok;
    collides[s] = hit;
    mark[s] = Done;
  };
  eager_.assign(n, 0);
  for (uint32_t s = 0; s < n; ++s) {
    if (m_.symbols[s].rules.empty()) continue;
    if (mark[s] == Unseen) visit(s);
    eager_[s] = simple[s] && collides[s];
  }
}

// Whether direct symbols that place instances may be used: when nothing but the
// instances' order could tell (no collisions, merges, lines or occlusion queries),
// and every shape the axiom leads to is direct or has no rules, all of one priority,
// so that the interpreter's order is that of (depth, preorder) of the placing shapes
// (breadth-first) or of their preorder (depth-first): orderDirectInstances restores it.
bool Derivation::canOrderDirectInstances() const {
  if (!program_->directPlaces || collide_.active() || usesOcclusion_ || collide_.testsEveryInstance()) return false;
  // Synthesize and Evolve create shapes of the symbols their files name, not written as Emit.
  if (moduleUses([](const ir::Op& op) { return op.kind == ir::OpKind::Synthesize || op.kind == ir::OpKind::Evolve ||
                               op.kind == ir::OpKind::Cells; }))
    return false;
  std::vector<uint8_t> seen(m_.symbols.size(), 0);
  std::vector<uint32_t> todo;
  std::function<void(const ir::Block&)> scan = [&](const ir::Block& b) {
    for (const auto& op : b) {
      if (op.kind == ir::OpKind::Emit && !seen[op.index]) {
        seen[op.index] = 1;
        todo.push_back(op.index);
      }
      for (const auto& body : op.bodies) scan(body);
    }
  };
  scan(m_.axiom);
  bool first = true;
  int priority = 0;
  while (!todo.empty()) {
    const uint32_t s = todo.back();
    todo.pop_back();
    const ir::Symbol& sym = m_.symbols[s];
    if (sym.rules.empty()) continue;
    if (!program_->direct[s] || (!first && sym.priority != priority)) return false;
    priority = sym.priority;
    first = false;
    for (uint32_t ri : sym.rules)
      for (const auto& alt : m_.rules[ri].alternatives) scan(alt.ops);
  }
  return true;
}

// Whether the plants of several seeds can be derived apart: when no shape can see what
// another placed — no collision tests (IC, Lock, `collision all`, --collide-all), no
// merges (IM), no lines (they join and stop at each other), no occlusion or visibility
// queries, no synthesis, Evolve or Cells (they place shapes and register assets of their own) —
// a plant grows alike alone.
bool Derivation::seedsGrowApart() const {
  if (m_.collision.all || opt_.collideAll) return false;
  if (moduleUses([](const ir::Op& op) {
        using K = ir::OpKind;
        return op.kind == K::Lock || op.kind == K::Line || op.kind == K::LineSeg || op.kind == K::Synthesize ||
               op.kind == K::Evolve || op.kind == K::Cells || (op.kind == K::Instance && op.mode != ir::InstanceMode::Plain);
      }))
    return false;
  return !moduleUsesQuery(ir::Query::ScopeOcc) && !moduleUsesQuery(ir::Query::ShapeVisible);
}

// Whether the grammar marches or samples a texture context: both need the surface laid
// out as a geometry image.
bool Derivation::usesMarchingSurface() const {
  return moduleUsesQuery(ir::Query::Texture) ||
         moduleUses([](const ir::Op& op) { return op.kind == ir::OpKind::Marching; });
}

double Derivation::stringId(const std::string& s) const {
  for (size_t i = 0; i < m_.strings.size(); ++i)
    if (m_.strings[i] == s) return static_cast<double>(i);
  return -1.0 - s.size();  // never equal to a grammar string: nothing compares with it
}

}  // namespace fgsg::backend
