// The typed intermediate representation of a grammar. Rules are functions of their
// parameters; a successor is a sequence of ops (with nested blocks for split bodies);
// guards, probabilities and arguments are expression trees. The IR is what the
// interpreter executes and what the LLVM backend compiles, so it holds no runtime
// data structures: only indices into the module's tables.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace fgsg::ir {

struct Loc {
  int line = 0;
  int col = 0;
};

enum class Type : uint8_t { Num, Bool, Str, Vec3 };

const char* typeName(Type t);
// Number of double slots a value of this type takes in a parameter block. Strings are
// indices into Module::strings, booleans 0/1.
inline int slotWidth(Type t) { return t == Type::Vec3 ? 3 : 1; }

// ---------------------------------------------------------------- expressions

enum class ExprOp : uint8_t {
  Const,   // num (Num/Bool/Str id) or vec (Vec3)
  Param,   // slot: first slot of the parameter in the rule's parameter block
  Attr,    // index into Module::attrs
  Neg, Not,
  Add, Sub, Mul, Div, Mod, Pow,
  Eq, Ne, Lt, Le, Gt, Ge,
  And, Or,  // short-circuit
  Select,   // args[0] ? args[1] : args[2]
  Call,     // builtin: Builtin
  Rand,     // uniform in [args[0], args[1]) from the shape's random stream
  Query,    // query: Query; args as the query takes
  MakeVec,  // (x, y, z)
  VecElem,  // args[0].x/.y/.z: index 0..2
  // CGA's string `+`: args[0] and args[1] (Num, Bool or Str each) as text, joined (Str; a
  // number as CityEngine prints it, backend/interp/joined_strings.h).
  Join,
};

enum class Builtin : uint8_t {
  Sin, Cos, Tan, Asin, Acos, Atan, Atan2, Sqrt, Abs, Min, Max, Floor, Ceil, Round,
  Clamp, Lerp, Pow, Exp, Log, Sign, Length, Dot, Normalize,
};

// What a query asks of the current shape or its environment.
enum class Query : uint8_t {
  ScopeSx, ScopeSy, ScopeSz, ScopePx, ScopePy, ScopePz,  // Scope.sx ...
  ShapeDepth,          // Shape.depth: derivation depth (axiom = 0)
  ShapeIndex,          // Shape.index: position among the siblings of one successor
  ShapeVisible,        // Shape.visible("street"): args[0] a Str
  ScopeOcc,            // Scope.occ("noparent"): Str "none" | "part" | "full"
  Field,               // F1.member: env = the field, extra = string id of the member
  Texture,             // context.mask(uv): env = the texture; args as written
  Feature,             // Feature.edge, Feature.label("window") inside Cells: extra = string id of the member; args as written
  // CGA's shape attributes split.index/total, comp.index/total: the shape's place among
  // the parts of the last split (comp) above it, inherited by the shapes it creates.
  ShapeSplitIndex, ShapeSplitTotal, ShapeCompIndex, ShapeCompTotal,
  // CGA's geometry.*(): of the shape's own geometry (a box, polygon or solid), in metres.
  GeometryArea, GeometryHeight, GeometryVertices, GeometryFaces,
  GeometryIsPlanar,     // args[0]: the tolerance in degrees (Num); Bool
  GeometryIsConcave,    // Bool
  GeometryBoundaryLength,
  // CityEngine's context queries (docs/cga.md, "Occlusion and context queries"): extra =
  // the target (ContextTarget), args[0] the label (Str; "" any occluder). The occlusion
  // queries are Bool, minimumDistance and contextCount Num.
  ContextInside, ContextOverlaps, ContextTouches, ContextMinimumDistance, ContextCount,
  // CGA's geometry.angle(maxSlope | azimuth | zenith): extra = the selector
  // (rt::cga::GeometryAngleKind: 0, 1, 2), in degrees.
  GeometryAngle,
  // CGA's geometry.du(k, uvSpace) and dv: the spread of the texture coordinates of the
  // scope's projection of uv set k = extra (0..9) over the geometry.
  GeometryDu, GeometryDv,
  // CGA's contextCompare(target, label, comparison): the shape's rank among the labelled
  // shapes; extra = the target (ContextTarget) | the comparison (ContextComparison) << 2,
  // args[0] the label (Str).
  ContextCompare,
  // CGA's comp.sel: the name of the selector that chose the shape in the last comp above
  // it (Str): Module::compSelectors[place.compSel - 1], "" for none.
  ShapeCompSel,
};
inline constexpr Query kLastQuery = Query::ShapeCompSel;
inline bool isGeometryQuery(Query q) {
  return (q >= Query::GeometryArea && q <= Query::GeometryBoundaryLength) ||
         (q >= Query::GeometryAngle && q <= Query::GeometryDv);
}
inline bool isContextQuery(Query q) {
  return (q >= Query::ContextInside && q <= Query::ContextCount) || q == Query::ContextCompare;
}
// Which shapes a context query looks at: its own start shape's (CityEngine's intra), the
// other start shapes' (inter), or both.
enum class ContextTarget : uint8_t { Intra, Inter, All };
// contextCompare's comparisons in CityEngine's order: world.northernmost, southernmost,
// easternmost, westernmost, highest, lowest, area.largest, area.smallest.
enum class ContextComparison : uint8_t {
  Northernmost, Southernmost, Easternmost, Westernmost, Highest, Lowest, LargestArea, SmallestArea
};

