// The parallel (L-system) rewriter: every module of the string is rewritten at each
// step (ABOP), with left and right context matched over branches, and the final string
// is read by the turtle. Compiled successors append to the string through the same
// entry points (native_bridge.cpp).
#include "backend/engine/derivation.h"
#include "runtime/page_prefault.h"

#include "backend/native/query_bridge.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace fgsg::backend {
namespace {

// Template steps of strings this long or longer are rewritten in chunks of kChunk
// modules, concurrently; shorter ones in one pass on this thread, without TBB: on a
// machine whose cores are shared, a worker descheduled in the middle of its chunk holds up
// the whole step for a scheduler tick (4 ms), longer than such a step takes alone.
constexpr size_t kConcurrentFrom = size_t(1) << 18;
constexpr size_t kChunk = size_t(1) << 15;

// Writes template t's modules at w (keys made from the rewritten module's `key`) and its
// arguments at a, which is argument number `base` of the string.
void writeTemplate(const SuccessorTemplate& t, uint64_t key, StringModule* w, double* a, uint32_t base) {
  for (size_t k = 0; k < t.ops.size(); ++k)
    w[k] = {t.ops[k], base + t.firstArg[k], rt::keyWithSalt(key, t.keySalt[k]) & t.keyMask[k]};
  if (!t.args.empty()) std::memcpy(a, t.args.data(), t.args.size() * sizeof(double));
}

// Before a step writes `next` from `str`: room, in one allocation, for the longest string
// `next` will hold — this step's and every other one after it, `stepsAfter` being left
// after this one — predicted from the last step's growth and at most `maxModules`. So a
// growing string is not copied into a fresh, page-faulting buffer at every step (the
// prediction is only room: a longer string grows the buffer as before, a shorter one
// leaves pages that were never written, which cost nothing).
void reserveForGrowth(ModuleString& next, const ModuleString& str, double growth, int stepsAfter, size_t maxModules) {
  if (!(growth > 1.0) || str.size() == 0) return;
  const double modules = std::min(double(str.size()) * std::pow(growth, 1 + 2 * (stepsAfter / 2)), double(maxModules));
  if (modules <= double(next.modules.capacity())) return;
  next.modules.reserve(size_t(modules));
  next.args.reserve(size_t(modules / double(str.size()) * double(str.args.size())));
}

}  // namespace

