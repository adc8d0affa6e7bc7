// Semantic analysis: resolves every name (rule parameters, constants, attributes,
// functions, queries, commands, shape symbols), infers parameter types, checks arity,
// types, split bodies and probabilities, and warns about symbols without rules and
// rules that can never fire. Lowering to IR reads its result and trusts it.
#pragma once

#include "frontend/ast.h"
#include "frontend/diagnostics.h"

#include <array>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

namespace fgsg::frontend {

enum class ValueType { Unknown, Num, Bool, Str, Vec3 };
const char* valueTypeName(ValueType t);

struct ConstValue {
  ValueType type = ValueType::Num;
  double num = 0.0;  // Num, Bool (0/1)
  std::string str;
  double vec[3] = {0, 0, 0};
};

struct SymbolInfo {
  std::string name;
  std::vector<ValueType> params;
  bool arityKnown = false;
  std::vector<size_t> rules;  // indices into Program::rules
  SourceRange firstUse;
  bool reachable = false;
};

struct AttrInfo {
  std::string name;
  ConstValue value;
  SourceRange range;
  std::vector<AttrAnnotation> annotations;  // from a .cga file's @Range, @Enum ...
  // An import's attr set from the importer's attrs (`m.floor_height = floor_height`): the
  // expression it follows at run time (`value` is its default); null for a constant.
  const Expr* importerValue = nullptr;
};

// `tileset NAME { ... }` checked: its curves as constant points, in the order written.
// Whether the tiles make a valid tile set (points inside the unit square, cross-sections
// from (-1, 0) to (1, 0), one letter per locus x section) is the runtime's rule
// (rt::evolve::validateTileSet), asked by `fgsg check` and by Evolve.
struct TileCurveInfo {
  std::string name;  // may be empty
  bool cubic = false;  // a cubic Bezier (4 points), else a polyline
  std::vector<std::array<double, 2>> points;
  SourceRange range;
};
struct TilesetInfo {
  std::string name;
  std::vector<TileCurveInfo> loci, sections;
  std::vector<int> orientations;  // degrees as written; empty: all four
  std::string symbols;            // empty: A, B, C, ...
  // The GA's settings it gives (`population 100;` -> {"population", {100}}), in order.
  std::vector<std::pair<std::string, std::vector<double>>> settings;
  SourceRange range;
};

// How an identifier inside a rule resolved.
struct NameRef {
  enum Kind { Param, Const, Attr, Builtin } kind = Const;
  size_t index = 0;   // Param: position in the rule's parameter list; Attr: attr index
  ConstValue value;   // Const, Builtin (pi)
};

// `surface ...;` evaluated: a mesh file or a procedural surface with constant arguments.
struct SurfaceInfo {
  bool present = false;
  std::string path;       // a mesh file, as written
  std::string generator;  // or: torus sphere plane genus2 cylinder
  std::vector<double> args;
  SourceRange range;
};

// One item of a field design block, evaluated: `center at vertex 120 decay 2;` becomes
// kind "centre" with words ("vertex", {120}), ("decay", {2}); `smooth 300;` kind
// "smooth" with ("iterations", {300}); `at (x, y, z)` is ("at", {x, y, z}).
struct FieldDesignInfo {
  std::string kind;
  std::vector<std::pair<std::string, std::vector<double>>> words;
  SourceRange range;
};

// `field NAME = ...;` evaluated: source "file" | "design" | "curvature" | "image" |
// "expression", kind "tensor" | "vector" | "scalar" (curvature, image: "tensor").
struct FieldInfo {
  std::string name;
  std::string source;
  std::string kind;
  std::string path;
  std::vector<FieldDesignInfo> design;
  // source "expression": `scalar(EXPR)`, a number computed at each vertex of the surface
  // from its position x, y, z (surfacePointNames), consts and attrs. Points into the AST.
  const Expr* expression = nullptr;
  SourceRange range;
};

// The names a scalar field's expression reads at each vertex: x, y, z (its position).
const std::vector<std::pair<std::string, ValueType>>& surfacePointNames();

struct SemaResult {
  std::vector<SymbolInfo> symbols;
  std::map<std::string, size_t> symbolIndex;
  std::vector<AttrInfo> attrs;
  std::map<std::string, ConstValue> constants;
  std::vector<std::string> fields, textures;  // declared names (for queries)
  SurfaceInfo surface;                 // the first `surface` declaration, if any
  std::vector<FieldInfo> fieldSpecs;   // the fields that check out, in declaration order
  std::vector<TilesetInfo> tilesets;   // the tilesets that check out, in declaration order
  std::unordered_map<const Expr*, ValueType> exprTypes;
  std::unordered_map<const Expr*, NameRef> names;  // Ident expressions
  // Per rule: the names and types of its parameters (predecessor, then left and right
  // context modules in order).
  std::vector<std::vector<std::pair<std::string, ValueType>>> ruleParams;
  std::string startSymbol;  // the symbol the derivation starts from when no axiom is given
  std::string mode = "breadthfirst";
  int steps = 0;
  int depthBound = -1;  // `derive breadthfirst N;`: shapes at depth >= N stay terminal; -1: none
  // `derive parallel n;` with an attr n: the attr that gives N when the grammar runs
  // (--set n=9); steps / depthBound hold its default. Empty: N is a constant.
  std::string countAttr;
  // `#ignore: + - F;`: the symbols of the grammar context matching steps over.
  std::vector<std::string> contextIgnored;
  double turtleAngle = 90.0, turtleStep = 1.0, turtleWidth = 0.1;
  std::string turtleSegments = "cylinders";  // `turtle segments "tubes";`
  int turtleSides = 8;
  std::vector<std::array<float, 3>> turtleColors;  // `turtle colors "..."`; empty: the default palette
  // `collision ...;` (the first declaration): every I() tested (all), and the metric
  // "mesh", "centre", "geodesic" or "distance" with its radius (0 for mesh).
  bool collisionDeclared = false;
  bool collisionAll = false;
  bool collisionOmit = false;  // `collision omit;`: a collision drops the instance only
  std::string collisionMetric = "mesh";
  double collisionRadius = 0.0;
  SourceRange collisionRange;

  int findSymbol(const std::string& name) const {
    auto it = symbolIndex.find(name);
    return it == symbolIndex.end() ? -1 : static_cast<int>(it->second);
  }
};

// Returns false when errors were reported.
bool analyze(const Program& program, SemaResult& out, Diagnostics& diags);

// True when `item` creates a shape (as opposed to running a command): every identifier
// that is not a command, and a command name the grammar gives rules to (F in FGSG
// Fig. 1, S in Fig. 11).
bool isShapeItem(const Item& item, const SemaResult& sema);

}  // namespace fgsg::frontend