struct Expr {
  ExprOp op = ExprOp::Const;
  Type type = Type::Num;
  double num = 0.0;
  double vec[3] = {0, 0, 0};
  uint32_t index = 0;  // Param slot, Attr index, Builtin, Query, VecElem lane
  uint32_t extra = 0;  // Query::Field: string id of the member name
  uint32_t env = 0;    // Query::Field / Texture: index into Module::environment
  std::vector<Expr> args;
  Loc loc;

  static Expr number(double v);
  static Expr boolean(bool v);
  static Expr string(uint32_t id);
  bool isConst() const { return op == ExprOp::Const; }
};

// ---------------------------------------------------------------- ops

// A size argument: absolute (h), relative to the remaining space (1r), or floating (~h).
struct Size {
  enum Kind : uint8_t { Absolute, Relative, Floating } kind = Absolute;
  Expr value;
};

enum class OpKind : uint8_t {
  Translate,     // args tx ty tz
  Rotate,        // axis 0/1/2 (Rx Ry Rz), args[0] degrees; axis 3: R(ax, ay, az)
  RotateNormal,  // RS(a): about the scope's normal (Z on the plane)
  Scale,         // S(sx, sy, sz): sizes (may be 1r)
  Push, Pop,     // [ ]
  Instance,      // I / IC / IM: index = asset; mode; args (IM: maxDist, maxAngle)
  Emit,          // a shape: index = symbol, args = parameter values
  Turtle,        // index = TurtleOp, args optional
  Subdiv,        // axis 0/1/2; sizes; one body per size; `repeat`: the parts repeat as a pattern
  Repeat,        // axes mask (1 X, 2 Y, 4 Z); sizes one per axis; bodies[0]
  Comp,          // str = selector id; bodies: one, applied to every component
  Extrude,       // args[0] height
  Footprint,     // args x1 z1 x2 z2 ...: the shape becomes this polygon in its scope's XZ plane; holes from ringStarts
  Offset,        // args[0] distance; bodies labelled `inside` / `border` (partLabels)
  Roof,          // str = kind ("hipped", "gable", "pyramid", "shed", "ridge"); index: kRoofByAngle
                 // or kRoofByHeight; args[0] the angle or height, then overhangs, edge; bodies[0]
  Lock,          // bodies: derived as one unit; a collision anywhere removes the whole set
  Line,          // Line(width, merge): args[0] width, args[1] merge (Bool); starts a line here
  LineSeg,       // LineSeg(length?): optional args[0] moves along X first; extends the line
  Synthesize,    // str = example file; args nx ny nz; index = parts' symbol string + 1 (0: none): model synthesis fills the scope
  Center,        // index = axes mask (1 X, 2 Y, 4 Z): centre the scope in the successor's first scope
  Color,         // args r, g, b: the colour of the instances placed from this scope on (clamped to 0..1)
  Texture,       // str = image file; args tile width, height (none: the scope's X and Y sizes): the image the
                 // leaves output from this scope on are textured with, projected from this scope's frame
  Marching,      // args length, angle; bodies: Top, Extruded, then the condition block (Buron et al. §5)
  MarchCondition,  // args[0] the condition (Bool): the whole of a Marching condition block
  Branch,        // args[0] n: n branches from the scope; bodies: the first n-1 take body 0, the last the last body
  Evolve,        // index 0: str = tile file; index i > 0: Module::tileSets[i - 1] (str its name); args generation, then optional k (rule size) and p4 (Bool): Chan & Hui's GA pattern fills the scope
  Cells,         // index 1: str = base mesh file, else the scope's own geometry; args joint, optional mortar; bodies[0]: each feature's shape (Legakis et al.)
  CellPattern,   // index = CellGenerator; args its sizes; bodies: none, or [0] each cell's shape
  Report,        // args key (Str), value (Num/Bool/Str): CGA's report(), collected per start shape
  Print,         // args the value (Num/Bool/Str), or a vector's three components: CGA's print()
  ShapeOperation,  // str = the command (AlignScopeToAxes, Setback, ShapeL ...: frontend/shape_operations.h); args its
                   // numbers (a word argument as the number it stands for); bodies labelled (partLabels) or none
  Label,         // args[0] the label (Str): CGA's label(), the shape a labelled context shape
  Material,      // index = MaterialProperty; args[0] its value (a number), or str = the image (the maps): the
                 // material of the instances placed from this scope on (backend/commands/texture_commands.h)
  Uv,            // index = UvOp: CGA's uv operations on the scope's projection of uv set `uvSet`; Setup: str =
                 // the axes ("xz"), sizes the tile width and height; Tile: sizes; Normalize: str = the mode;
                 // Scale / Translate: args u, v; Rotate: args[0] degrees; Delete / Project: no arguments;
                 // Copy: args[0] the source set (a constant 0..9)
  Unsupported,   // a construct whose runtime arrives later: `name`, its issue in `why`
};

