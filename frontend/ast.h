// The abstract syntax tree of a .fgsg program. Built from the ANTLR parse tree by
// ast_builder.cpp with typed functions; every node carries its source range so that
// semantic analysis and later passes can point at the text that caused a problem.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fgsg::frontend {

struct SourceLoc {
  int line = 0;  // 1-based
  int col = 0;   // 1-based, in characters
};

struct SourceRange {
  SourceLoc begin;
  SourceLoc end;  // last character, inclusive
};

// The name a symbol is shown by (the IR's symbol: instances, scene nodes, reports). The
// .cga front end marks a rule named like an fgsg command (`Roof`, `Color` ...) with a '$'
// after it (`Roof$`, its leaf `Roof$.`, a helper `Roof$$1`), which no name written in a
// .cga or .fgsg file can hold: shown, the mark is dropped (`Roof`, `Roof.`, `Roof$1`).
// '$' alone (the turtle's roll) and a helper's `$n` stay.
inline std::string symbolDisplayName(const std::string& name) {
  std::string out;
  out.reserve(name.size());
  for (size_t i = 0; i < name.size(); ++i) {
    const bool mark = name[i] == '$' && i > 0 && (i + 1 == name.size() || name[i + 1] < '0' || name[i + 1] > '9');
    if (!mark) out += name[i];
  }
  return out;
}

// ---------------------------------------------------------------- expressions

enum class ExprKind {
  Number,     // 3, 0.5            -> number
  Bool,       // true, false       -> boolean
  String,     // "street"          -> text
  Ident,      // x, building_height, pi
  Unary,      // op in text: "-", "!", "+"
  Binary,     // op in text: + - * / % ^ == != < <= > >= && ||
  Ternary,    // args[0] ? args[1] : args[2]
  Call,       // text(args...)          e.g. Rand(1, 2), sin(x)
  Member,     // object.text or object.text(args...) e.g. Scope.sx, F1.vector1,
              // Shape.visible("street"), context.mask(texCoord); `hasCall` tells which
  Vector,     // (a, b, c) literal
  RelSize,    // 1r: a size relative to the remaining space (number holds 1)
  FloatSize,  // ~e: a floating size, args[0] is e
};

struct Expr;
using ExprPtr = std::unique_ptr<Expr>;

struct Expr {
  ExprKind kind = ExprKind::Number;
  SourceRange range;
  double number = 0.0;
  bool boolean = false;
  std::string text;    // identifier, string literal, operator or member name
  std::string object;  // for Member: the left side ("Scope", "F1", "context")
  bool hasCall = false;
  std::vector<ExprPtr> args;
};

// ---------------------------------------------------------------- successors

struct Successor;

enum class ItemKind {
  Call,     // an identifier, optional (args), optional { body | body }: a shape symbol
            // or a command (T, S, Subdiv, I, Lock, ...); which one is decided by name
  Turtle,   // a turtle symbol + - & ^ \ / | ! $ with optional (args); `name` is the symbol
  Bracket,  // [ children ]
};

struct Item {
  ItemKind kind = ItemKind::Call;
  SourceRange range;
  std::string name;
  std::vector<ExprPtr> args;
  bool hasBody = false;
  std::vector<Successor> body;  // parts between '|' or ',' inside { }
  bool repeatPattern = false;   // `{ ... }*`: the parts repeat as a pattern (CGA's repeat split)
  std::vector<Item> children;   // Bracket contents
  std::string surface;          // the turtle symbol `~`: the asset of the predefined surface
  // A Subdiv from a CityEngine `.cga` split: sizes are laid out as CityEngine does
  // (absolute sizes that do not fill the scope leave the rest empty, those that overflow
  // are cut) instead of fgsg's "parts must fill the scope" (R002).
  bool cityEngineSizing = false;
  // An I() that a .cga leaf follows (`i("tree.obj") Tree.`): the leaf's symbol, which the
  // instance is recorded under (CityEngine's shape after the insert is that leaf); empty:
  // the shape whose successor places it.
  std::string recordAs;
};

struct Successor {
  SourceRange range;
  bool epsilon = false;  // written as ε / epsilon / NIL: explicitly empty
  std::vector<Item> items;
  // A body part's `front:` (Comp's labelled parts); empty when it has none.
  std::string selector;
  SourceRange selectorRange;
  // A body part's size label `~3:` (CGA's split syntax); null when it has none. A Subdiv
  // whose parts all carry sizes (or names: `floor_h: Floor`) gets them as its arguments.
  ExprPtr size;
};

