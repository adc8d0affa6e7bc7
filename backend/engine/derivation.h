// The engine core: one derivation of a grammar, sequential (CGA/FGSG: one shape at a
// time by priority, then breadth- or depth-first) or parallel (L-systems: every module
// of a string per step, then the turtle). It owns the shapes waiting to be derived, the
// rule choice, the derivation order, the limits, the random streams, the output and the
// bridge that compiled code calls (runtime/abi.def) — and nothing about what a command
// does: each op goes to the command family that registered its kind
// (backend/commands/, docs/design.md "Adding a command").
//
// Its member functions are defined by concern:
//   derivation.cpp         run(), set-up, how a derivation ends
//   derivation_order.cpp   the sequential order: queues, successors, Emit, Lock-style
//                          on-the-spot derivation, op dispatch
//   lots.cpp               --lots: the axiom on every lot's footprint, one after another
//   seed_plants.cpp        independent seeds' plants, each derived on its own
//                          (concurrently) and output in seed order
//   rule_choice.cpp        guards, specific before general rules, weighted choice
//   limits.cpp             --max-depth/-shapes/-seconds/-memory and their messages
//   instance_output.cpp    the instance list: symbols, colours, placing, final order
//   grammar_facts.cpp      what the grammar uses, found once before deriving
//   queries.cpp            Shape.visible / occlusion / field queries
//   native_bridge.cpp      compiled blocks, guards, weights and direct derivation
//   parallel_rewriter.cpp  the L-system string rewriter and its turtle interpretation
#pragma once

#include "backend/commands/cells_command.h"
#include "backend/commands/cga_commands.h"
#include "backend/commands/evolve_command.h"
#include "backend/commands/collision_commands.h"
#include "backend/commands/marching_commands.h"
#include "backend/commands/report_commands.h"
#include "backend/commands/scope_commands.h"
#include "backend/commands/surface_world.h"
#include "backend/commands/synthesis_command.h"
#include "backend/commands/texture_commands.h"
#include "backend/commands/turtle_commands.h"
#include "backend/engine/context_world.h"
#include "backend/engine/instance_origins.h"
#include "backend/engine/limit_reached.h"
#include "backend/engine/native_call.h"
#include "backend/engine/parallel_string.h"
#include "backend/engine/sequential_string.h"
#include "backend/engine/shape_frames.h"
#include "backend/engine/shape_store.h"
#include "backend/engine/successor.h"
#include "backend/interp/eval.h"
#include "ir/program_layout.h"
#include "runtime/abi.h"
#include "runtime/assets.h"
#include "runtime/cga/street_edges.h"
#include "runtime/deadline.h"
#include "runtime/derivation.h"
#include "runtime/geometry.h"
#include "runtime/occlusion.h"

#include <array>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace fgsg::backend {

class Derivation final : public QueryHost {
 public:
  // `program`: the grammar's compiled code (deriveCompiled), else the IR is walked;
  // `direct`: direct symbols are derived by their compiled code at once.
  Derivation(const ir::Module& m, const rt::DeriveOptions& o, rt::AssetLibrary& assets, std::vector<double> attrs,
             const FgsgProgram* program = nullptr, bool direct = false);

  rt::DeriveResult run();
  // --lots: each lot's attribute values (lotAttributeSlots), one per DeriveOptions::lots.
  void setLotAttributes(std::vector<std::vector<double>> slots) { lotAttrs_ = std::move(slots); }
  // Whether the last run() stopped because direct derivation could not be exact.
  bool needsExactRun() const { return inexactDirect_; }
  // CityEngine's two derivations for context queries (context_queries.cpp): the first
  // records what the queries look at (queries give their defaults), the second answers them.
  void recordContext();
  std::shared_ptr<const ContextWorld> takeContextWorld();
  void answerContextFrom(std::shared_ptr<const ContextWorld> world);