void Derivation::runParallel() {
  if (!program_) layout_ = ir::layoutProgram(m_);
  plan_ = planString(m_, layout_, [&](const ir::Expr& e, double* out, bool asSlots) {
    Frame none{nullptr, nullptr, nullptr, 0, 0, this};
    if (asSlots)
      eval_.store(e, none, out);
    else
      out[0] = eval_.num(e, none);
  });
  ModuleString str, next;
  std::vector<double> none;
  Frame f{none.data(), nullptr, nullptr, 0, 0, this, nullptr};
  rt::RandomStream rng{rt::rootKey(opt_.seed), 0};
  f.rng = &rng;
  appendModules(0, m_.axiom, f, rt::rootKey(opt_.seed), str);
  cutBranches(str);
  answerQueries(str);
  bool limitHit = false;
  std::optional<LimitReached> stopped;  // --max-seconds or --max-memory, mid-step
  const auto rewriteStart = std::chrono::steady_clock::now();
  double growth = 0;  // the last step's: modules written over modules read
  for (int step = 0; step < steps_ && !limitHit; ++step) {
    next.clear();
    reserveForGrowth(next, str, growth, steps_ - 1 - step, opt_.maxShapes);
    if (!rewriteTemplates(str, next)) {
      next.clear();
      if (plan_.hasContext) linkBrackets(str);
      for (size_t i = 0; i < str.size(); ++i) {
        const StringModule& mod = str.modules[i];
        const StringOp& so = plan_[mod.op];
        if (limitHit || so.rewrite == Rewrite::Keep) {
          copyModule(str, i, next);
          continue;
        }
        if (so.rewrite == Rewrite::Template) {
          appendTemplate(plan_.templates[so.successor], mod.key, next);
        } else {
          const ir::Symbol& sym = m_.symbols[so.op->index];
          rt::RandomStream modRng{mod.key, 0};
          const ir::Alternative* alt =
              chooseInString(sym, ir::RuleSection::Production, str, i, modRng, static_cast<uint32_t>(step));
          if (!alt) {
            copyModule(str, i, next);
            continue;
          }
          ++stats_.rewrites;
          ++ruleUses_[chosenRule_];
          Frame rf{params_.data(), &modRng, nullptr, static_cast<uint32_t>(step), so.childIndex, this};
          appendModules(blockOf(alt), alt->ops, rf, mod.key, next, so.op->index);
        }
        // At the limit the rest of this step's string is kept unrewritten, so the
        // turtle still draws the whole (partly older) plant.
        if (next.size() >= opt_.maxShapes) limitHit = true;
        if (!limitHit && (stopped = limitsReached())) limitHit = true;
      }
    }
    cutBranches(next);
    growth = str.size() ? double(next.size()) / double(str.size()) : 0;
    str.swap(next);
    // lpfg's and L-Py's decomposition: its result is the string (rule_sections.cpp).
    if (!limitHit && rewriteSection(ir::RuleSection::Decomposition, str, next, static_cast<uint32_t>(step), limitHit,
                                    stopped))
      str.swap(next);
    answerQueries(str);  // ?P ?H ?U ?L for the next step's contexts and guards
    if (!limitHit && deadline_.expiredNow()) stopped = timeLimit(), limitHit = true;
  }
  stats_.rewriteSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - rewriteStart).count();
  // The homomorphism: the turtle reads its result; the derived string stays as it is.
  if (!limitHit && rewriteSection(ir::RuleSection::Homomorphism, str, next, static_cast<uint32_t>(steps_), limitHit,
                                  stopped)) {
    interpretString(next);
    stats_.stringLength = str.size();
    stats_.stringBytes = str.size() * sizeof(StringModule) + str.args.size() * sizeof(double);
  } else {
    interpretString(str);
  }
  if (stopped) throw *stopped;
  if (limitHit) shapeLimit(ir::Op{});
}

// A symbol's fixed successor, appended: its modules with keys made from `key`, and its
// arguments.
void Derivation::appendTemplate(const SuccessorTemplate& t, uint64_t key, ModuleString& out) {
  ++stats_.rewrites;
  ++ruleUses_[t.rule];
  const uint32_t base = static_cast<uint32_t>(out.args.size());
  writeTemplate(t, key, out.modules.extend(t.ops.size()), out.args.extend(t.args.size()), base);
}