// Cells' pattern generators (runtime/cells/generators.h).
enum class CellGenerator : uint8_t { BrickBond, HeaderRow, ArchBricks, RandomStones, EnglishBond, FlemishBond, HeaderBond,
                                      Shingles };

enum class InstanceMode : uint8_t { Plain, Collide, Merge };

// How I() fits its asset (CityEngine's i() insertMode): stretched onto the scope, or at its own
// size, either where its file puts it in the scope's frame (the scope becomes the asset's box)
// or centred on the scope's x and z with its box on y = 0.
enum class InsertFit : uint8_t { AlignSizeAndPosition, KeepSizeAndPosition, KeepSizeAlignPosition };

// Material(property, value) (frontend::materialProperty's words, in this order): the numbers
// first, then the images from NormalMap on. ColorMap is the .cga dialect's texture() (the
// image of the current projection, its frame kept); the maps after it are CityEngine's other
// texture layers.
enum class MaterialProperty : uint8_t {
  Roughness, Metallic, Opacity, ColorR, ColorG, ColorB, EmissiveR, EmissiveG, EmissiveB,
  NormalMap, ColorMap, BumpMap, DirtMap, SpecularMap, OpacityMap, EmissiveMap, OcclusionMap, RoughnessMap, MetallicMap
};
inline constexpr uint32_t kMaterialProperties = uint32_t(MaterialProperty::MetallicMap) + 1;
// Whether the property names an image (op.str) rather than a number (args[0]).
inline constexpr bool materialPropertyIsImage(uint32_t property) { return property >= uint32_t(MaterialProperty::NormalMap); }
// CityEngine's texture layer of an image property: its uv set (0 colormap, 1 bumpmap, 2 dirtmap,
// 3 specularmap, 4 opacitymap, 5 normalmap, 6 emissivemap, 7 occlusionmap, 8 roughnessmap,
// 9 metallicmap).
inline constexpr uint32_t materialLayerOf(MaterialProperty p) {
  switch (p) {
    case MaterialProperty::ColorMap: return 0;
    case MaterialProperty::BumpMap: return 1;
    case MaterialProperty::DirtMap: return 2;
    case MaterialProperty::SpecularMap: return 3;
    case MaterialProperty::OpacityMap: return 4;
    case MaterialProperty::NormalMap: return 5;
    case MaterialProperty::EmissiveMap: return 6;
    case MaterialProperty::OcclusionMap: return 7;
    case MaterialProperty::RoughnessMap: return 8;
    default: return 9;  // MetallicMap
  }
}