  // ------------------------------------------------ what command modules use
  const ir::Module& module() const { return m_; }
  const rt::DeriveOptions& options() const { return opt_; }
  rt::AssetLibrary& assets() { return assets_; }
  rt::InstanceList& output() { return out_; }
  rt::DeriveStats& stats() { return stats_; }
  rt::GeometryArena& arena() { return arena_; }
  // The projection of uv set `set` a scope's `projection` names; null: the set has none.
  const rt::cga::UvProjection* uvProjection(uint32_t scopeProjection, uint32_t set) const {
    return textures_.projection(scopeProjection, set);
  }
  rt::OcclusionIndex& occluders() { return occluders_; }
  const std::shared_ptr<const SurfaceWorld>& surface() const { return surface_; }
  size_t scopeStackSize() const { return stack_.size(); }
  rt::Deadline& deadline() { return deadline_; }
  LimitReached timeLimit() const;
  // The symbol an instance of this successor is recorded under ("axiom" for the axiom).
  uint32_t placingSymbol(const Exec& ex) const { return ex.symbol == UINT32_MAX ? axiomSymbol_ : ex.symbol; }
  // Turtle segments: a cylinder asset under a symbol "F" of their own.
  uint32_t segmentAsset() const { return segmentAsset_; }
  uint32_t segmentSymbol() const { return segmentSymbol_; }
  uint8_t assetFlatAxes(uint32_t asset) const { return asset < assetFlatAxes_.size() ? assetFlatAxes_[asset] : 0; }
  // CityEngine's object coordinate system of the start shape being derived (the P and
  // axes of the scope returned; translate's and rotate's `object` and `pivot`): a lot's
  // first corner and edge (lots.cpp), else the world's frame. Worked out on first use.
  const rt::Scope& objectFrame();
  // The street edges of the lot being derived (its "streetWidth"; lots.cpp), null when it
  // has none: street.* then fall back to the object system. Worked out on first use.
  const rt::cga::StreetEdges* streetEdges();
  // CityEngine's pivot of a shape with this scope (translate's and rotate's `pivot`): the
  // frame setPivot gave it or the shape it came from (scope.pivot), else objectFrame().
  const rt::Scope& pivotFrame(const rt::Scope& scope);
  // CityEngine's pivots and trim planes of the start shape being derived (shape_frames.h).
  ShapeFrames& shapeFrames() { return frames_; }
  // Whether comp(f) gives its faces trim planes: only a grammar that can apply them
  // (trim(), the primitives, an insert after a comp) pays for them.
  bool makesTrimPlanes() const { return makesTrimPlanes_; }