// A step of a grammar whose every rewriting symbol has a template. A long string is
// rewritten over chunks on all cores: the sizes each chunk writes are counted first, so
// every chunk writes its part of `next` in place, and the result is the one-thread
// result. Returns false (nothing written) where the general loop must do the step: a
// limit reached during it.
bool Derivation::rewriteTemplates(const ModuleString& str, ModuleString& next) {
  if (!plan_.allTemplates) return false;
  if (str.size() < kConcurrentFrom) return rewriteTemplatesOnThisThread(str, next);
  const size_t chunks = (str.size() + kChunk - 1) / kChunk;
  const size_t templates = plan_.templates.size();
  // Per chunk: modules and arguments written, then per template its uses.
  std::vector<uint64_t> counts(chunks * (2 + templates), 0);
  tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
    uint64_t* n = &counts[c * (2 + templates)];
    const size_t end = std::min(str.size(), (c + 1) * kChunk);
    for (size_t i = c * kChunk; i < end; ++i) {
      const StringOp& so = plan_[str.modules[i].op];
      if (so.rewrite == Rewrite::Template) {
        const SuccessorTemplate& t = plan_.templates[so.successor];
        n[0] += t.ops.size(), n[1] += t.args.size(), ++n[2 + so.successor];
      } else {
        n[0] += 1, n[1] += so.argCount;
      }
    }
  });
  std::vector<uint64_t> moduleAt(chunks + 1, 0), argAt(chunks + 1, 0);
  for (size_t c = 0; c < chunks; ++c) {
    moduleAt[c + 1] = moduleAt[c] + counts[c * (2 + templates)];
    argAt[c + 1] = argAt[c] + counts[c * (2 + templates) + 1];
  }
  // The one-thread loop stops at these limits mid-step, and knows how.
  if (moduleAt[chunks] >= opt_.maxShapes || argAt[chunks] >= UINT32_MAX || limitsReached()) return false;
  next.modules.resizeForOverwrite(moduleAt[chunks]);
  next.args.resizeForOverwrite(argAt[chunks]);
  tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
    StringModule* w = next.modules.data() + moduleAt[c];
    double* a = next.args.data() + argAt[c];
    const size_t end = std::min(str.size(), (c + 1) * kChunk);
    for (size_t i = c * kChunk; i < end; ++i) {
      const StringModule& mod = str.modules[i];
      const StringOp& so = plan_[mod.op];
      const uint32_t base = static_cast<uint32_t>(a - next.args.data());
      if (so.rewrite == Rewrite::Template) {
        const SuccessorTemplate& t = plan_.templates[so.successor];
        writeTemplate(t, mod.key, w, a, base);
        w += t.ops.size();
        a += t.args.size();
      } else {
        *w++ = {mod.op, base, mod.key};
        if (so.argCount) std::memcpy(a, str.args.data() + mod.firstArg, so.argCount * sizeof(double));
        a += so.argCount;
      }
    }
  });
  for (size_t c = 0; c < chunks; ++c)
    for (size_t t = 0; t < templates; ++t) {
      const uint64_t uses = counts[c * (2 + templates) + 2 + t];
      stats_.rewrites += uses;
      ruleUses_[plan_.templates[t].rule] += uses;
    }
  return true;
}

// The same step in one pass, as the general loop does it but without its per-module
// checks: the limits are asked once, before, and a string reaching --max-shapes is
// dropped for the general loop to redo, stopping where it stops.
bool Derivation::rewriteTemplatesOnThisThread(const ModuleString& str, ModuleString& next) {
  if (limitsReached()) return false;
  std::vector<uint64_t> uses(plan_.templates.size(), 0);
  for (size_t i = 0; i < str.size(); ++i) {
    const StringModule& mod = str.modules[i];
    const StringOp& so = plan_[mod.op];
    if (so.rewrite == Rewrite::Template) {
      const SuccessorTemplate& t = plan_.templates[so.successor];
      const uint32_t base = static_cast<uint32_t>(next.args.size());
      writeTemplate(t, mod.key, next.modules.extend(t.ops.size()), next.args.extend(t.args.size()), base);
      ++uses[so.successor];
    } else {
      copyModule(str, i, next);
    }
    if (next.size() >= opt_.maxShapes || next.args.size() >= UINT32_MAX) {
      next.clear();
      return false;
    }
  }
  for (size_t t = 0; t < uses.size(); ++t) {
    stats_.rewrites += uses[t];
    ruleUses_[plan_.templates[t].rule] += uses[t];
  }
  return true;
}

void Derivation::linkBrackets(const ModuleString& str) {
  bracketPartner_.assign(str.size(), UINT32_MAX);
  std::vector<uint32_t> open;
  for (uint32_t i = 0; i < str.size(); ++i) {
    const ir::OpKind k = plan_[str.modules[i].op].kind;
    if (k == ir::OpKind::Push) open.push_back(i);
    if (k == ir::OpKind::Pop && !open.empty()) {
      bracketPartner_[i] = open.back();
      bracketPartner_[open.back()] = i;
      open.pop_back();
    }
  }
}

