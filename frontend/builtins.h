// The names the language gives meaning to: scope commands and operations that may
// appear in successors, functions callable in expressions, and query objects. One table
// each, shared by semantic analysis and lowering so both agree on every name.
#pragma once

#include <span>
#include <string>
#include <vector>

namespace fgsg::frontend {

enum class CommandId {
  Translate, Rotate, RotateX, RotateY, RotateZ, RotateNormal, Scale,
  Instance, InstanceCollide, InstanceMerge,
  Subdiv, Repeat, Comp, Extrude, Footprint, Offset, Roof, Lock, Center, Color, Texture,
  Material,  // CGA's material attributes (roughness, metallic, opacity, colour components, normal map)
  UvOperation,  // CGA's uv operations on the texture projection (SetupProjection, ScaleUV, ...)
  Forward, Move,  // turtle F and f written as identifiers
  Marching, Branch, Line, LineSeg, Synthesize, Evolve, Cells,
  BrickBond, HeaderRow, ArchBricks, RandomStones,  // Cells' pattern generators
  EnglishBond, FlemishBond, HeaderBond, Shingles,
  Report, Print,  // CGA's report(key, value) (collected per start shape) and print(value)
  Label,          // CGA's label("name"): the shape a labelled context shape (occlusion queries)
  ShapeOperation,  // CityEngine's footprint-shaping and scope operations (frontend/shape_operations.h)
};

enum class BodyRule {
  None,        // no { } allowed
  PerSize,     // one body part per size argument (Subdiv)
  One,         // exactly one part (Repeat, Comp, Roof)
  AtLeastOne,  // Lock, Branch, Marching
  Optional,    // at most one part (the cell generators' cell symbol)
};

struct CommandInfo {
  CommandId id;
  const char* name;
  int minArgs;
  int maxArgs;  // -1: unbounded
  BodyRule body;
  const char* signature;  // for messages: "T(tx, ty, tz)"
  const char* laterIssue;  // non-null: parses and type-checks, but its runtime is not here yet
};

// The command a successor identifier names, or nullptr for a shape symbol. Accepts the
// FGSG paper's upper-case spellings RX RY RZ.
const CommandInfo* findCommand(const std::string& name);

// Material(property, value)'s property words ("roughness", "metallic", "opacity", "color.r",
// "color.g", "color.b", "emissive.r", "emissive.g", "emissive.b", then the images "normalmap",
// "colormap", "bumpmap", "dirtmap", "specularmap", "opacitymap", "emissivemap", "occlusionmap",
// "roughnessmap", "metallicmap"), numbered as ir::MaterialProperty; -1: none.
int materialProperty(const std::string& name);
const char* materialPropertyName(int property);  // nullptr: no such number
bool materialPropertyIsImage(int property);       // an image file (the maps), not a number
const char* materialPropertyList();  // for messages: "roughness, metallic, ..."
// The uv command `name` (SetupProjection, ScaleUV, ...) numbered as ir::UvOp; -1: none.
int uvOperation(const std::string& name);
// Every command, in the table's order (editors complete and describe them: fgsg lsp).
std::span<const CommandInfo> allCommands();

struct FunctionInfo {
  const char* name;
  int minArgs;
  int maxArgs;
};
// Math functions and Rand; nullptr when unknown. Names are matched exactly, with
// `Rand` and `rand` both accepted.
const FunctionInfo* findFunction(const std::string& name);
std::span<const FunctionInfo> allFunctions();

// The members Feature answers inside Cells (Feature.edge, Feature.label("window") ...),
// with whether the value is a number (else a truth value) and whether it takes the one
// string argument.
bool isFeatureMember(const std::string& member, bool& isNumber, bool& takesString);
// Those members, each once (their docs: frontend/builtin_docs.cpp).
std::vector<std::string> featureMemberNames();

// The members a field answers (F1.vector1 ...), with whether the value is a vector.
bool isFieldMember(const std::string& member, bool& isVector);
std::vector<std::string> fieldMemberNames();

}  // namespace fgsg::frontend