  // Adds an instance of `asset` filling `scope` to the output (R005 when it is not finite
  // or reaches past float range); I("none") adds nothing. `cut`, when given, receives the
  // geometry a grammar asset cut by the shape's trim planes leaves the shape (untouched
  // when nothing cut it).
  void placeInstance(uint32_t asset, const rt::Scope& scope, uint32_t symbol, const double* params,
                     uint32_t paramCount, ir::Loc loc, bool zUp = false, std::optional<rt::GeomRef>* cut = nullptr);
  // CityEngine's i() makes the shape's geometry the asset's: grammar asset `asset` (zUp
  // turned) as a solid in the normalised coordinates of the scope it fills
  // (rt::cga::assetGeometry), built once per derivation.
  rt::GeomRef insertedGeometry(uint32_t asset, bool zUp);
  // Whether grammar asset `asset` is I("none"), which places nothing.
  bool placesNothing(uint32_t asset) const { return asset == noneAsset_; }
  // Whether anything can read the geometry Instance op `op` gives its shape (findReadInserts).
  bool insertIsRead(const ir::Op& op) const { return !readInserts_.empty() && readInserts_.count(&op) != 0; }
  // Whether Instance op `op` only gives its shape the asset (a .cga i() whose successor goes
  // on: CityEngine replaces the geometry, and the leaf that ends the shape outputs it once).
  bool insertIsCarried(const ir::Op& op) const {
    return leavesOutput_ && op.mode == ir::InstanceMode::Plain && op.recordAs == ir::Op::kPlacingSymbol &&
           op.index < assetMesh_.size() && op.index != noneAsset_ && insertIsRead(op);
  }
  // The geometry a carried insert gives a shape filling `scope`: the asset's solid, cut by
  // the shape's trim planes where they reach it; outputLeaf knows it as the asset's.
  rt::GeomRef carryInsert(const ir::Op& op, const rt::Scope& scope);
  // The scope an Instance op's asset fills, as its insert mode says (runtime/insert_fit.h);
  // placeInstance(..., op.zUp) then turns a zUp asset inside it.
  rt::Scope insertFitted(const ir::Op& op, const rt::Scope& scope) const;
  // An ABOP polygon (`{ . }`): its world-space vertices fanned into triangles from the
  // first, output as geometry of its own in the turtle's colour (a leaf green unless
  // Color says), under the symbol "polygon".
  void placePolygon(const std::vector<rt::Vec3>& vertices, const rt::Scope& turtle, ir::Loc loc);
  // Turtle geometry built in world coordinates (a polygon, a generalized cylinder) as an
  // instance of its own mesh, in the turtle's colour, under `symbol`.
  void placeTurtleMesh(rt::Mesh mesh, const rt::Scope& turtle, uint32_t symbol, ir::Loc loc);
  // Registers a mesh the derivation built itself (an ornament, the mortar, a cell's box)
  // as an output asset named `name`: its index in the output's asset table. `builtIn`,
  // when given, receives the world box it was built in (placing the asset there puts it
  // back where it was built).
  uint32_t addGeneratedAsset(const std::string& name, const rt::Mesh& world, rt::Scope* builtIn = nullptr);
  // Writes a shape of op's symbol with its parameter slots evaluated.
  void emit(const ir::Op& op, const double* slots, State& st, Exec& ex);
  // Writes a shape of `symbol` (parameterless) on `scope` as an Emit at `at` would: how
  // the solvers' pieces (Synthesize, Evolve) become shapes.
  void emitShape(uint32_t symbol, const rt::Scope& scope, Exec& ex, ir::Loc at, const rt::GeomRef& geom = {});
  // Runs body k of op (a split part, a roof, a Lock alternative) on its own scope; the part
  // takes `place` (CGA's split/comp index and total) and `frame` (its shape frame: comp(f)'s
  // trim planes), else the outer shape's.
  void runBody(const ir::Op& op, size_t k, const rt::Scope& scope, const rt::GeomRef& geom, const State& outer,
               Exec& ex, Frame& f, const rt::Scope::Place* place = nullptr, const uint16_t* frame = nullptr);
  // Inside a Lock every shape is derived where it is written.
  void enterLock() { ++lockDepth_; }
  void leaveLock() { --lockDepth_; }
  bool inLock() const { return lockDepth_ > 0; }
  // While set, every terminal shape (a symbol without rules) also leaves its surface
  // (rt::cga::surfacePolygons), labelled with its symbol's name, in `into`: how a Cells
  // base part's pieces become a base mesh. Returns the recorder it replaces.
  std::vector<rt::cells::LabelledPolygon>* recordTerminals(std::vector<rt::cells::LabelledPolygon>* into) {
    std::swap(into, terminalPieces_);
    return into;
  }

  // ------------------------------------------------ queries (QueryHost)
  double visible(const rt::Scope& scope, const std::string& target, ir::Loc at) override;
  double occlusion(const rt::Scope& scope, ir::Loc at) override;
  double fieldNumber(const rt::Scope& scope, uint32_t env, const std::string& member, ir::Loc at) override;
  rt::Vec3 fieldVector(const rt::Scope& scope, uint32_t env, const std::string& member, ir::Loc at) override;
  double texture(const rt::Scope& scope, uint32_t env, ir::Loc at) override;
  double feature(const std::string& member, const std::string& arg, ir::Loc at) override {
    return cells_.feature(member, arg, at);
  }
  double geometry(ir::Query q, const rt::Scope& scope, const rt::GeomRef& geom, double arg, ir::Loc at) override;
  double context(ir::Query q, uint32_t target, const std::string& label, const rt::Scope& scope,
                 const rt::GeomRef& geom, ir::Loc at) override;
  // label("name"): the running shape becomes a labelled context shape (first derivation).
  void label(const std::string& name, const State& st);
  // The running shape as an occluder (a comp or offset runs on it; a leaf: `node` its own).
  void noteOccluder(const State& st, uint64_t node);
  void noteOccluder(const State& st) { noteOccluder(st, currentNode_); }
  // A split or comp part becomes the running node of the shape tree; returns the outer one.
  uint64_t enterBody(Exec& ex);
  void leaveBody(uint64_t outer) { currentNode_ = outer; }