// ABOP's %: each cut drops the rest of its branch — the modules after it up to the `]`
// that closes the branch (kept), or to the end of the string — and itself.
void Derivation::cutBranches(ModuleString& str) {
  if (!plan_.hasCut) return;
  const auto kind = [&](size_t i) { return plan_[str.modules[i].op].kind; };
  const auto isCut = [&](size_t i) {
    const StringOp& so = plan_[str.modules[i].op];
    return so.kind == ir::OpKind::Turtle && so.op->index == static_cast<uint32_t>(ir::TurtleOp::Cut);
  };
  size_t kept = 0;
  for (size_t i = 0; i < str.size();) {
    if (!isCut(i)) {
      str.modules[kept++] = str.modules[i++];
      continue;
    }
    int depth = 0;
    for (++i; i < str.size(); ++i) {
      if (kind(i) == ir::OpKind::Push) ++depth;
      if (kind(i) == ir::OpKind::Pop && depth-- == 0) break;
    }
  }
  str.modules.truncate(kept);
}

void Derivation::copyModule(const ModuleString& str, size_t i, ModuleString& out) {
  const StringModule& mod = str.modules[i];
  out.append(mod.op, mod.key, str.args.data() + mod.firstArg, plan_[mod.op].argCount);
}

// Flattens a successor into string modules, evaluating every argument now.
void Derivation::appendModules(uint32_t block, const ir::Block& ops, Frame& f, uint64_t key, ModuleString& out,
                               uint32_t owner) {
  StringTarget target{&out, key, owner};
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
  const uint32_t first = layout_.firstOp[block];
  for (size_t k = 0; k < ops.size(); ++k) {
    const ir::Op& op = ops[k];
    const uint32_t id = first + static_cast<uint32_t>(k);
    if (op.kind == ir::OpKind::Emit) {
      appendModule(id, evalSlots(op, f, buf), m_.symbols[op.index].slotCount, target);
      continue;
    }
    checkParallelOp(op);
    uint32_t n = 0;
    const double* a = evalOpArgs(op, f, buf, n);
    appendModule(id, a, n, target);
  }
}

