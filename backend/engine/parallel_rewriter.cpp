// The parallel (L-system) rewriter: every module of the string is rewritten at each
// step (ABOP), with left and right context matched over branches, and the final string
// is read by the turtle. Compiled successors append to the string through the same
// entry points (native_bridge.cpp).
#include "backend/engine/derivation.h"

#include "backend/native/query_bridge.h"

#include <algorithm>

namespace fgsg::backend {
namespace {

bool isSymbol(const StringModule& m) { return m.op->kind == ir::OpKind::Emit; }

}  // namespace

void Derivation::runParallel() {
  std::vector<StringModule> str, next;
  std::vector<double> args, nextArgs;
  std::vector<double> none;
  Frame f{none.data(), nullptr, nullptr, 0, 0, this};
  rt::RandomStream rng{rt::rootKey(opt_.seed), 0};
  f.rng = &rng;
  appendModules(0, m_.axiom, f, rt::rootKey(opt_.seed), str, args);
  cutBranches(str);
  bool limitHit = false;
  std::optional<LimitReached> stopped;  // --max-seconds or --max-memory, mid-step
  for (int step = 0; step < steps_ && !limitHit; ++step) {
    next.clear();
    nextArgs.clear();
    for (size_t i = 0; i < str.size(); ++i) {
      const StringModule& mod = str[i];
      if (limitHit || mod.op->kind != ir::OpKind::Emit || m_.symbols[mod.op->index].rules.empty()) {
        copyModule(mod, args, next, nextArgs);
        continue;
      }
      const ir::Symbol& sym = m_.symbols[mod.op->index];
      rt::RandomStream modRng{mod.key, 0};
      const ir::Alternative* alt = chooseInString(sym, str, args, i, modRng, static_cast<uint32_t>(step));
      if (!alt) {
        copyModule(mod, args, next, nextArgs);
        continue;
      }
      ++stats_.rewrites;
      ++ruleUses_[chosenRule_];
      Frame rf{params_.data(), &modRng, nullptr, static_cast<uint32_t>(step), mod.index, this};
      appendModules(blockOf(alt), alt->ops, rf, mod.key, next, nextArgs, mod.op->index);
      // At the limit the rest of this step's string is kept unrewritten, so the
      // turtle still draws the whole (partly older) plant.
      if (next.size() >= opt_.maxShapes) limitHit = true;
      if (!limitHit && (stopped = limitsReached())) limitHit = true;
    }
    cutBranches(next);
    str.swap(next);
    args.swap(nextArgs);
    if (!limitHit && deadline_.expiredNow()) stopped = timeLimit(), limitHit = true;
  }
  interpretString(str, args);
  if (stopped) throw *stopped;
  if (limitHit) shapeLimit(ir::Op{});
}

// ABOP's %: each cut drops the rest of its branch — the modules after it up to the `]`
// that closes the branch (kept), or to the end of the string — and itself.
void Derivation::cutBranches(std::vector<StringModule>& str) {
  const auto turtle = [](const StringModule& m, ir::TurtleOp t) {
    return m.op->kind == ir::OpKind::Turtle && m.op->index == static_cast<uint32_t>(t);
  };
  if (std::none_of(str.begin(), str.end(), [&](const StringModule& m) { return turtle(m, ir::TurtleOp::Cut); }))
    return;
  size_t kept = 0;
  for (size_t i = 0; i < str.size();) {
    if (!turtle(str[i], ir::TurtleOp::Cut)) {
      str[kept++] = str[i++];
      continue;
    }
    int depth = 0;
    for (++i; i < str.size(); ++i) {
      if (str[i].op->kind == ir::OpKind::Push) ++depth;
      if (str[i].op->kind == ir::OpKind::Pop && depth-- == 0) break;
    }
  }
  str.resize(kept);
}

void Derivation::copyModule(const StringModule& mod, const std::vector<double>& args,
                            std::vector<StringModule>& out, std::vector<double>& outArgs) {
  StringModule copy = mod;
  copy.firstArg = static_cast<uint32_t>(outArgs.size());
  outArgs.insert(outArgs.end(), args.begin() + mod.firstArg,
                 args.begin() + mod.firstArg + mod.argCount);
  out.push_back(copy);
}

// Flattens a successor into string modules, evaluating every argument now.
void Derivation::appendModules(uint32_t block, const ir::Block& ops, Frame& f, uint64_t key,
                               std::vector<StringModule>& out, std::vector<double>& outArgs, uint32_t owner) {
  StringTarget target{&out, &outArgs, key, owner};
  if (owner != UINT32_MAX) target.ownerParams = f.params, target.ownerParamCount = m_.symbols[owner].slotCount;
  if (program_) {
    NativeCall call;
    call.engine = this;
    call.f = &f;
    call.string = &target;
    native::QueryBridge bridge(m_, f);
    bridge.attach(call);
    program_->blocks[block](&call, f.params, eval_.attrData());
    if (call.thrown) std::rethrow_exception(call.thrown);
    if (call.errorCode != FGSG_OK) throw bridge.error(call);
    return;
  }
  ArgBuffer buf;
  for (const ir::Op& op : ops) {
    if (op.kind == ir::OpKind::Emit) {
      appendModule(op, evalSlots(op, f, buf), m_.symbols[op.index].slotCount, target);
      continue;
    }
    checkParallelOp(op);
    uint32_t n = 0;
    const double* a = evalOpArgs(op, f, buf, n);
    appendModule(op, a, n, target);
  }
}

// Ops a string can hold: symbols, scope and turtle commands, plain instances.
void Derivation::checkParallelOp(const ir::Op& op) {
  switch (op.kind) {
    case ir::OpKind::Emit:
    case ir::OpKind::Translate:
    case ir::OpKind::Rotate:
    case ir::OpKind::RotateNormal:
    case ir::OpKind::Scale:
    case ir::OpKind::Push:
    case ir::OpKind::Pop:
    case ir::OpKind::Turtle:
    case ir::OpKind::Color: return;
    case ir::OpKind::Instance:
      if (op.mode != ir::InstanceMode::Plain) sequentialOnly(op);
      return;
    case ir::OpKind::Unsupported: unsupported(op);
    case ir::OpKind::Lock:
    case ir::OpKind::Texture:  // textures only leaves' own geometry, which sequential CGA outputs
    case ir::OpKind::Line:
    case ir::OpKind::LineSeg: sequentialOnly(op);
    case ir::OpKind::Center:
      throw DeriveError{op.loc, "R009",
                        "'Center' cannot appear in a parallel (L-system) derivation: it centres the "
                        "scope in the scope its successor started with, which a module of a string "
                        "does not have"};
    default:
      throw DeriveError{op.loc, "R009",
                        "'" + op.name + "' cannot appear in a parallel (L-system) derivation: "
                        "split and component commands need a sequential derivation"};
  }
}

// Appends one module with its evaluated arguments (a symbol's: its parameter slots).
void Derivation::appendModule(const ir::Op& op, const double* args, uint32_t n, StringTarget& t) {
  checkParallelOp(op);
  StringModule mod;
  mod.op = &op;
  mod.owner = t.owner;
  if (op.kind == ir::OpKind::Instance) args = t.ownerParams, n = t.ownerParamCount;  // I() has no arguments of its own
  mod.firstArg = static_cast<uint32_t>(t.args->size());
  mod.argCount = n;
  if (n) t.args->insert(t.args->end(), args, args + n);
  if (op.kind == ir::OpKind::Emit) {
    mod.index = t.child;
    mod.key = rt::childKey(t.key, t.child++);
  }
  t.out->push_back(mod);
}

// Rule choice for one module of the string: context must match, then the guard.
const ir::Alternative* Derivation::chooseInString(const ir::Symbol& sym, const std::vector<StringModule>& str,
                                                  const std::vector<double>& args, size_t at,
                                                  rt::RandomStream& rng, uint32_t step) {
  candidates_.clear();
  double total = 0;
  for (int pass = 0; pass < 2 && candidates_.empty(); ++pass)
  for (uint32_t ri : sym.rules) {
    const ir::Rule& r = m_.rules[ri];
    if (isSpecific(r) != (pass == 0)) continue;
    params_.assign(r.slotCount, 0.0);
    std::copy(args.begin() + str[at].firstArg, args.begin() + str[at].firstArg + sym.slotCount,
              params_.begin());
    if (!matchLeft(r, str, args, at) || !matchRight(r, str, args, at)) continue;
    Frame f{params_.data(), &rng, nullptr, step, str[at].index, this};
    if (r.hasGuard && !guardHolds(ri, f)) continue;
    addCandidates(r, ri, f, total);
  }
  if (candidates_.empty()) return nullptr;
  const Candidate* pick = &pickCandidate(rng, total);
  chosenRule_ = pick->rule;
  // Rebuild the chosen rule's parameter block (another rule may have overwritten it).
  const ir::Rule& r = m_.rules[pick->rule];
  params_.assign(r.slotCount, 0.0);
  std::copy(args.begin() + str[at].firstArg, args.begin() + str[at].firstArg + sym.slotCount,
            params_.begin());
  matchLeft(r, str, args, at);
  matchRight(r, str, args, at);
  return pick->alt;
}

void Derivation::bind(const ir::ContextModule& cm, const StringModule& mod, const std::vector<double>& args) {
  const ir::Symbol& s = m_.symbols[cm.symbol];
  uint32_t src = mod.firstArg;
  for (size_t k = 0; k < cm.paramSlots.size() && k < s.paramTypes.size(); ++k) {
    const int w = ir::slotWidth(s.paramTypes[k]);
    for (int c = 0; c < w; ++c) params_[cm.paramSlots[k] + c] = args[src + c];
    src += w;
  }
}

// ABOP left context: walk left over symbols, skipping commands and whole branches,
// and stepping out of the current branch into its parent.
bool Derivation::matchLeft(const ir::Rule& r, const std::vector<StringModule>& str, const std::vector<double>& args,
                           size_t at) {
  long j = static_cast<long>(at) - 1;
  for (long p = static_cast<long>(r.left.size()) - 1; p >= 0; --p) {
    const ir::ContextModule& cm = r.left[p];
    if (cm.bracket != 0) return false;
    while (j >= 0) {
      const ir::OpKind k = str[j].op->kind;
      if (k == ir::OpKind::Pop) {
        int depth = 0;
        for (; j >= 0; --j) {
          if (str[j].op->kind == ir::OpKind::Pop) ++depth;
          if (str[j].op->kind == ir::OpKind::Push && --depth == 0) break;
        }
        --j;
      } else if (k == ir::OpKind::Emit) {
        break;
      } else {
        --j;
      }
    }
    if (j < 0 || str[j].op->index != cm.symbol) return false;
    bind(cm, str[j], args);
    --j;
  }
  return true;
}

// ABOP right context: a pattern symbol may descend into branches of the string that
// the pattern skips; a pattern ']' skips to the end of the current branch.
bool Derivation::matchRight(const ir::Rule& r, const std::vector<StringModule>& str, const std::vector<double>& args,
                            size_t at) {
  size_t j = at + 1;
  const size_t n = str.size();
  auto skipBranch = [&](size_t from) {  // from is a '['; returns the index after its ']'
    int depth = 0;
    for (size_t x = from; x < n; ++x) {
      if (str[x].op->kind == ir::OpKind::Push) ++depth;
      if (str[x].op->kind == ir::OpKind::Pop && --depth == 0) return x + 1;
    }
    return n;
  };
  for (const auto& cm : r.right) {
    if (cm.bracket == 1) {
      while (j < n && !isSymbol(str[j]) && str[j].op->kind != ir::OpKind::Push &&
             str[j].op->kind != ir::OpKind::Pop)
        ++j;
      if (j >= n || str[j].op->kind != ir::OpKind::Push) return false;
      ++j;
    } else if (cm.bracket == -1) {
      int depth = 0;
      while (j < n) {
        if (str[j].op->kind == ir::OpKind::Push) ++depth;
        if (str[j].op->kind == ir::OpKind::Pop) {
          if (depth == 0) break;
          --depth;
        }
        ++j;
      }
      if (j >= n) return false;
      ++j;
    } else {
      while (j < n && !isSymbol(str[j])) {
        if (str[j].op->kind == ir::OpKind::Push)
          j = skipBranch(j);
        else if (str[j].op->kind == ir::OpKind::Pop)
          return false;
        else
          ++j;
      }
      if (j >= n || str[j].op->index != cm.symbol) return false;
      bind(cm, str[j], args);
      ++j;
    }
  }
  return true;
}

// The turtle interpretation of the final string: commands act on one scope.
void Derivation::interpretString(const std::vector<StringModule>& str, const std::vector<double>& args) {
  streetDirection_ = rt::Vec3::UnitZ();
  State st;
  st.width = m_.turtle.width;
  st.stackBase = stack_.size();
  stats_.stringLength = str.size();
  for (const StringModule& mod : str) {
    const ir::Op& op = *mod.op;
    const double* a = args.data() + mod.firstArg;
    switch (op.kind) {
      case ir::OpKind::Emit: {
        ++stats_.terminals;
        ++stats_.shapesCreated;
        // ABOP: F and f are rewritten by rules and still draw and move when the turtle
        // reads the final string; their first parameter is the length.
        const std::string& name = m_.symbols[op.index].name;
        if (name == "F" || name == "f") {
          const ir::TurtleOp t = name == "F" ? ir::TurtleOp::Forward : ir::TurtleOp::Move;
          turtle_.command(st, t, a, std::min<uint32_t>(mod.argCount, 1), op.loc);
        }
        break;
      }
      case ir::OpKind::Turtle:
        turtle_.command(st, static_cast<ir::TurtleOp>(op.index), a, mod.argCount, op.loc);
        break;
      case ir::OpKind::Instance:
        placeInstance(op.index, st.scope, mod.owner == UINT32_MAX ? axiomSymbol_ : mod.owner, a, mod.argCount,
                      op.loc);
        break;
      default: scope_.command(st, op, a); break;
    }
  }
}

void Derivation::sequentialOnly(const ir::Op& op) {
  throw DeriveError{op.loc, "R009",
                    "'" + op.name + "' cannot appear in a parallel (L-system) derivation: a "
                    "collision or a line ending culls the rest of one production, which needs a "
                    "sequential derivation"};
}

}  // namespace fgsg::backend
