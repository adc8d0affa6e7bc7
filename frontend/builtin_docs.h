// The reference text of every builtin name, in one table: the commands (keyed by
// CommandInfo::name), functions (FunctionInfo::name), queries (Scope.sx, Shape.*,
// Geometry.*, Feature.*, Lot.*, a field's members) and the .cga dialect's CityEngine
// operations, functions and shape attributes with the fgsg builtin each becomes.
// `fgsg lsp` hovers with it, and docs/language.md's "Builtin reference" is generated from
// it (`fgsg builtin-reference`; tests/docs/check_builtin_reference.py keeps them equal).
#pragma once

#include <span>
#include <string>

namespace fgsg::frontend {

enum class BuiltinDocKind {
  Command,       // a successor's command: Subdiv, T, Extrude ...
  Function,      // an expression's function: sin, Rand, clamp ...
  Query,         // an object's member: Scope.sx, Shape.splitIndex, Geometry.area, Feature.edge, Lot.area
  FieldMember,   // a declared field's member, keyed without the field: "vector1" (F1.vector1)
  Surface,       // a procedural surface of `surface NAME(...);`: torus, sphere, plane ...
  FieldSource,   // what `field F = ...;` is made from: tensor("file"), curvature, design ...
  CgaOperation,  // .cga: split, extrude, comp, setback ...
  CgaFunction,   // .cga: rand, p, rint, geometry.area ...
  CgaAttribute,  // .cga: scope.sx, split.index, comp.total ...
};

struct BuiltinDoc {
  BuiltinDocKind kind;
  const char* name;       // as written in a grammar (a field member without its field)
  const char* signature;  // nullptr for a command and a surface: CommandInfo's or SurfaceGeneratorInfo's
  const char* doc;        // one or two sentences: what it does, units, defaults
  const char* fgsgName;   // a .cga name's fgsg command, function or query; else nullptr
};

std::span<const BuiltinDoc> builtinDocs();
// The entry of that kind and name, or nullptr.
const BuiltinDoc* findBuiltinDoc(BuiltinDocKind kind, const std::string& name);
// How the name is called: the entry's signature, a command's from its CommandInfo, a
// surface's from its SurfaceGeneratorInfo (frontend/sema_environment.h).
std::string builtinDocSignature(const BuiltinDoc& doc);
// docs/language.md's "Builtin reference" section, between its markers.
std::string builtinReferenceMarkdown();

}  // namespace fgsg::frontend