// CGA's uv operations (frontend::uvOperation's commands, in this order).
enum class UvOp : uint8_t { Setup, Scale, Translate, Rotate, Tile, Normalize, Delete, Project, Copy };
// CityEngine's uv sets 0..9 (0 the colour map's, 5 the normal map's).
inline constexpr uint32_t kUvSets = 10;

enum class TurtleOp : uint8_t {
  Forward,     // F(l): draw a segment and move
  Move,        // f(l): move without drawing
  Left,        // +(a)
  Right,       // -(a)
  PitchDown,   // &(a)
  PitchUp,     // ^(a)
  RollLeft,    // \(a)
  RollRight,   // /(a)
  TurnAround,  // |
  Width,       // !(w)
  RollHorizontal,  // $: roll about the heading until the left vector (scope X) is level (ABOP Fig. 2.6)
  Cut,             // %: a parallel derivation drops the rest of the branch after each step
  PolygonBegin,    // {: ABOP's polygons (ch. 5): start collecting vertices
  PolygonVertex,   // .: the turtle's position is the polygon's next vertex
  PolygonEnd,      // }: fill the polygon
  ColorIndex,      // ': the next colour of `turtle colors` ('(n): colour n; 0: the default colours)
  SurfaceBox,      // ~(s) / ~(sx, sy, sz): the scope becomes the box of a predefined surface at the turtle
                   // (`~leaf(s)` is `[ ~(s) I("leaf") ]`, ABOP's ~)
  Tropism,         // @Tp(x, y, z): the tropism vector T of ABOP eq. 2.4 (L-Py's Tropism)
  Elasticity,      // @Ts(e): the elasticity e; after each F, H turns by e |H x T| towards T
  Sphere,          // @O(r): a sphere (Op::asset) of radius r, default half the width, centred on the turtle
  MoveTo,          // @M(x, y, z): the turtle's position becomes (x, y, z)
  SetHeading,      // @R(hx, hy, hz, ux, uy, uz): the turtle's heading and (squared to it) up
  ColorPrevious,   // lpfg's `,`: the previous colour of `turtle colors` (`,(n)`: colour n)
  Circle,          // @o(r): a disc (Op::asset) of radius r, default half the width, across the heading
  CylinderStart,   // @Gs: lpfg's generalized cylinder starts at the turtle (its first control point)
  CylinderPoint,   // @Gc(n): lpfg's next control point, n strips from the last; with none open, L-Py's start
  CylinderEnd,     // @Ge(n): the last control point; the tube is drawn (backend/commands/generalized_cylinder.h)
};

// The turtle command a symbol's name stands for ("F", "+", "!" ...), or -1: how the
// turtle reads a rewritten turtle symbol in a parallel derivation's final string.
int turtleOpNamed(const std::string& name);

struct Op;
using Block = std::vector<Op>;

// Roof's op.index: args[0] is the slope in degrees, or the roof's height (Roof(kind,
// "byHeight", h), CityEngine's roofHip(byHeight, h) ...).
inline constexpr uint32_t kRoofByAngle = 0;
inline constexpr uint32_t kRoofByHeight = 1;

// Marching's op.index: the smoothness of the terminals on its segments, its optional
// fourth argument (Buron et al. §6; rt::marching::TerminalSmoothness in this order).
inline constexpr uint32_t kMarchC1 = 0;             // "C1", the default
inline constexpr uint32_t kMarchC0 = 1;             // "C0"
inline constexpr uint32_t kMarchDiscontinuous = 2;  // "none"

