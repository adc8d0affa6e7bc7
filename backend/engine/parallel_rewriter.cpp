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
#include <optional>

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

// The steps of an all-template grammar whose random keys nothing reads and whose string
// holds no arguments (the plain L-systems of ABOP ch. 1: `X -> F [ + X ] F [ - X ] + X`).
// Keys are read only by rule choice, successors that compute (neither in such a grammar)
// and decomposition and homomorphism rules (none); without arguments every op becomes
// the same modules wherever it is: its image, written whole (key 0, first argument 0).
// And what a step makes is known without reading the string: how many modules of each op
// the next string holds is this one's tally through the images, so a step is one pass
// that copies images, and every step's size is known before the first, so the two
// buffers are sized once, exactly, and the same sizes find the same blocks kept from the
// last derivation (StringStoragePool). Keys stay 0 and differ from the keyed steps' ones:
// that is the reason they must be unread.
class KeylessTemplateImages {
 public:
  static bool applies(const ir::Module& m, const StringOps& plan, const ModuleString& axiom) {
    if (!plan.allTemplates || plan.hasCut || plan.hasQuery || axiom.args.size() != 0) return false;
    for (const SuccessorTemplate& t : plan.templates)
      if (!t.args.empty()) return false;
    for (const ir::Symbol& s : m.symbols)
      if (!s.decompositions.empty() || !s.homomorphisms.empty()) return false;
    return true;
  }

  KeylessTemplateImages(const StringOps& plan, const ModuleString& axiom) : plan_(plan), tally_(plan.ops.size(), 0) {
    images_.resize(plan.ops.size());
    for (uint32_t op = 0; op < plan.ops.size(); ++op) {
      const StringOp& so = plan.ops[op];
      Image& im = images_[op];
      im.at = static_cast<uint32_t>(modules_.size());
      if (so.rewrite == Rewrite::Template) {
        for (uint32_t child : plan.templates[so.successor].ops) modules_.push_back({child, 0, 0});
      } else {
        modules_.push_back({op, 0, 0});
      }
      im.len = static_cast<uint32_t>(modules_.size()) - im.at;
      im.copied = std::max<uint32_t>(2, im.len + im.len % 2);  // copied two modules at a time
      modules_.resize(im.at + im.copied);
    }
    for (const StringModule& mod : axiom.modules) ++tally_[mod.op];
  }

  // Sizes `str` (holding the string before `steps` steps) and `next` once for all of them:
  // each buffer the longest string it will hold, up to `maxModules`. Only the first
  // kLookahead steps are looked at (a step past them that needs more grows its buffer):
  // this runs before the first step, where --max-seconds cannot stop it.
  void reserve(ModuleString& str, ModuleString& next, int steps, uint64_t maxModules) const {
    constexpr int kLookahead = 64;
    std::vector<uint64_t> tally = tally_, after(tally.size());
    uint64_t most[2] = {0, 0};
    for (int step = 0; step < std::min(steps, kLookahead); ++step) {
      advance(tally, after, maxModules);
      tally.swap(after);
      most[step % 2] = std::max(most[step % 2], std::min(total(tally), maxModules));
    }
    next.modules.reserve(most[0]);
    str.modules.reserve(std::max<uint64_t>(most[1], str.size()));
  }

  // The modules of the next string (at least `maxModules` where it has that many).
  uint64_t nextModules(uint64_t maxModules) const {
    std::vector<uint64_t> after(tally_.size());
    advance(tally_, after, maxModules);
    return total(after);
  }

  // The step's rewrites, in all and per rule, then the tally moved on to the next string.
  void finishStep(uint64_t& rewrites, std::vector<uint64_t>& ruleUses) {
    for (uint32_t op = 0; op < tally_.size(); ++op) {
      const StringOp& so = plan_.ops[op];
      if (so.rewrite != Rewrite::Template || !tally_[op]) continue;
      rewrites += tally_[op];
      ruleUses[plan_.templates[so.successor].rule] += tally_[op];
    }
    std::vector<uint64_t> after(tally_.size());
    advance(tally_, after, UINT64_MAX / 2);
    tally_.swap(after);
  }

