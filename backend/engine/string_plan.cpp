// The per-op table of a parallel derivation (parallel_string.h): what each op's modules
// are, and which symbols rewrite by a fixed template.
#include "backend/engine/parallel_string.h"

#include "backend/engine/query_modules.h"

#include "runtime/random.h"

#include <algorithm>

namespace fgsg::backend {
namespace {

bool allFixed(const std::vector<ir::Expr>& es) { return std::all_of(es.begin(), es.end(), isFixed); }

// Ops a template may hold: what a string holds, with no argument taken from the module.
bool templateOp(const ir::Op& op, const ir::Module& m, uint32_t owner) {
  if (!stringHolds(op)) return false;
  if (op.kind == ir::OpKind::Instance)  // holds the owner's parameters, which vary unless there are none
    return m.symbols[owner].slotCount == 0;
  return allFixed(op.args) &&
         std::all_of(op.sizes.begin(), op.sizes.end(), [](const ir::Size& s) { return isFixed(s.value); });
}

// The symbol's successor as a template, when it has one (see SuccessorTemplate).
bool makeTemplate(const ir::Module& m, const ir::ProgramLayout& layout, uint32_t symbol,
                  const std::function<void(const ir::Expr&, double*, bool)>& store, const std::vector<StringOp>& ops,
                  SuccessorTemplate& t) {
  const ir::Symbol& sym = m.symbols[symbol];
  if (sym.rules.size() != 1) return false;
  const ir::Rule& r = m.rules[sym.rules[0]];
  if (r.hasGuard || !r.left.empty() || !r.right.empty() || r.alternatives.size() != 1) return false;
  const ir::Alternative& alt = r.alternatives[0];
  if (!alt.probability.isConst() || !(alt.probability.num > 0)) return false;
  for (const ir::Op& op : alt.ops)
    if (!templateOp(op, m, symbol)) return false;
  t.rule = sym.rules[0];
  const uint32_t first = layout.firstOp[layout.alternativeBlock(sym.rules[0], 0)];
  for (size_t k = 0; k < alt.ops.size(); ++k) {
    const ir::Op& op = alt.ops[k];
    const uint32_t id = first + static_cast<uint32_t>(k);
    t.ops.push_back(id);
    t.firstArg.push_back(static_cast<uint32_t>(t.args.size()));
    const bool isSymbol = op.kind == ir::OpKind::Emit;
    t.keySalt.push_back(isSymbol ? rt::childSalt(ops[id].childIndex) : 0);
    t.keyMask.push_back(isSymbol ? ~uint64_t(0) : 0);
    // By index, not by the iterator insert returns: an op without arguments inserts
    // nothing and that iterator is end(), which may not be dereferenced.
    const size_t at = t.args.size();
    t.args.resize(at + ops[id].argCount, 0.0);
    double* a = t.args.data() + at;
    if (op.kind == ir::OpKind::Instance) continue;  // the owner has no parameters
    for (const ir::Expr& e : op.args) {
      store(e, a, isSymbol);
      a += isSymbol ? ir::slotWidth(e.type) : 1;
    }
    for (const ir::Size& s : op.sizes) store(s.value, a++, false);
  }
  return true;
}

}  // namespace

bool stringHolds(const ir::Op& op) {
  switch (op.kind) {
    case ir::OpKind::Emit:
    case ir::OpKind::Translate:
    case ir::OpKind::Rotate:
    case ir::OpKind::RotateNormal:
    case ir::OpKind::Scale:
    case ir::OpKind::Push:
    case ir::OpKind::Pop:
    case ir::OpKind::Turtle:
    case ir::OpKind::Color: return true;
    case ir::OpKind::Instance: return op.mode == ir::InstanceMode::Plain;
    default: return false;
  }
}

bool isFixed(const ir::Expr& e) {
  switch (e.op) {
    case ir::ExprOp::Param:
    case ir::ExprOp::Rand:
    case ir::ExprOp::Query: return false;
    default: return allFixed(e.args);
  }
}

StringOps planString(const ir::Module& m, const ir::ProgramLayout& layout,
                     const std::function<void(const ir::Expr&, double*, bool)>& store) {
  StringOps plan;
  plan.ops.resize(layout.ops.size());
  // Owners and positions, block by block: the axiom, then each rule's branches.
  std::vector<uint32_t> ownerOfBlock(layout.blocks.size(), UINT32_MAX);
  for (uint32_t ri = 0; ri < m.rules.size(); ++ri)
    for (uint32_t a = 0; a < m.rules[ri].alternatives.size(); ++a)
      ownerOfBlock[layout.alternativeBlock(ri, a)] = m.rules[ri].symbol;
  for (size_t b = 0; b < layout.blocks.size(); ++b) {
    uint32_t children = 0;
    for (size_t k = 0; k < layout.blocks[b]->size(); ++k) {
      const uint32_t id = layout.firstOp[b] + static_cast<uint32_t>(k);
      const ir::Op& op = *layout.ops[id];
      StringOp& so = plan.ops[id];
      so.op = &op;
      so.kind = op.kind;
      so.owner = ownerOfBlock[b];
      if (op.kind == ir::OpKind::Emit) {
        so.childIndex = children++;
        so.argCount = m.symbols[op.index].slotCount;
        so.draws = static_cast<int8_t>(ir::turtleOpNamed(m.symbols[op.index].name));
        so.query = static_cast<int8_t>(queryModuleNamed(m.symbols[op.index].name));
        plan.hasQuery |= so.query >= 0;
        so.contextSymbol = std::find(m.contextIgnored.begin(), m.contextIgnored.end(), op.index) ==
                           m.contextIgnored.end();
      } else if (op.kind == ir::OpKind::Instance) {
        so.argCount = so.owner == UINT32_MAX ? 0 : m.symbols[so.owner].slotCount;
      } else if (op.kind != ir::OpKind::Unsupported) {
        so.argCount = static_cast<uint32_t>(op.args.size() + op.sizes.size());
      }
      if (op.kind == ir::OpKind::Turtle && op.index == static_cast<uint32_t>(ir::TurtleOp::Cut)) plan.hasCut = true;
    }
  }
  // How each symbol rewrites, then each op that writes it.
  std::vector<Rewrite> bySymbol(m.symbols.size(), Rewrite::Keep);
  std::vector<uint32_t> templateOf(m.symbols.size(), 0);
  plan.allTemplates = true;
  plan.hasContext = std::any_of(m.rules.begin(), m.rules.end(),
                                [](const ir::Rule& r) { return !r.left.empty() || !r.right.empty(); });
  for (uint32_t s = 0; s < m.symbols.size(); ++s) {
    if (m.symbols[s].rules.empty()) continue;
    SuccessorTemplate t;
    if (makeTemplate(m, layout, s, store, plan.ops, t)) {
      bySymbol[s] = Rewrite::Template;
      templateOf[s] = static_cast<uint32_t>(plan.templates.size());
      plan.templates.push_back(std::move(t));
    } else {
      bySymbol[s] = Rewrite::General;
      plan.allTemplates = false;
    }
  }
  for (StringOp& so : plan.ops)
    if (so.kind == ir::OpKind::Emit) so.rewrite = bySymbol[so.op->index], so.successor = templateOf[so.op->index];
  return plan;
}

}  // namespace fgsg::backend