struct Op {
  OpKind kind = OpKind::Push;
  Loc loc;
  uint32_t index = 0;   // symbol / asset / axis / TurtleOp / axes mask
  uint32_t str = 0;     // string id (Comp selector, Roof kind)
  // Turtle SurfaceBox: the asset the box is for (the I() after it); Line: the asset drawn
  // along the line (UINT32_MAX: a tube).
  uint32_t asset = 0;
  InstanceMode mode = InstanceMode::Plain;
  // Instance: CityEngine's i(asset, upAxisOfGeometry, insertMode): zUp turns the asset -90
  // degrees about X before it is fitted (runtime/insert_fit.h).
  InsertFit insertFit = InsertFit::AlignSizeAndPosition;
  bool zUp = false;
  // Uv: CGA's uv set (texture layer, 0..9) the operation acts on; Copy: the set copied into.
  uint8_t uvSet = 0;
  // Instance: the symbol the instance is recorded under (a .cga leaf after the insert,
  // `i("tree.obj") Tree.`), without parameters; kPlacingSymbol: the shape that places it.
  static constexpr uint32_t kPlacingSymbol = UINT32_MAX;
  uint32_t recordAs = kPlacingSymbol;
  bool repeat = false;  // Subdiv `{ ... }*`: its parts repeat as a pattern along the axis
  // Subdiv from a CityEngine `.cga` split: CityEngine's sizing (rt::cga::cityEngineSizes:
  // the rest left empty, overflow cut) instead of R002 when the sizes do not fill the scope.
  bool cityEngineSizing = false;
  std::vector<Expr> args;
  std::vector<Size> sizes;
  std::vector<Block> bodies;
  // Comp and Offset with labelled parts (`Comp("f"){ front: A | side: B }`,
  // `Offset(2){ inside: A | border: B }`): each body's label, a string id; empty when the
  // parts are not labelled.
  std::vector<uint32_t> partLabels;
  // Footprint with holes: the index in `args` where each hole's corners start (ascending).
  std::vector<uint32_t> ringStarts;
  std::string name;  // Unsupported: the construct; also the source spelling of commands
  std::string why;   // Unsupported: what it waits for
};

// ---------------------------------------------------------------- rules and module

struct Param {
  std::string name;
  Type type = Type::Num;
  uint32_t slot = 0;
};

// One module of a context pattern; symbol ~0u with bracket 1/-1 stands for '[' / ']'.
struct ContextModule {
  uint32_t symbol = ~0u;
  int bracket = 0;
  std::vector<uint32_t> paramSlots;  // where the matched module's parameters go
};

struct Alternative {
  Expr probability;  // weight; alternatives of one shape are normalised at run time
  Block ops;
  Loc loc;
};

// A parallel derivation's rules by when they apply (lpfg, L-Py): productions at each
// step; decompositions after each step until none applies; homomorphisms (L-Py's
// interpretation rules) only on the way to the turtle, leaving the string as it was.
enum class RuleSection : uint8_t { Production, Decomposition, Homomorphism };

struct Rule {
  uint32_t symbol = 0;
  std::string label;  // user label or "<symbol>#<n>"
  int priority = 0;
  RuleSection section = RuleSection::Production;
  Loc loc;
  std::vector<Param> params;  // predecessor params first, then context params
  uint32_t slotCount = 0;     // size of the parameter block
  std::vector<ContextModule> left, right;
  bool hasGuard = false;
  Expr guard;
  std::vector<Alternative> alternatives;
  bool weighted = false;  // some branch writes a probability (`: 0.3`)
};

struct Symbol {
  std::string name;
  std::vector<Type> paramTypes;
  uint32_t slotCount = 0;       // sum of slot widths
  std::vector<uint32_t> rules;  // indices into Module::rules, in source order: its productions
  std::vector<uint32_t> decompositions, homomorphisms;  // its rules of those sections, likewise
  int priority = 0;             // highest priority among its rules
  // Several rules with a guard or a context and none writes a probability: the first that
  // applies is taken (CGA's case, lpfg's first matching production), not one at random.
  bool firstApplicable = false;
  bool firstApplicableDecomposition = false, firstApplicableHomomorphism = false;  // the same per section
};

// An attr's annotation (`@Range(0, 10)` in a .cga file): metadata for inspectors, no
// effect on deriving.
struct AttrAnnotation {
  std::string name;
  std::vector<std::pair<std::string, std::string>> args;  // (key or "", value text)
};

