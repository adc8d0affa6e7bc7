// A derivation from start to end: the command families registered by op kind, the
// set-up (compiled code checked against the grammar, surface, assets, output tables) and
// how run() ends: a limit keeps what was derived (R004), running out of memory keeps
// nothing (R020), a DeriveError is the located error.
#include "backend/engine/derivation.h"
#include "backend/commands/insert_along_uv_command.h"
#include "backend/commands/surface_geometry.h"
#include "backend/engine/surface_reuse.h"

#include "runtime/memory_budget.h"
#include "runtime/stack_budget.h"

#include <algorithm>
#include <new>
#include <stdexcept>
#include <string>

namespace fgsg::backend {
namespace {

// The axes (1 X, 2 Y, 4 Z) along which a mesh has no extent; normalised into the unit
// box, an asset lies at 0 along them (a `leaf` or `quad` at z = 0).
bool hasContextRules(const ir::Module& m) {
  for (const ir::Rule& r : m.rules)
    if (!r.left.empty() || !r.right.empty()) return true;
  return false;
}

uint8_t flatAxes(const rt::Mesh& mesh) {
  const auto lo = mesh.boundsMin(), hi = mesh.boundsMax();
  uint8_t flat = 0;
  for (int axis = 0; axis < 3; ++axis)
    if (lo[axis] == hi[axis]) flat |= uint8_t(1u << axis);
  return flat;
}

}  // namespace

using Clock = std::chrono::steady_clock;

Derivation::Derivation(const ir::Module& m, const rt::DeriveOptions& o, rt::AssetLibrary& assets,
                       std::vector<double> attrs, const FgsgProgram* program, bool direct)
    : m_(m), opt_(o), assets_(assets), eval_(m, std::move(attrs)), paramStride_(maxSlotCount(m)),
      ruleUses_(m.rules.size(), 0), maxSlots_(maxRuleSlots(m)), program_(program), direct_(direct),
      scope_(surface_, stack_, deadline_, eval_.joinedStrings()), turtle_(*this, scope_), cga_(*this), collide_(*this), synthesis_(*this), marching_(*this), evolve_(*this), cells_(*this),
      reports_(*this) {
  if (program_) layout_ = ir::layoutProgram(m_);
  maxDepth_ = opt_.maxDepth;
  // `derive parallel n;` with an attr n: the count is its value in this run (--set
  // checked it: attributeOverrideProblem).
  int depthBound = m_.depthBound;
  steps_ = m_.steps;
  if (m_.countAttr >= 0) {
    const double count = eval_.attrData()[3 * size_t(m_.countAttr)];
    if (count >= 0 && count <= 2147483647.0) {
      if (m_.mode == ir::DeriveMode::Parallel) steps_ = int(count);
      else depthBound = int(count);
    }
  }
  // --step N: the derivation up to step N of its length (the CLI warns past the length).
  if (m_.mode == ir::DeriveMode::Parallel && opt_.parallelStep >= 0) steps_ = std::min(steps_, int(opt_.parallelStep));
  if (m_.mode != ir::DeriveMode::Parallel && depthBound >= 0 && static_cast<uint32_t>(depthBound) <= maxDepth_) {
    maxDepth_ = static_cast<uint32_t>(depthBound);
    depthBoundIsGrammars_ = true;
  }
  CommandFamily* const families[] = {&scope_,    &turtle_, &cga_,   &collide_,  &synthesis_,
                                     &marching_, &evolve_, &cells_, &textures_, &reports_};
  for (CommandFamily* family : families) registerFamily(*family);
  // Emit and Label are the core's own; an Unsupported op is refused. Every other kind needs a family.
  for (size_t k = 0; k < familyOf_.size(); ++k) {
    const auto kind = static_cast<ir::OpKind>(k);
    if (!familyOf_[k] && kind != ir::OpKind::Emit && kind != ir::OpKind::Unsupported && kind != ir::OpKind::Label)
      throw std::logic_error("no command family applies op kind " + std::to_string(k));
  }
}

void Derivation::registerFamily(CommandFamily& family) {
  for (ir::OpKind kind : family.kinds()) {
    CommandFamily*& slot = familyOf_[static_cast<size_t>(kind)];
    if (slot)
      throw std::logic_error("two command families apply op kind " + std::to_string(static_cast<int>(kind)));
    slot = &family;
  }
}

// A sequential grammar with contexts keeps the string they are matched in; direct code,
// which writes no string, is not used.
void Derivation::startSequentialString() {
  sequentialString_ = std::make_unique<SequentialString>(m_);
  scope_.writeBracketsTo(sequentialString_.get());
  direct_ = false;
}

uint32_t Derivation::maxSlotCount(const ir::Module& m) {
  uint32_t n = 0;
  for (const auto& s : m.symbols) n = std::max(n, s.slotCount);
  return n;
}

uint32_t Derivation::maxRuleSlots(const ir::Module& m) {
  uint32_t n = maxSlotCount(m);
  for (const auto& r : m.rules) n = std::max(n, r.slotCount);
  return n;
}

rt::DeriveResult Derivation::run() {
  rt::DeriveResult result;
  const auto start = Clock::now();
  deadline_ = rt::Deadline(opt_.startedAt == Clock::time_point{} ? start : opt_.startedAt, opt_.maxSeconds);
  memoryBudget_ = opt_.maxMemoryBytes ? opt_.maxMemoryBytes : rt::defaultMemoryBudget();
  stackFloor_ = rt::stackFloor();
  try {
    checkProgram();
    checkEnvironment();
    // Direct code applies scope commands on the plane (on a surface T traces).
    direct_ = direct_ && program_ && program_->direct && !surface_ && m_.mode != ir::DeriveMode::Parallel;
    if (m_.mode != ir::DeriveMode::Parallel && hasContextRules(m_)) startSequentialString();
    resolveAssets();
    textures_.prepare(m_, opt_.assetDirs);
    initOutput();
    orderedDirect_ = direct_ && canOrderDirectInstances();
    if (m_.mode == ir::DeriveMode::Parallel)
      runParallel();
    else
      runSequential();
    result.ok = true;
    if (depthLimitHit_) result.messages.push_back(depthWarning_);
    closeStarts();
    orderDirectInstances();
    appendCurves();  // marching's curves first: their instances index them from 0
    appendLines();
    appendSurface();
  } catch (const LimitReached& limit) {
    keepAfter(limit, result);
  } catch (const rt::TimeLimitReached&) {  // from a trace, deep in the runtime
    keepAfter(timeLimit(), result);
  } catch (const std::bad_alloc&) {
    outOfMemory(result);
  } catch (const DeriveError& e) {
    result.messages.push_back({true, e.code, e.loc.line, e.loc.col, e.message});
  } catch (const InexactDirect&) {
    inexactDirect_ = true;
  }
  stats_.deriveSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  stats_.instances = out_.instances.size();
  // Lines and the surface are appended after the rules' instances: placed by no rule.
  if (origins_.on()) out_.origins.resize(out_.instances.size());
  overlapWarnings(result.messages);
  turtle_.endCylinders(result.messages);  // R032
  if (result.ok)
    if (auto never = marching_.tally().neverStarted()) result.messages.push_back(*never);  // R030
  result.stats = stats_;
  // Strings a `+` joined follow the module's in the instances' table (string parameters).
  if (out_.strings.size() == m_.strings.size())
    out_.strings.insert(out_.strings.end(), eval_.joinedStrings().joined().begin(), eval_.joinedStrings().joined().end());
  out_.finishes = textures_.finishes();  // what InstanceList::finishIndex numbers
  result.instances = std::move(out_);
  result.reports = reports_.takeReports();
  result.prints = reports_.takePrints();
  return result;
}

// The grammar's lines (Line/LineSeg) as swept tubes or bent assets, and as the line
// graph. Normals for the bent assets: the surface's at the closest point, else +Z.
void Derivation::appendLines() {
  const auto normalAt = [this](const rt::Vec3& p) -> rt::Vec3 {
    return surface_ ? rt::Vec3(surface_->startScopeAt(p, nullptr).Z()) : rt::Vec3::UnitZ();
  };
  appendLineTubes(collide_.lines(), assets_, out_, symbolColor_, normalAt);
}

// The end of the last start shape's instances (InstanceList::startBounds): lots and seeds
// derived apart opened theirs as they began; anything else is the one axiom's.
void Derivation::closeStarts() {
  if (startsClosed_) return;
  startsClosed_ = true;
  auto& bounds = out_.startBounds;
  if (bounds.empty()) bounds.push_back(0);
  bounds.push_back(static_cast<uint32_t>(out_.instances.size()));
}

// A limit ends the derivation: what was derived is kept, with the R004 warning.
void Derivation::keepAfter(const LimitReached& limit, rt::DeriveResult& result) {
  if (depthLimitHit_) result.messages.push_back(depthWarning_);
  result.ok = true;
  result.messages.push_back({false, "R004", limit.loc.line, limit.loc.col, limit.message});
  try {
    closeStarts();
    orderDirectInstances();
    appendCurves();  // marching's curves first: their instances index them from 0
    appendLines();
    appendSurface();
  } catch (const std::bad_alloc&) {
    result.messages.clear();
    outOfMemory(result);
  }
}

// Memory ran out before the budget noticed (a single huge allocation, or a budget over
// what the system gives): nothing is kept, and the error names the rule that ran away.
void Derivation::outOfMemory(rt::DeriveResult& result) {
  out_ = rt::InstanceList{};
  buckets_.clear();
  result.ok = false;
  const auto [who, loc] = runaway(ir::Loc{});
  result.messages.push_back({true, "R020", loc.line, loc.col,
                             "out of memory while deriving (" + rt::formatMemorySize(rt::residentMemoryBytes()) +
                                 " in use): " + who +
                                 " ran away; nothing is written (--max-memory stops a derivation "
                                 "earlier and keeps its shapes)"});
}

// Compiled code must come from this very grammar: its tables are numbered by its IR.
void Derivation::checkProgram() const {
  if (!program_) return;
  const FgsgProgram& p = *program_;
  if (p.abiVersion != FGSG_ABI_VERSION)
    throw DeriveError{{}, "R900", "compiled code for runtime ABI " + std::to_string(p.abiVersion) +
                                      ", but this runtime is ABI " + std::to_string(FGSG_ABI_VERSION) +
                                      ": compile the grammar again"};
  if ((p.direct && !p.directPlaces) || p.blockCount != layout_.blocks.size() || p.ruleCount != m_.rules.size() ||
      p.alternativeCount != layout_.alternativeCount || p.symbolCount != m_.symbols.size() ||
      p.scopeSize != sizeof(rt::Scope))
    throw DeriveError{{}, "R900", "the compiled code does not match this grammar (" +
                                      std::to_string(p.blockCount) + " blocks and " +
                                      std::to_string(p.ruleCount) + " rules compiled, " +
                                      std::to_string(layout_.blocks.size()) + " and " +
                                      std::to_string(m_.rules.size()) + " in the grammar)"};
}

void Derivation::checkEnvironment() {
  if (m_.mode == ir::DeriveMode::Parallel && (m_.collision.all || opt_.collideAll))
    throw DeriveError{m_.collision.loc, "R009",
                      "collision tests need a sequential derivation: a collision culls the rest "
                      "of one production, and an L-system rewrites every module at once"};
  if (m_.surface.present || !opt_.surfaceOverride.empty()) {
    // An L-system's turtle draws in space; its surface and fields are only the
    // environment its ?E queries read (query_modules.cpp), so it needs one.
    const bool lsystem = m_.mode == ir::DeriveMode::Parallel;
    if (lsystem && m_.findSymbol("?E") < 0)
      throw DeriveError{m_.surface.loc, "R009",
                        "a surface needs a sequential derivation: L-system turtles draw in space, "
                        "and read a surface's fields only through the environmental query ?E"};
    std::shared_ptr<const SurfaceWorld>& world = lsystem ? environment_ : surface_;
    const auto start = Clock::now();
    SurfaceReuse* reuse = SurfaceReuseScope::current();  // fgsg view: the last derivation's
    if (reuse) {
      std::lock_guard<std::mutex> lock(reuse->mutex);
      world = reuse->world;
    }
    if (!world) {
      world = reuse && reuse->geometries
                  ? std::make_shared<SurfaceWorld>(m_, opt_, opt_.assetDirs,
                                                   reuse->geometries->obtain(m_.surface, opt_, opt_.assetDirs, &deadline_),
                                                   &deadline_)
                  : std::make_shared<SurfaceWorld>(m_, opt_, opt_.assetDirs, &deadline_);
      if (reuse) {
        std::lock_guard<std::mutex> lock(reuse->mutex);
        reuse->world = world;
      }
    }
    stats_.surfaceSeconds += std::chrono::duration<double>(Clock::now() - start).count();
  }
  marching_.loadTextures();
}

// A `.cga` grammar's inserts whose shape goes on after them in their successor (an op
// follows before the bracket around them closes): only there can anything read the
// geometry the asset gives the shape, which a large asset takes a while to build
// (`i("tree.obj") Tree.` never does). In fgsg's dialect I() places the asset and the shape
// goes on with its own geometry (`I("sphere") Top`, `Top ~> Comp("top"){ ... }` comps the box).
void Derivation::findReadInserts() {
  readInserts_.clear();
  if (!m_.cityEngineLots) return;
  std::function<void(const ir::Block&)> visit = [&](const ir::Block& b) {
    for (size_t k = 0; k < b.size(); ++k) {
      for (const auto& body : b[k].bodies) visit(body);
      if (b[k].kind == ir::OpKind::Instance && k + 1 < b.size() && b[k + 1].kind != ir::OpKind::Pop)
        readInserts_.insert(&b[k]);
    }
  };
  visit(m_.axiom);
  for (const auto& r : m_.rules)
    for (const auto& a : r.alternatives) visit(a.ops);
}

// Every asset is loaded before deriving, so a missing file is reported at its I().
void Derivation::resolveAssets() {
  std::vector<ir::Loc> firstUse(m_.assets.size());
  std::function<void(const ir::Block&)> visit = [&](const ir::Block& b) {
    for (const auto& op : b) {
      if (op.kind == ir::OpKind::Instance && firstUse[op.index].line == 0) firstUse[op.index] = op.loc;
      if ((op.kind == ir::OpKind::Line || isInsertAlongUv(m_, op)) && op.asset < firstUse.size() &&
          firstUse[op.asset].line == 0)
        firstUse[op.asset] = op.loc;
      for (const auto& body : op.bodies) visit(body);
    }
  };
  visit(m_.axiom);
  for (const auto& r : m_.rules)
    for (const auto& a : r.alternatives) visit(a.ops);
  findReadInserts();
  assetHasTexcoords_.assign(m_.assets.size(), 0);
  assetHasImages_.assign(m_.assets.size(), 0);
  assetFlatAxes_.assign(m_.assets.size(), 0);
  assetSourceBox_.assign(m_.assets.size(), {0, 0, 0, 1, 1, 1});
  assetMesh_.assign(m_.assets.size(), -1);
  for (size_t i = 0; i < m_.assets.size(); ++i) {
    std::string error;
    const int mesh = assets_.resolve(m_.assets[i], error);
    if (mesh < 0) throw DeriveError{firstUse[i], "R003", error};
    assetMesh_[i] = mesh;
    assetHasTexcoords_[i] = assets_.mesh(mesh).hasTexcoords();
    assetHasImages_[i] = assets_.mesh(mesh).textured();
    assetFlatAxes_[i] = flatAxes(assets_.mesh(mesh));
    assetSourceBox_[i] = assets_.sourceBox(mesh);
  }
}

}  // namespace fgsg::backend