// ---------------------------------------------------------------- rules

struct ParamDecl {
  std::string name;
  SourceRange range;
};

// One module of a predecessor or context pattern: A, A(x, y). In a right context the
// names "[" and "]" stand for a bracket (ABOP context matching skips/enters branches).
struct ModulePattern {
  std::string name;
  SourceRange range;
  std::vector<ParamDecl> params;
};

struct Branch {
  SourceRange range;
  Successor successor;
  ExprPtr probability;  // null: weight 1
};

// The section a rule is written in (lpfg's `decomposition:` / `homomorphism:`, L-Py's
// `interpretation:`; everything else, and after `production:`, is a production).
enum class RuleSection : uint8_t { Production, Decomposition, Homomorphism };

struct Rule {
  SourceRange range;
  RuleSection section = RuleSection::Production;
  std::string label;  // "1", "p4" or empty
  int priority = 0;   // from the last `priority N:` before the rule
  std::vector<ModulePattern> leftContext;   // lc < pred
  ModulePattern predecessor;
  std::vector<ModulePattern> rightContext;  // pred > rc
  ExprPtr guard;                            // null: always true
  std::vector<Branch> branches;             // one or more `~> successor : prob`
  bool imported = false;                    // from a module: the importer may not use it (no W002)
};

// ---------------------------------------------------------------- declarations

// One annotation of an attr, from a CityEngine `.cga` file: `@Range(min=0, max=10)` is
// name "Range" and args [("min", "0"), ("max", "10")]; a value without a key has an empty
// key; strings keep their quotes off.
struct AttrAnnotation {
  std::string name;
  std::vector<std::pair<std::string, std::string>> args;
};

struct ValueDecl {  // const name = expr;   attr name = expr;
  SourceRange range;
  bool isAttr = false;
  std::string name;
  ExprPtr value;
  std::vector<AttrAnnotation> annotations;  // metadata for inspectors (sliders, enums ...)
  // An imported attr set by the importer (`import m : "m.cga"` then `m.floor_height =
  // floor_height`): its value may read the importer's attrs, and follows them.
  bool fromImporter = false;
};

struct SurfaceDecl {  // surface "bunny.off";   surface torus(2, 0.6);
  SourceRange range;
  SourceRange target;     // the path string, or the generator with its arguments
  SourceRange nameRange;  // the generator's name (the path string for a file)
  std::string path;       // non-empty for a file
  std::string generator;  // non-empty for a procedural surface
  std::vector<ExprPtr> args;
};

// One statement of a field design block: `wedge at (0.2,0.1,0.9) decay 2;` becomes
// kind "wedge" and words [("at", vector expr), ("decay", 2)]. A word without a value
// has a null expr; a value without a keyword has an empty keyword. A bare name is always
// a keyword here (`decay d` is two words); sema reads a name that is a const as the
// previous keyword's value.
struct FieldDesignWord {
  SourceRange range;  // the keyword and its value
  std::string keyword;
  ExprPtr value;
};
struct FieldDesignItem {
  SourceRange range;
  SourceRange kindRange;
  std::string kind;
  std::vector<FieldDesignWord> words;
};

struct FieldDecl {
  SourceRange range;
  SourceRange nameRange;
  SourceRange sourceRange;    // everything after '='
  SourceRange functionRange;  // tensor / vector / curvature / the call's name
  std::string name;
  std::string source;     // "file" | "design" | "curvature" | "call"
  std::string function;   // tensor / vector for file and design, or the call's name
  std::string path;       // for file sources: tensor("foot.tfield")
  std::vector<ExprPtr> args;
  std::vector<FieldDesignItem> design;
};

struct TextureDecl {  // texture mask = "paint.png";
  SourceRange range;
  std::string name;
  std::string path;
};

// One item of a tileset: `locus arc = cubic((0.5, 0), ...);` is kind "locus", name "arc"
// and one value (the call); `orientations 0, 90;` kind "orientations", no name, two values.
struct TilesetItem {
  SourceRange range;
  SourceRange kindRange;
  SourceRange nameRange;  // empty name: none written
  std::string kind;
  std::string name;
  std::vector<ExprPtr> values;
};

struct TilesetDecl {  // tileset ornament { locus ...; section ...; orientations ...; symbols "AB"; }
  SourceRange range;
  SourceRange nameRange;
  std::string name;
  std::vector<TilesetItem> items;
};