  // Writes the images of `n` modules at w, up to `end` (where they end): two modules at a
  // time, the second of which may be the next image's place, and never past `end`.
  void writeImages(const StringModule* in, size_t n, StringModule* __restrict w, const StringModule* end) const {
    const Image* images = images_.data();
    const StringModule* modules = modules_.data();
    for (size_t i = 0; i < n; ++i) {
      const Image im = images[in[i].op];
      const StringModule* from = modules + im.at;
      if (w + im.copied <= end) {
        std::memcpy(w, from, 2 * sizeof(StringModule));
        for (uint32_t k = 2; k < im.copied; k += 2) std::memcpy(w + k, from + k, 2 * sizeof(StringModule));
      } else {
        std::memcpy(w, from, im.len * sizeof(StringModule));
      }
      w += im.len;
    }
  }

 private:
  struct Image {
    uint32_t at = 0, len = 0;  // its modules in modules_
    uint32_t copied = 2;       // len rounded up to an even count, at least 2 (modules_ holds them)
  };

  // The next string's tally from this one's, counts held at most at `cap`.
  void advance(const std::vector<uint64_t>& tally, std::vector<uint64_t>& after, uint64_t cap) const {
    std::fill(after.begin(), after.end(), 0);
    for (uint32_t op = 0; op < tally.size(); ++op) {
      if (!tally[op]) continue;
      const Image& im = images_[op];
      for (uint32_t k = 0; k < im.len; ++k) {
        uint64_t& n = after[modules_[im.at + k].op];
        n = std::min(saturatingSum(n, tally[op]), cap);
      }
    }
  }
  static uint64_t total(const std::vector<uint64_t>& tally) {
    uint64_t sum = 0;
    for (uint64_t n : tally) sum = std::min(saturatingSum(sum, n), UINT64_MAX / 2);
    return sum;
  }
  // Counts are held at a cap that may be near UINT64_MAX (--max-shapes 2^63): a sum past
  // it must stay at the cap, not wrap to a small count.
  static uint64_t saturatingSum(uint64_t a, uint64_t b) { return a > UINT64_MAX - b ? UINT64_MAX : a + b; }

  const StringOps& plan_;
  std::vector<Image> images_;          // by op id
  std::vector<StringModule> modules_;  // the images, one after another
  std::vector<uint64_t> tally_;        // modules of each op in the current string
};

// One step of a grammar whose every rewriting symbol has a template, in two passes over
// chunks of kChunk modules: count what each chunk writes, so that the next string is sized
// once, exactly, and every chunk writes its own part of it in place (concurrently where
// the string is long), then write. Both passes read one flat table by op id (what a module
// of that op becomes) instead of the plan's StringOp and SuccessorTemplate vectors, and
// keep their running counts and pointers in registers: this step is most of the rewriting
// time of a large template L-system, and its floor is the memory bandwidth.
class TemplateStep {
 public:
  // Makes the table and counts (pass 1). With `images`, the chunks are written as their
  // images (KeylessTemplateImages) in pass 2.
  TemplateStep(const StringOps& plan, const ModuleString& str, bool concurrent,
               const KeylessTemplateImages* images = nullptr)
      : plan_(plan), str_(str), concurrent_(concurrent), images_(images), templates_(plan.templates.size()),
        chunks_((str.size() + kChunk - 1) / kChunk) {
    perOp_.resize(plan.ops.size());
    for (size_t op = 0; op < plan.ops.size(); ++op) {
      const StringOp& so = plan.ops[op];
      PerOp& p = perOp_[op];
      p.args = so.argCount;
      if (so.rewrite != Rewrite::Template) continue;
      const SuccessorTemplate& t = plan.templates[so.successor];
      p.modules = static_cast<uint32_t>(t.ops.size());
      p.args = static_cast<uint32_t>(t.args.size());
      p.successor = so.successor;
      p.first = static_cast<uint32_t>(entries_.size());
      p.argData = t.args.data();
      for (size_t k = 0; k < t.ops.size(); ++k)
        entries_.push_back({t.ops[k], t.firstArg[k], t.keySalt[k], t.keyMask[k]});
    }
    counts_.assign(chunks_ * (2 + templates_), 0);
    count();
  }