// Ops a string can hold (stringHolds); the others are refused, saying why.
void Derivation::checkParallelOp(const ir::Op& op) {
  if (stringHolds(op)) return;
  switch (op.kind) {
    case ir::OpKind::Instance: sequentialOnly(op);  // IC, IM
    case ir::OpKind::Unsupported: unsupported(op);
    case ir::OpKind::Lock:
    case ir::OpKind::Texture:  // textures only leaves' own geometry, which sequential CGA outputs
    case ir::OpKind::Material:
    case ir::OpKind::Uv:
    case ir::OpKind::Line:
    case ir::OpKind::LineSeg: sequentialOnly(op);
    case ir::OpKind::Report:
    case ir::OpKind::Print:
      throw DeriveError{op.loc, "R009",
                        "'" + op.name + "' cannot appear in a parallel (L-system) derivation: reports and "
                        "prints run as a shape is derived, in a sequential (CGA) derivation"};
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

// Appends one module (op id `op`) with its evaluated arguments (a symbol's: its
// parameter slots).
void Derivation::appendModule(uint32_t op, const double* args, uint32_t n, StringTarget& t) {
  const StringOp& so = plan_[op];
  checkParallelOp(*so.op);
  if (so.kind == ir::OpKind::Instance) args = t.ownerParams, n = t.ownerParamCount;  // I() has no arguments of its own
  if (n != so.argCount)
    throw DeriveError{so.op->loc, "R900",
                      "internal: '" + so.op->name + "' appended with " + std::to_string(n) + " arguments, not " +
                          std::to_string(so.argCount)};
  t.out->append(op, so.kind == ir::OpKind::Emit ? rt::childKey(t.key, so.childIndex) : 0, args, n);
}

// Rule choice for one module of the string: context must match, then the guard.
const ir::Alternative* Derivation::chooseInString(const ir::Symbol& sym, ir::RuleSection section,
                                                  const ModuleString& str, size_t at, rt::RandomStream& rng,
                                                  uint32_t step) {
  candidates_.clear();
  double total = 0;
  const double* own = str.args.data() + str.modules[at].firstArg;
  const uint32_t index = plan_[str.modules[at].op].childIndex;
  const bool decomposition = section == ir::RuleSection::Decomposition;
  const bool homomorphism = section == ir::RuleSection::Homomorphism;
  const std::vector<uint32_t>& rules = decomposition ? sym.decompositions : homomorphism ? sym.homomorphisms : sym.rules;
  const bool firstApplicable = decomposition    ? sym.firstApplicableDecomposition
                               : homomorphism ? sym.firstApplicableHomomorphism
                                              : sym.firstApplicable;
  for (int pass = 0; pass < 2 && candidates_.empty(); ++pass) {
    uint32_t taken = UINT32_MAX;
    for (uint32_t ri : rules) {
      const ir::Rule& r = m_.rules[ri];
      if (isSpecific(r) != (pass == 0)) continue;
      params_.assign(r.slotCount, 0.0);
      std::copy(own, own + sym.slotCount, params_.begin());
      if (!matchLeft(r, str, at) || !matchRight(r, str, at)) continue;
      Frame f{params_.data(), &rng, nullptr, step, index, this, nullptr};
      if (r.hasGuard && !guardHolds(ri, f)) continue;
      if (pass == 0 && !takesPart(firstApplicable, ri, taken)) continue;
      addCandidates(r, ri, f, total);
    }
  }
  if (candidates_.empty()) return nullptr;
  const Candidate* pick = &pickCandidate(rng, total);
  chosenRule_ = pick->rule;
  // Rebuild the chosen rule's parameter block (another rule may have overwritten it).
  const ir::Rule& r = m_.rules[pick->rule];
  params_.assign(r.slotCount, 0.0);
  std::copy(own, own + sym.slotCount, params_.begin());
  matchLeft(r, str, at);
  matchRight(r, str, at);
  return pick->alt;
}

void Derivation::bind(const ir::ContextModule& cm, const ModuleString& str, size_t at) {
  const ir::Symbol& s = m_.symbols[cm.symbol];
  const double* src = str.args.data() + str.modules[at].firstArg;
  for (size_t k = 0; k < cm.paramSlots.size() && k < s.paramTypes.size(); ++k) {
    const int w = ir::slotWidth(s.paramTypes[k]);
    for (int c = 0; c < w; ++c) params_[cm.paramSlots[k] + c] = src[c];
    src += w;
  }
}

// ABOP left context: walk left over symbols, skipping commands, #ignore'd symbols and
// whole branches, and stepping out of the current branch into its parent.
bool Derivation::matchLeft(const ir::Rule& r, const ModuleString& str, size_t at) {
  const auto kind = [&](long j) { return plan_[str.modules[j].op].kind; };
  const auto sees = [&](long j) { return plan_[str.modules[j].op].contextSymbol; };
  long j = static_cast<long>(at) - 1;
  for (long p = static_cast<long>(r.left.size()) - 1; p >= 0; --p) {
    const ir::ContextModule& cm = r.left[p];
    if (cm.bracket != 0) return false;
    while (j >= 0) {
      const ir::OpKind k = kind(j);
      if (k == ir::OpKind::Pop) {  // step over the whole branch, to before its '['
        const uint32_t open = bracketPartner_[size_t(j)];
        j = open == UINT32_MAX ? -1 : long(open) - 1;
      } else if (k == ir::OpKind::Emit && sees(j)) {
        break;
      } else {
        --j;
      }
    }
    if (j < 0 || plan_[str.modules[j].op].op->index != cm.symbol) return false;
    bind(cm, str, j);
    --j;
  }
  return true;
}

// ABOP right context: a pattern symbol may descend into branches of the string that
// the pattern skips; a pattern ']' skips to the end of the current branch. Commands and
// #ignore'd symbols are stepped over.
bool Derivation::matchRight(const ir::Rule& r, const ModuleString& str, size_t at) {
  const auto kind = [&](size_t j) { return plan_[str.modules[j].op].kind; };
  const auto sees = [&](size_t j) { return kind(j) == ir::OpKind::Emit && plan_[str.modules[j].op].contextSymbol; };
  size_t j = at + 1;
  const size_t n = str.size();
  auto skipBranch = [&](size_t from) {  // from is a '['; returns the index after its ']'
    const uint32_t close = bracketPartner_[from];
    return close == UINT32_MAX ? n : size_t(close) + 1;
  };
  for (const auto& cm : r.right) {
    if (cm.bracket == 1) {
      while (j < n && !sees(j) && kind(j) != ir::OpKind::Push && kind(j) != ir::OpKind::Pop) ++j;
      if (j >= n || kind(j) != ir::OpKind::Push) return false;
      ++j;
    } else if (cm.bracket == -1) {
      int depth = 0;
      while (j < n) {
        if (kind(j) == ir::OpKind::Push) ++depth;
        if (kind(j) == ir::OpKind::Pop) {
          if (depth == 0) break;
          --depth;
        }
        ++j;
      }
      if (j >= n) return false;
      ++j;
    } else {
      while (j < n && !sees(j)) {
        if (kind(j) == ir::OpKind::Push)
          j = skipBranch(j);
        else if (kind(j) == ir::OpKind::Pop)
          return false;
        else
          ++j;
      }
      if (j >= n || plan_[str.modules[j].op].op->index != cm.symbol) return false;
      bind(cm, str, j);
      ++j;
    }
  }
  return true;
}

// The turtle interpretation of the final string: commands act on one scope.
void Derivation::interpretString(const ModuleString& str) {
  placingDepth_ = UINT32_MAX;  // modules do not carry the step that wrote them
  streetDirection_ = rt::Vec3::UnitZ();
  State st;
  st.width = m_.turtle.width;
  st.stackBase = stack_.size();
  stats_.stringLength = str.size();
  stats_.stringBytes = str.size() * sizeof(StringModule) + str.args.size() * sizeof(double);
  // Room for every segment at once: a million instances grown by doubling copy each one
  // about twice more.
  size_t segments = 0;
  for (const StringModule& mod : str.modules) {
    const StringOp& so = plan_[mod.op];
    segments += so.draws == static_cast<int8_t>(ir::TurtleOp::Forward) ||
                (so.kind == ir::OpKind::Turtle && so.op->index == static_cast<uint32_t>(ir::TurtleOp::Forward)) ||
                so.kind == ir::OpKind::Instance;
  }
  out_.instances.reserve(out_.instances.size() + segments);
  // The kernel zeroes the new pages on a second thread while this one fills them.
  const rt::PrefaultAhead prefault(out_.instances.data() + out_.instances.size(),
                                   (out_.instances.capacity() - out_.instances.size()) * sizeof(rt::Instance));
  for (const StringModule& mod : str.modules) {
    const StringOp& so = plan_[mod.op];
    const ir::Op& op = *so.op;
    const double* a = str.args.data() + mod.firstArg;
    switch (so.kind) {
      case ir::OpKind::Emit:
        ++stats_.terminals;
        ++stats_.shapesCreated;
        // ABOP: F, f and turtle symbols with rules (`+ -> -`) are rewritten and still act
        // when the turtle reads the final string, with their first parameter.
        if (so.draws >= 0)
          turtle_.command(st, static_cast<ir::TurtleOp>(so.draws), a, std::min<uint32_t>(so.argCount, 1), op.loc);
        break;
      case ir::OpKind::Turtle:
        turtle_.command(st, op, a, so.argCount);
        break;
      case ir::OpKind::Instance:
        placeInstance(op.index, insertFitted(op, st.scope), so.owner == UINT32_MAX ? axiomSymbol_ : so.owner, a,
                      so.argCount, op.loc, op.zUp);
        if (op.insertFit != ir::InsertFit::AlignSizeAndPosition) st.scope = insertFitted(op, st.scope);  // as CollisionCommands::apply
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