  // ------------------------------------------------ the runtime entry points of compiled
  // code (runtime/abi.def, native_bridge.cpp), for a sequential derivation (call.st set)
  // or a parallel rewriting step (call.string set).
  void nativeEmit(NativeCall& call, uint32_t op, const double* slots);
  void nativeOp(NativeCall& call, uint32_t op, const double* args, uint32_t n);
  void nativeTranslate(NativeCall& call, double x, double y, double z) { scope_.translate(call.st->scope, x, y, z); }
  void nativeRotate(NativeCall& call, uint32_t axis, double degrees) {
    scope_.turn(call.st->scope, static_cast<int>(axis), degrees);
  }
  void nativePush(NativeCall& call) { scope_.push(*call.st); }
  void nativePop(NativeCall& call, uint32_t op) { scope_.command(*call.st, *layout_.ops[op], nullptr); }
  void directCosSin(double degrees, double* out) { scope_.cosSin(degrees, out); }
  void directTimeCheck() { checkTime(); }
  void directInstance(rt::Scope& s, uint32_t op, uint32_t symbol, const double* params, uint32_t depth,
                      uint64_t preorder);
  double nativeJoin(double a, uint32_t ta, double b, uint32_t tb) {
    return eval_.join(a, static_cast<ir::Type>(ta), b, static_cast<ir::Type>(tb));
  }
  // A string id's text (the module's, or one a string `+` joined): reports, prints.
  const std::string& stringText(double id) const { return eval_.string(id); }

 private:
  // A branch of a rule that applies, with its weight.
  struct Candidate {
    const ir::Alternative* alt;
    uint32_t rule;
    double weight;
  };
  // The shape (depth, preorder number) that placed an instance in direct code.
  struct PlacingShape {
    uint32_t depth = 0;
    uint64_t preorder = 0;  // the axiom: 0; direct shapes from 1 on
  };

  static uint32_t maxSlotCount(const ir::Module& m);
  static uint32_t maxRuleSlots(const ir::Module& m);

  // derivation.cpp
  void keepAfter(const LimitReached& limit, rt::DeriveResult& result);
  void closeStarts();
  void outOfMemory(rt::DeriveResult& result);
  void checkProgram() const;
  void checkEnvironment();
  void resolveAssets();
  void findReadInserts();
  void registerFamily(CommandFamily& family);

  // derivation_order.cpp
  void runSequential();
  void deriveWaitingShapes();
  void deriveShape(const WaitingShape& shape);
  // node: the shape's place in the sequential string (UINT32_MAX without one).
  bool deriveNow(uint32_t symbol, const double* slots, const State& at, const Exec& parent, uint32_t index,
                 uint32_t node);
  bool deriveNowOnFreshStack(uint32_t symbol, const double* slots, const State& at, const Exec& parent,
                             uint32_t index, uint32_t node);
  void startSequentialString();
  void execRoot(uint32_t block, const ir::Block& ops, const rt::Scope& scope, const rt::GeomRef& geom, uint64_t key,
                uint32_t depth, uint32_t index, const double* params, uint32_t symbol,
                rt::RandomStream* rng = nullptr, rt::LineCursor line = {});
  ShapeQueue& bucketFor(int priority);
  void runBlock(uint32_t block, const ir::Block& ops, State& st, Exec& ex, Frame& f);
  void execBlock(const ir::Block& ops, State& st, Exec& ex, Frame& f);
  void applyEvaluated(const ir::Op& op, State& st, Exec& ex, Frame& f, ArgBuffer& buf);
  void applyOp(const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex, Frame& f);
  const double* evalSlots(const ir::Op& op, const Frame& f, ArgBuffer& buf);
  const double* evalOpArgs(const ir::Op& op, const Frame& f, ArgBuffer& buf, uint32_t& n);
  [[noreturn]] void unsupported(const ir::Op& op);