  uint64_t modules() const { return moduleAt_[chunks_]; }
  uint64_t args() const { return argAt_[chunks_]; }
  // Pass 2: `next` (empty) sized to what pass 1 counted, and written.
  void fill(ModuleString& next) const {
    next.modules.resizeForOverwrite(modules());
    next.args.resizeForOverwrite(args());
    StringModule* out = next.modules.data();
    double* outArgs = next.args.data();
    forEachChunk([&](size_t c) {
      const size_t begin = c * kChunk, end = std::min(str_.size(), begin + kChunk);
      if (images_)
        return images_->writeImages(str_.modules.data() + begin, end - begin, out + moduleAt_[c], out + moduleAt_[c + 1]);
      fillChunk(str_.modules.data() + begin, end - begin, out + moduleAt_[c], outArgs + argAt_[c],
                static_cast<uint32_t>(argAt_[c]));
    });
  }
  // The step's rewrites, in all and per rule.
  void addUses(uint64_t& rewrites, std::vector<uint64_t>& ruleUses) const {
    for (size_t t = 0; t < templates_; ++t) {
      uint64_t uses = 0;
      for (size_t c = 0; c < chunks_; ++c) uses += counts_[c * (2 + templates_) + 2 + t];
      rewrites += uses;
      ruleUses[plan_.templates[t].rule] += uses;
    }
  }

 private:
  struct Entry {  // one module of a template
    uint32_t op, firstArg;
    uint64_t salt, mask;
  };
  struct PerOp {  // what a module of one op becomes
    uint32_t modules = 1, args = 0;
    uint32_t first = UINT32_MAX;       // its template's first entry; UINT32_MAX: the module is kept
    uint32_t successor = UINT32_MAX;   // its template's index in StringOps::templates
    const double* argData = nullptr;   // its template's arguments
  };

  // Pass 1: per chunk, the modules and arguments it writes and its uses of each template.
  void count() {
    forEachChunk([&](size_t c) {
      const size_t begin = c * kChunk, end = std::min(str_.size(), begin + kChunk);
      // Per op, its modules in the chunk: four tables, a module counted in the one of its
      // position mod 4, so that a run of one op is not one chain of increments of a single
      // counter (each waiting for the last).
      const size_t opCount = perOp_.size();
      std::vector<uint32_t> tally(4 * opCount, 0);
      uint32_t* t0 = tally.data();
      uint32_t* t1 = t0 + opCount;
      uint32_t* t2 = t1 + opCount;
      uint32_t* t3 = t2 + opCount;
      const StringModule* m = str_.modules.data();
      size_t i = begin;
      for (; i + 4 <= end; i += 4) ++t0[m[i].op], ++t1[m[i + 1].op], ++t2[m[i + 2].op], ++t3[m[i + 3].op];
      for (; i < end; ++i) ++t0[m[i].op];
      uint64_t* n = &counts_[c * (2 + templates_)];
      for (size_t op = 0; op < opCount; ++op) {
        const uint64_t k = uint64_t(t0[op]) + t1[op] + t2[op] + t3[op];
        if (!k) continue;
        const PerOp& p = perOp_[op];
        n[0] += k * p.modules;
        n[1] += k * p.args;
        if (p.successor != UINT32_MAX) n[2 + p.successor] += k;
      }
    });
    moduleAt_.assign(chunks_ + 1, 0);
    argAt_.assign(chunks_ + 1, 0);
    for (size_t c = 0; c < chunks_; ++c) {
      moduleAt_[c + 1] = moduleAt_[c] + counts_[c * (2 + templates_)];
      argAt_[c + 1] = argAt_[c] + counts_[c * (2 + templates_) + 1];
    }
  }
  template <class Body>
  void forEachChunk(const Body& body) const {
    if (concurrent_)
      tbb::parallel_for(size_t(0), chunks_, body);
    else
      for (size_t c = 0; c < chunks_; ++c) body(c);
  }

  // Writes the successors of `n` modules at w and their arguments at a, argument number
  // `base` of the next string.
  void fillChunk(const StringModule* in, size_t n, StringModule* __restrict w, double* __restrict a,
                 uint32_t base) const {
    const PerOp* perOp = perOp_.data();
    const Entry* entries = entries_.data();
    const double* inArgs = str_.args.data();
    for (size_t i = 0; i < n; ++i) {
      const StringModule mod = in[i];
      const PerOp p = perOp[mod.op];
      if (p.first != UINT32_MAX) {
        const Entry* e = entries + p.first;
        for (uint32_t k = 0; k < p.modules; ++k)
          w[k] = StringModule{e[k].op, base + e[k].firstArg, rt::keyWithSalt(mod.key, e[k].salt) & e[k].mask};
        if (p.args) std::memcpy(a, p.argData, p.args * sizeof(double));
      } else {
        w[0] = StringModule{mod.op, base, mod.key};
        if (p.args) std::memcpy(a, inArgs + mod.firstArg, p.args * sizeof(double));
      }
      w += p.modules;
      a += p.args;
      base += p.args;
    }
  }