struct Attr {
  std::string name;
  Type type = Type::Num;
  Expr value;  // constant default; `--set` replaces it
  std::vector<AttrAnnotation> annotations;
  // An import's attr set from the importer's attrs (`m.floor_height = floor_height`):
  // computed from their values (--set, a lot's properties included) unless --set names
  // this attr itself; `value` is its default.
  bool fromImporter = false;
  Expr importerValue;
};

enum class DeriveMode : uint8_t { BreadthFirst, DepthFirst, Parallel };

// The colours `'` steps through unless `turtle colors "..."` says: browns, greens, a
// yellow, a red, a white (a plant's bark, leaves, flowers).
std::vector<std::array<float, 3>> defaultTurtleColors();

// What a turtle segment (F) is drawn as: `turtle segments "tubes";`.
enum class TurtleSegments : uint8_t {
  Cylinders,  // the built-in capped cylinder (32 sides, 128 triangles)
  Tubes,      // an open tube of `sides` sides (2 x sides triangles)
  Ribbons,    // a flat strip in the turtle's X-Y plane (2 triangles)
  Lines,      // a line segment (no triangles; glTF LINES, OBJ l, PLY edge)
};

struct TurtleSettings {
  double angle = 90.0;  // default turn for + - & ^ \ / without argument (degrees)
  double step = 1.0;    // default length for F and f without argument
  double width = 0.1;   // initial segment width
  TurtleSegments segments = TurtleSegments::Cylinders;
  int sides = 8;        // Tubes: sides around
  // ABOP's colour index (`'`): colour i >= 1 is colors[(i - 1) % size], in [0,1].
  std::vector<std::array<float, 3>> colors = defaultTurtleColors();
};

// An environment declaration the runtime must honour or refuse (surface, field, texture).
struct EnvDecl {
  std::string kind;  // "surface" | "field" | "texture"
  std::string name;
  std::string detail;
  Loc loc;
};

// How collision-tested instancing decides that two instances collide (FGSG §4.4), set
// by `collision ...;`: the exact meshes (default), or their centres closer than
// `radius` (Euclidean; geodesic on a surface, which on the plane is the same).
// Distance: the meshes come closer than `radius` (a clearance; FGSG §4.4's distance-field test).
enum class CollisionMetric : uint8_t { Mesh, Centre, Geodesic, Distance };

struct CollisionSettings {
  bool all = false;  // `collision all;`: every I() is tested as IC (FGSG's global flag)
  // `collision omit;`: a collision drops only the colliding instance (a Lock: its set) and
  // the production goes on; false (`cull`, the default): the rest of the production goes.
  bool omit = false;
  CollisionMetric metric = CollisionMetric::Mesh;
  double radius = 0.0;  // Centre / Geodesic / Distance: the distance below which two collide
  Loc loc;              // the declaration (line 0: none)
};

// `surface "bunny.off";` or `surface torus(2, 0.6);`: what the grammar grows on (none:
// the plane). Arguments are constants, evaluated by the compiler.
struct SurfaceSpec {
  bool present = false;
  std::string path;       // a mesh file, as written (relative to the grammar's folder)
  std::string generator;  // or a procedural surface: torus sphere plane genus2 cylinder
  std::vector<double> args;
  Loc loc;
};

// One item of a field design block, `wedge at (0.2, 0.1, 0.9) decay 2;`: its kind and its
// words with their constant values (a number: one value; a vector: three; none: empty).
struct FieldDesignSpec {
  std::string kind;  // regular wedge trisector node centre saddle smooth
  std::vector<std::pair<std::string, std::vector<double>>> words;  // keyword -> values
  Loc loc;
};

// `field F1 = tensor("foot.tfield");`, `field F2 = design tensor { ... };`,
// `field K = curvature;`. Listed in declaration order; a field query names its field
// through Module::environment (kind "field", same name).
struct FieldSpec {
  std::string name;
  std::string source;  // "file" | "design" | "curvature" | "image" | "expression"
  std::string kind;    // "tensor" | "vector" | "scalar" (curvature, image: "tensor")
  std::string path;    // file and image sources
  std::vector<FieldDesignSpec> design;
  // source "expression" (`scalar(EXPR)`): one number expression, computed at each vertex
  // with its position in the parameters surfacePointParams() names.
  std::vector<Expr> expression;
  Loc loc;
};