  // lots.cpp
  void deriveLots(uint64_t root);
  // context_queries.cpp: start shape `start` begins at tree node `node`.
  void enterStart(uint32_t start, uint64_t node, const rt::Scope& scope, const rt::GeomRef& geom);

  // seed_plants.cpp
  struct Plant;
  friend struct SeedPlantCache;  // keeps plants for the next derivation (fgsg view)
  void deriveSeedsApart(const std::vector<rt::Scope>& starts, uint64_t root);
  void adoptParent(const Derivation& parent);
  Plant derivePlant(const rt::Scope& start, uint64_t key, uint32_t index);
  void mergePlants(std::vector<Plant>& plants);

  // rule_choice.cpp
  static bool isSpecific(const ir::Rule& r);
  // `node`: the shape's place in the sequential string (contexts), or UINT32_MAX; a
  // context's parameters are written into `params` (f's block, with room for them).
  const ir::Alternative* choose(const ir::Symbol& sym, const Frame& f, uint32_t node, double* params);
  bool contextHolds(const ir::Rule& r, uint32_t node, double* params) const;
  bool guardHolds(uint32_t rule, const Frame& f);
  bool takesPart(bool firstApplicable, uint32_t ri, uint32_t& taken);
  void noteOverlap(const std::pair<uint32_t, uint32_t>& rules);  // (taken, also applying), once
  void overlapWarnings(std::vector<rt::DeriveMessage>& messages) const;
  void addCandidates(const ir::Rule& r, uint32_t ri, const Frame& f, double& total);
  const Candidate& pickCandidate(rt::RandomStream& rng, double total) const;

  // limits.cpp
  void depthLimit(const ir::Symbol& sym, uint32_t creator);
  std::pair<std::string, ir::Loc> runaway(ir::Loc axiomAt) const;
  [[noreturn]] void shapeLimit(const ir::Op& op);
  LimitReached shapeLimitReached(ir::Loc axiomAt) const;
  std::optional<LimitReached> limitsReached();
  void pollLimits();
  void checkTime();
  std::optional<LimitReached> memoryLimit();
  uint64_t assetOutputBytes(uint32_t asset);

  // instance_output.cpp
  void initOutput();
  void outputLeaf(uint32_t symbol, const State& st, const double* params, ir::Loc loc);
  // CityEngine's i() on a shape with trim planes (comp(f)'s): when an enabled plane cuts
  // into the asset's box, the asset's mesh cut by them goes out as geometry of its own
  // (nothing when it is cut away) and true is returned; false: place it as it is.
  bool placeTrimmedAsset(uint32_t asset, const rt::Scope& scope, uint32_t symbol, const double* params,
                         uint32_t paramCount, ir::Loc loc, bool zUp, std::optional<rt::GeomRef>* cut);
  // An instance of grammar asset `asset` (or of its cut mesh) takes the image of a Texture
  // above it and is drawn untinted when textured, unless Color says.
  void applyAssetLook(rt::Instance& inst, uint32_t asset, const rt::Scope& scope) const;
  // The trim planes of `scope`'s shape that cut into asset `asset` filling it (zUp turned);
  // none when its box, or else its mesh's vertices, lie wholly on their kept side.
  std::vector<rt::cga::TrimPlane> planesCuttingAsset(uint32_t asset, const rt::Scope& scope, bool zUp) const;
  // outputLeaf of a shape whose geometry is still what carryInsert gave it: an instance of
  // the asset (or its cut mesh) with the asset's normals, uvs and images; false otherwise.
  bool outputCarriedAsset(uint32_t symbol, const State& st, const double* params, uint32_t slots, ir::Loc loc);
  void reserveForLots(size_t done, size_t lots);
  static std::array<float, 3> colorFor(const std::string& name);
  void appendSurface();
  void appendCurves();
  void appendLines();
  void orderDirectInstances();