  const StringOps& plan_;
  const ModuleString& str_;
  const bool concurrent_;
  const KeylessTemplateImages* images_;
  const size_t templates_, chunks_;
  std::vector<PerOp> perOp_;
  std::vector<Entry> entries_;
  std::vector<uint64_t> counts_;  // per chunk: modules and arguments written, then per template its uses
  std::vector<uint64_t> moduleAt_, argAt_;  // per chunk: where it writes in the next string
};

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
  next.args.reserve(size_t(std::min(modules / double(str.size()) * double(str.args.size()), double(maxModules))));
}

// The most modules a string buffer is sized for ahead of need (reserveForGrowth,
// KeylessTemplateImages::reserve): --max-shapes, but no more than the two buffers' share
// of --max-memory and than a size_t can address in bytes. --max-shapes 10^12 with
// --max-memory 1G reserved 16 TB up front (R020 before the first step) and 2^63 wrapped
// the byte count to a tiny block (a crash); a string that outgrows this grows its buffer.
size_t lookaheadModules(uint64_t maxShapes, uint64_t memoryBudget) {
  const uint64_t bySize = SIZE_MAX / 2 / sizeof(StringModule);
  return static_cast<size_t>(std::min({maxShapes, memoryBudget / 2 / sizeof(StringModule), bySize}));
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
  std::optional<KeylessTemplateImages> images;
  if (KeylessTemplateImages::applies(m_, plan_, str)) {
    images.emplace(plan_, str);
    images->reserve(str, next, steps_, lookaheadModules(opt_.maxShapes, memoryBudget_));
  }
  // A step of such a grammar; false, nothing written, where it would reach --max-shapes,
  // a string larger than --max-memory, or a limit is reached (for the general loop to
  // redo, as rewriteTemplates: it stops within the step at the limit).
  const auto rewriteImages = [&](KeylessTemplateImages& im) {
    const uint64_t modules = im.nextModules(opt_.maxShapes);
    if (modules >= opt_.maxShapes || modules > memoryBudget_ / sizeof(StringModule) || limitsReached()) return false;
    if (str.size() >= kConcurrentFrom) {
      TemplateStep(plan_, str, true, &im).fill(next);
    } else {
      next.modules.resizeForOverwrite(modules);
      im.writeImages(str.modules.data(), str.size(), next.modules.data(), next.modules.data() + modules);
    }
    im.finishStep(stats_.rewrites, ruleUses_);
    return true;
  };
  double growth = 0;  // the last step's: modules written over modules read
  for (int step = 0; step < steps_ && !limitHit; ++step) {
    next.clear();
    if (!images) reserveForGrowth(next, str, growth, steps_ - 1 - step, lookaheadModules(opt_.maxShapes, memoryBudget_));
    if (images ? !rewriteImages(*images) : !rewriteTemplates(str, next)) {
      images.reset();  // its tally is not the general loop's string
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

// A step of a grammar whose every rewriting symbol has a template (TemplateStep): a long
// string is rewritten over chunks on all cores, the result being the one-thread result.
// The limits are asked once, before writing: a step that would reach --max-shapes is left
// (nothing written, false returned) for the general loop to redo, stopping where it stops.
bool Derivation::rewriteTemplates(const ModuleString& str, ModuleString& next) {
  if (!plan_.allTemplates) return false;
  if (str.size() < kConcurrentFrom) return rewriteTemplatesOnThisThread(str, next);
  TemplateStep step(plan_, str, true);
  if (step.modules() >= opt_.maxShapes || step.args() >= UINT32_MAX || limitsReached()) return false;
  step.fill(next);
  step.addUses(stats_.rewrites, ruleUses_);
  return true;
}

// The same step of a shorter string, without TBB.
bool Derivation::rewriteTemplatesOnThisThread(const ModuleString& str, ModuleString& next) {
  TemplateStep step(plan_, str, false);
  if (step.modules() >= opt_.maxShapes || step.args() >= UINT32_MAX || limitsReached()) return false;
  step.fill(next);
  step.addUses(stats_.rewrites, ruleUses_);
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