struct DeriveDecl {  // derive parallel 5;  derive depthfirst;  derive breadthfirst;
  SourceRange range;
  std::string mode;
  ExprPtr steps;  // null unless given
};

struct TurtleDecl {  // turtle angle 60 step 1 width 0.05;
  SourceRange range;
  std::vector<std::pair<std::string, ExprPtr>> settings;
};

struct IgnoreDecl {  // #ignore: + - F;   #consider: A B;   (frontend/context_lists.h)
  SourceRange range;
  bool consider = false;  // the modules listed are the only ones context matching sees
  std::vector<std::pair<std::string, SourceRange>> symbols;
};

// One word of a `collision` declaration: a name (`all`, `centre` ...) or a number (a
// radius; negative when written with '-').
struct CollisionWord {
  SourceRange range;
  std::string word;  // empty for a number
  double number = 0.0;
  bool isNumber() const { return word.empty(); }
};

struct CollisionDecl {  // collision all;  collision centre 0.3;  collision all geodesic 0.25;
  SourceRange range;
  std::vector<CollisionWord> words;
};

// import "std/cga/facade" as facade (floor_height = 3.5);  (frontend/imports.cpp)
struct ImportDecl {
  SourceRange range;
  SourceRange pathRange;
  std::string path;   // as written
  std::string alias;  // empty: the module's names come unqualified
  std::vector<std::pair<std::string, ExprPtr>> settings;  // the module's attrs, set here
  std::vector<SourceRange> settingRanges;
  // CityEngine's import (a `.cga` importer): this file's attrs pass their values to the
  // module's attrs of the same names (frontend/imports.cpp), but for those named in the
  // import's list (`import m : "m.cga" (a, b)`), or all of them (`()`: protectAll).
  bool propagateAttrs = false;
  bool protectAll = false;
  std::vector<std::string> protectedAttrs;
  std::vector<SourceRange> protectedRanges;
  // CityEngine's styles list (`import m (Wide, Tall) : "m.cga"`): only those styles of the
  // module come here; empty: all of them.
  std::vector<std::string> styles;
  std::vector<SourceRange> styleRanges;
};

struct AxiomDecl {  // axiom: S(20,0,12) footprint;
  SourceRange range;
  Successor successor;
};

// A `.cga` file's function or const (CityEngine's functions; the file itself inlines them
// where used): the body with its k-th parameter written as the Ident "#k" (no CGA name
// can hold a '#'), so that an importer's `alias.name(args)` takes a copy in its place
// (frontend/imports.cpp). A body that does not translate keeps its first error instead,
// reported where an importer calls it.
struct FunctionDecl {
  SourceRange range;  // the name in its declaration
  std::string name;
  size_t params = 0;
  ExprPtr body;  // null: `errorCode`, `error` at `errorAt`
  std::string errorCode, error;
  SourceRange errorAt;
};

struct Program {
  std::string fileName;
  std::vector<ImportDecl> imports;
  std::vector<ValueDecl> values;
  std::vector<Rule> rules;
  std::vector<SurfaceDecl> surfaces;
  std::vector<FieldDecl> fields;
  std::vector<TextureDecl> textures;
  std::vector<TilesetDecl> tilesets;
  std::vector<DeriveDecl> derives;
  std::vector<TurtleDecl> turtles;
  std::vector<IgnoreDecl> ignores;
  std::vector<CollisionDecl> collisions;
  std::vector<AxiomDecl> axioms;
  std::vector<FunctionDecl> functions;  // a .cga file's, for its importers
  // lpfg's and L-Py's `maximum depth: N` of the decomposition and homomorphism sections
  // (default 1, as L-Py's): how many times their rules are applied in a row.
  int decompositionDepth = 1;
  int homomorphismDepth = 1;
  // A `.cga` file: a lot is CityEngine's initial shape (scope x along its first edge, y up).
  bool cityEngineLots = false;
  // Rules that start derivations in CityEngine though not in this run: the @StartRule when
  // --start-rule names another. What they reach is not dead code (no W002).
  std::vector<std::string> otherStartRules;
  // A `.cga` file's style (`--start-rule Style$Rule`; empty: Default), which its imports
  // are read in too, and the styles it has: Default, its own and those its imports bring
  // (frontend/imports.cpp checks the chosen one against them once they are in).
  std::string cgaStyle;
  std::vector<std::string> cgaStyles;
};

}  // namespace fgsg::frontend