  // grammar_facts.cpp
  bool moduleUses(const std::function<bool(const ir::Op&)>& pred) const { return ir::anyOp(m_, pred); }
  bool moduleUsesQuery(ir::Query q) const;
  void findEagerSymbols();
  bool canOrderDirectInstances() const;
  bool seedsGrowApart() const;
  bool usesMarchingSurface() const;
  double stringId(const std::string& s) const;

  // native_bridge.cpp
  uint32_t blockOf(const ir::Alternative* alt) const;
  double callValue(FgsgValueFn fn, const Frame& f);
  void deriveDirect(uint32_t symbol, const double* slots, const rt::Scope& scope, uint64_t key, uint32_t depth);
  void runNative(uint32_t block, State& st, Exec& ex, Frame& f);

  // parallel_rewriter.cpp
  void runParallel();
  bool rewriteTemplates(const ModuleString& str, ModuleString& next);
  bool rewriteTemplatesOnThisThread(const ModuleString& str, ModuleString& next);
  void appendTemplate(const SuccessorTemplate& t, uint64_t key, ModuleString& out);
  void cutBranches(ModuleString& str);
  void copyModule(const ModuleString& str, size_t i, ModuleString& out);
  void appendModules(uint32_t block, const ir::Block& ops, Frame& f, uint64_t key, ModuleString& out,
                     uint32_t owner = UINT32_MAX);
  void checkParallelOp(const ir::Op& op);
  void appendModule(uint32_t op, const double* args, uint32_t n, StringTarget& t);
  const ir::Alternative* chooseInString(const ir::Symbol& sym, ir::RuleSection section, const ModuleString& str,
                                        size_t at, rt::RandomStream& rng, uint32_t step);
  void bind(const ir::ContextModule& cm, const ModuleString& str, size_t at);
  bool matchLeft(const ir::Rule& r, const ModuleString& str, size_t at);
  bool matchRight(const ir::Rule& r, const ModuleString& str, size_t at);
  void interpretString(const ModuleString& str);
  // query_modules.cpp
  void answerQueries(ModuleString& str);
  // rule_sections.cpp
  bool rewriteSection(ir::RuleSection section, const ModuleString& str, ModuleString& out, uint32_t step,
                      bool& limitHit, std::optional<LimitReached>& stopped);
  bool sectionPass(ir::RuleSection section, const ModuleString& str, ModuleString& next, uint32_t step,
                   bool& limitHit, std::optional<LimitReached>& stopped);
  void linkBrackets(const ModuleString& str);
  [[noreturn]] void sequentialOnly(const ir::Op& op);
  void checkInstanceReach(const rt::Mat4& unitBoxToWorld, uint32_t symbol, ir::Loc loc) const;