// The parameters a scalar field's expression reads at a vertex: x, y, z in slots 0..2.
const std::vector<Param>& surfacePointParams();

// `tileset NAME { locus ...; section ...; orientations ...; symbols "..."; }`: Chan & Hui's
// tiles for Evolve, as constants. The runtime checks them as a tile set (validateTileSet).
struct TileCurveSpec {
  std::string name;
  bool cubic = false;  // a cubic Bezier (4 points), else a polyline
  std::vector<std::array<double, 2>> points;
  Loc loc;
};
struct TileSetSpec {
  std::string name;
  std::vector<TileCurveSpec> loci, sections;
  std::vector<int> orientations;  // degrees; empty: all four
  std::string symbols;            // empty: A, B, C, ...
  // GA settings for Evolve with these tiles (population, max_generations, threshold,
  // weights, crossover, mutation, parents, elite), as constants; the rest keep defaults.
  std::vector<std::pair<std::string, std::vector<double>>> settings;
  Loc loc;
};

struct Module {
  std::string sourceName;
  std::vector<Symbol> symbols;
  std::vector<Rule> rules;
  std::vector<Attr> attrs;
  std::vector<std::string> strings;
  std::vector<std::string> assets;  // as written: "torus", "wall.obj"
  Block axiom;
  DeriveMode mode = DeriveMode::BreadthFirst;
  int steps = 0;  // parallel derivation steps
  // `derive breadthfirst N;` / `derive depthfirst N;`: the grammar's own depth bound,
  // shapes at depth >= N stay terminal (as --max-depth N, without its warning); -1: none.
  int depthBound = -1;
  // `derive parallel n;` (or a depth bound) given by an attr: its index; the count is
  // that attr's value when the grammar runs (--set n=9), steps / depthBound its default.
  // -1: the count is a constant.
  int countAttr = -1;
  // lpfg's and L-Py's `maximum depth:`: at most this many passes of the decomposition
  // (homomorphism) rules after each step (before the turtle).
  int decompositionDepth = 1;
  int homomorphismDepth = 1;
  // A `.cga` grammar: each lot (and the Footprint of its start) is CityEngine's initial
  // shape, a face in its scope's XZ plane with x along its first edge and y up
  // (rt::cga::polygonOnGround), not fgsg's Z-up footprint.
  bool cityEngineLots = false;
  TurtleSettings turtle;
  // `#ignore: + - F;`: symbols context matching steps over (commands are always skipped).
  std::vector<uint32_t> contextIgnored;
  CollisionSettings collision;
  SurfaceSpec surface;
  std::vector<FieldSpec> fields;
  std::vector<TileSetSpec> tileSets;
  std::vector<EnvDecl> environment;
  // The Comp parts' labels (string ids), each once, in the order the lowering met them,
  // and beside each the name comp.sel gives it (rt::cga::compSelectorName, interned): a
  // shape's Place::compSel is 1 + its index here (at most 255 of them; past that, "").
  std::vector<uint32_t> compSelectorLabels, compSelectors;

  uint32_t internString(const std::string& s);
  uint32_t internAsset(const std::string& s);
  int findSymbol(const std::string& name) const;
  // A symbol named at run time (a Synthesize label, an Evolve locus) by a rule of symbol
  // `from`: inside an imported module (`m.Land`) its own `m.name` first, then each enclosing
  // module's, then `name` itself.
  int findSymbolFrom(uint32_t from, const std::string& name) const;
  int findAttr(const std::string& name) const;
};

// Whether any op of the grammar (its rules, its axiom, their bodies) satisfies `pred`.
bool anyOp(const Module& m, const std::function<bool(const Op&)>& pred);

// CGA's geometry commands: they give shapes geometry of their own (a split piece, a face,
// a solid, a footprint polygon).
bool isCgaGeometryOp(OpKind kind);
// A sequential grammar that uses them is a CGA grammar: each shape of a symbol without
// rules (a leaf) outputs its own geometry, as CGA does. Elsewhere leaves place nothing.
bool leavesOutputGeometry(const Module& m);

}  // namespace fgsg::ir