  const ir::Module& m_;
  const rt::DeriveOptions& opt_;
  rt::AssetLibrary& assets_;
  Evaluator eval_;
  rt::Deadline deadline_;                // --max-seconds, passed down to traces and fields
  uint64_t memoryBudget_ = 0;            // --max-memory
  std::chrono::steady_clock::time_point memoryCheckedAt_{};  // the last memory reading
  size_t instancesCounted_ = 0;          // instances whose output bytes are in instanceBytes_
  uint64_t instanceBytes_ = 0;
  std::vector<uint64_t> assetBytes_;     // output bytes of one instance, per out_.assets entry
  // A seed plant's derivation: stats_.shapesCreated when each instance was placed (how
  // --max-shapes cuts a plant that follows others, seed_plants.cpp).
  bool recordShapesAtInstances_ = false;
  std::vector<uint64_t> shapesAtInstance_;
  rt::InstanceList out_;
  rt::DeriveStats stats_;
  uint32_t paramStride_ = 0;  // the largest parameter block of any symbol
  rt::GeometryArena arena_;
  rt::OcclusionIndex occluders_;
  // Context queries (context_queries.cpp): off unless the grammar asks them.
  enum class ContextMode { Off, Record, Answer } contextMode_ = ContextMode::Off;
  std::shared_ptr<ContextWorld> recorded_;        // the first derivation's
  std::shared_ptr<const ContextWorld> world_;     // what the second answers from
  std::vector<std::vector<uint32_t>> shapesByStart_;  // world_->shapes by start shape
  std::unordered_map<uint64_t, uint64_t> parentOf_;  // this derivation's shape tree
  uint64_t currentNode_ = 0;   // the shape (or split part) whose ops run
  uint32_t currentStart_ = 0;  // the start shape being derived
  // The start shape objectFrame() is worked out from (a lot's polygon; none: the world),
  // and the frame once worked out.
  rt::Scope objectStartScope_;
  rt::GeomRef objectStartGeom_;
  bool objectFrameKnown_ = false;
  rt::Scope objectFrame_;
  const rt::Lot* streetLot_ = nullptr;  // the lot being derived when it has street widths
  bool streetEdgesKnown_ = false;
  rt::cga::StreetEdges streetEdges_;
  ShapeFrames frames_;  // setPivot's pivots and comp(f)'s trim planes of the start shape being derived
  bool makesTrimPlanes_ = false;
  uint64_t labelCount_ = 0;    // label() copies made so far (their tree nodes)
  std::vector<std::pair<int, ShapeQueue>> buckets_;
  std::vector<std::pair<int, size_t>> marks_;  // depth-first: queue sizes before a successor
  std::vector<Saved> stack_;
  std::vector<double> params_;
  std::vector<Candidate> candidates_;
  std::vector<std::pair<uint32_t, uint32_t>> overlaps_;  // (taken, also applying) rules, each pair once
  std::vector<uint64_t> ruleUses_;  // applications per rule, to name a runaway one
  uint32_t maxSlots_ = 0;           // the largest parameter block of any rule
  uint32_t chosenRule_ = 0;
  uint32_t creatorRule_ = UINT32_MAX;  // the rule whose successor is running
  // Shapes at depth >= maxDepth_ stay terminal: --max-depth or the grammar's own bound
  // (`derive breadthfirst N;`), the smaller; the grammar's is reached without a warning.
  uint32_t maxDepth_ = 0;
  bool depthBoundIsGrammars_ = false;
  int steps_ = 0;  // parallel steps: the grammar's N, or its attr's value (ir::Module::countAttr)
  bool depthLimitHit_ = false;
  rt::DeriveMessage depthWarning_;
  std::vector<std::array<float, 3>> symbolColor_;
  uint32_t segmentAsset_ = 0, segmentSymbol_ = 0, axiomSymbol_ = 0;
  uint32_t polygonSymbol_ = UINT32_MAX;  // "polygon", when the grammar writes { }
  uint32_t noneAsset_ = UINT32_MAX;      // I("none"), when the grammar writes it
  // Per grammar asset: it has texture coordinates, so a Texture above its I() draws on it.
  std::vector<uint8_t> assetHasTexcoords_;
  std::vector<uint8_t> assetFlatAxes_;  // per asset: 1 X, 2 Y, 4 Z for an axis it has no extent along
  std::vector<std::array<double, 6>> assetSourceBox_;  // per asset: its file's box (AssetLibrary::sourceBox)
  std::vector<uint8_t> assetHasImages_;  // ... and images of its own (an OBJ's materials), drawn untinted
  std::vector<int> assetMesh_;  // per grammar asset: its mesh in assets_ (resolveAssets)
  std::unordered_set<const ir::Op*> readInserts_;  // findReadInserts
  // Per grammar asset, yUp and zUp: insertedGeometry's, once made.
  std::vector<std::array<std::optional<rt::GeomRef>, 2>> assetGeometry_;
  // carryInsert's geometries, by carriedKey: the asset, its turn, and its cut mesh (an index
  // into carriedCutMeshes_, -1 when uncut). The arena is never cleared, so a key stays unique.
  struct CarriedAsset {
    uint32_t asset = 0;
    bool zUp = false;
    int32_t cutMesh = -1;
  };
  static uint64_t carriedKey(const rt::GeomRef& g) { return (uint64_t(g.kind) << 32) | g.first; }
  std::unordered_map<uint64_t, CarriedAsset> carriedAssets_;
  std::vector<rt::Mesh> carriedCutMeshes_;  // trimAssetMesh's, in the cut scope's normalised coordinates
  // A CGA grammar (ir::leavesOutputGeometry): leaves output their own geometry, as
  // instances of these assets (outputLeaf).
  bool leavesOutput_ = false;
  uint32_t ownGeometryAsset_ = UINT32_MAX, leafCubeAsset_ = UINT32_MAX, leafQuadAsset_ = UINT32_MAX;
  bool usesOcclusion_ = false;
  std::shared_ptr<const SurfaceWorld> surface_;  // null: the grammar grows on the plane; shared by seed plants
  // An L-system's surface and fields, read only by its environmental queries ?E
  // (query_modules.cpp): its turtle draws in space, not on the surface.
  std::shared_ptr<const SurfaceWorld> environment_;
  std::vector<std::vector<double>> lotAttrs_;  // --lots: each lot's attribute slots
  std::vector<uint8_t> eager_;  // per symbol: derived where it is written (findEagerSymbols)
  uint32_t lockDepth_ = 0;      // inside a Lock every shape is derived where it is written
  std::vector<rt::cells::LabelledPolygon>* terminalPieces_ = nullptr;  // recordTerminals
  uint32_t onTheSpot_ = 0;      // shapes being derived where they are written, nested
  double noneId_ = -1, partId_ = -1, fullId_ = -1;
  rt::Vec3 streetDirection_ = rt::Vec3::UnitZ();
  const FgsgProgram* program_ = nullptr;  // compiled code (deriveCompiled), else the IR is walked
  bool direct_ = false;          // direct symbols are derived by their compiled code at once
  bool orderedDirect_ = false;   // ... including those placing instances (canOrderDirectInstances)
  PlacingShape placingShape_;            // the shape whose instance is being placed
  InstanceOrigins origins_;              // DeriveOptions::recordOrigins
  uint32_t placingDepth_ = UINT32_MAX;   // the depth of the shape whose successor runs (origins_)
  std::vector<PlacingShape> placedBy_;   // per instance, while orderedDirect_
  uint64_t visits_ = 1;                  // direct shapes visited so far, plus one
  bool startsClosed_ = false;    // closeStarts ran
  bool inexactDirect_ = false;   // ... and one of them gave up (see deriveDirect)
  uintptr_t stackFloor_ = 0;     // recursion (direct code, Lock sets) stays above this frame address
  ir::ProgramLayout layout_;     // how program_ numbers blocks and ops (and the string's ops)
  StringOps plan_;               // a parallel derivation's per-op table
  // Per module of the string being rewritten, when rules have contexts: a '[' the index
  // of its ']', a ']' the index of its '[' (UINT32_MAX: none), so that context matching
  // steps over a branch at once instead of walking through it.
  std::vector<uint32_t> bracketPartner_;

  // The command families, and which one applies each op kind.
  // A sequential grammar with contexts: the string they are matched in (else null).
  std::unique_ptr<SequentialString> sequentialString_;
  ScopeCommands scope_;
  TurtleCommands turtle_;
  CgaCommands cga_;
  CollisionCommands collide_;
  SynthesisCommand synthesis_;
  MarchingCommands marching_;
  EvolveCommand evolve_;
  CellsCommand cells_;
  TextureCommands textures_;
  ReportCommands reports_;
  std::array<CommandFamily*, static_cast<size_t>(ir::OpKind::Unsupported) + 1> familyOf_{};
};

}  // namespace fgsg::backend
