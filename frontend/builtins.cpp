#include "frontend/builtins.h"

#include <cstring>
#include <iterator>
#include <string_view>
#include <unordered_map>

namespace fgsg::frontend {
namespace {

const CommandInfo kCommands[] = {
    {CommandId::Translate, "T", 3, 3, BodyRule::None, "T(tx, ty, tz)", nullptr},
    {CommandId::Rotate, "R", 3, 3, BodyRule::None, "R(ax, ay, az)", nullptr},
    {CommandId::RotateX, "Rx", 1, 1, BodyRule::None, "Rx(degrees)", nullptr},
    {CommandId::RotateY, "Ry", 1, 1, BodyRule::None, "Ry(degrees)", nullptr},
    {CommandId::RotateZ, "Rz", 1, 1, BodyRule::None, "Rz(degrees)", nullptr},
    {CommandId::RotateX, "RX", 1, 1, BodyRule::None, "RX(degrees)", nullptr},
    {CommandId::RotateY, "RY", 1, 1, BodyRule::None, "RY(degrees)", nullptr},
    {CommandId::RotateZ, "RZ", 1, 1, BodyRule::None, "RZ(degrees)", nullptr},
    {CommandId::RotateNormal, "RS", 1, 1, BodyRule::None, "RS(degrees)", nullptr},
    {CommandId::Scale, "S", 3, 3, BodyRule::None, "S(sx, sy, sz)", nullptr},
    // The same command for grammars whose shapes are named S (FGSG Fig. 11's glyphs).
    {CommandId::Scale, "Size", 3, 3, BodyRule::None, "Size(sx, sy, sz)", nullptr},
    {CommandId::Instance, "I", 1, 3, BodyRule::None,
     "I(\"asset\") or I(\"asset\", \"yUp\" or \"zUp\", \"alignSizeAndPosition\" or \"keepSizeAndPosition\" or "
     "\"keepSizeAlignPosition\")",
     nullptr},
    {CommandId::InstanceCollide, "IC", 1, 1, BodyRule::None, "IC(\"asset\")", nullptr},
    {CommandId::InstanceMerge, "IM", 3, 3, BodyRule::None, "IM(\"asset\", maxDist, maxAngle)",
     nullptr},
    {CommandId::Subdiv, "Subdiv", 2, -1, BodyRule::PerSize, "Subdiv(\"X\", s1, s2, ...){ a | b ... }",
     nullptr},
    // CityEngine's splitArea: the sizes are areas (ir::Op::str names it; sized as a .cga split).
    {CommandId::Subdiv, "SplitArea", 2, -1, BodyRule::PerSize,
     "SplitArea(\"X\", area1, area2, ...){ a | b ... }", nullptr},
    {CommandId::Repeat, "Repeat", 2, 4, BodyRule::One, "Repeat(\"X\", s){ tile }", nullptr},
    {CommandId::Comp, "Comp", 1, 1, BodyRule::One, "Comp(\"sidefaces\"){ face }", nullptr},
    {CommandId::Extrude, "Extrude", 1, 2, BodyRule::None, "Extrude(height)", nullptr},
    {CommandId::Footprint, "Footprint", 6, -1, BodyRule::None, "Footprint(x1, z1, x2, z2, x3, z3, ...) or Footprint(outline..., \"hole\", x1, z1, ...)", nullptr},
    {CommandId::Offset, "Offset", 1, 1, BodyRule::AtLeastOne, "Offset(distance){ inside: A | border: B }", nullptr},
    {CommandId::Roof, "Roof", 2, 6, BodyRule::One, "Roof(\"hipped\"[, \"byHeight\"], angle or height[, overhang[, gableOverhang[, edge]]]){ roof }", nullptr},
    {CommandId::Center, "Center", 1, 1, BodyRule::None, "Center(\"xyz\")", nullptr},
    {CommandId::Color, "Color", 1, 3, BodyRule::None, "Color(r, g, b) or Color(\"#rrggbb\")", nullptr},
    {CommandId::Texture, "Texture", 1, 3, BodyRule::None,
     "Texture(\"image.png\") or Texture(\"image.png\", tileWidth, tileHeight)", nullptr},
    {CommandId::Material, "Material", 2, 2, BodyRule::None,
     "Material(\"roughness\" or \"metallic\" or \"opacity\" or \"color.r\" or \"color.g\" or \"color.b\" or "
     "\"emissive.r\" or \"emissive.g\" or \"emissive.b\", value) or Material(\"normalmap\" or \"colormap\" or "
     "\"bumpmap\" or \"dirtmap\" or \"specularmap\" or \"opacitymap\" or \"emissivemap\" or \"occlusionmap\" or "
     "\"roughnessmap\" or \"metallicmap\", \"image.png\")",
     nullptr},
    // CGA's uv operations on the scope's texture projection, in ir::UvOp's order; the last
    // argument may name the uv set (0..9, CityEngine's texture layers; without it 0).
    {CommandId::UvOperation, "SetupProjection", 3, 4, BodyRule::None,
     "SetupProjection(\"xy\" or \"xz\" or \"yz\" or \"yx\" or \"zx\" or \"zy\", tileWidth, tileHeight, uvSet?)", nullptr},
    {CommandId::UvOperation, "ScaleUV", 2, 3, BodyRule::None, "ScaleUV(uFactor, vFactor, uvSet?)", nullptr},
    {CommandId::UvOperation, "TranslateUV", 2, 3, BodyRule::None, "TranslateUV(uOffset, vOffset, uvSet?)", nullptr},
    {CommandId::UvOperation, "RotateUV", 1, 2, BodyRule::None, "RotateUV(degrees, uvSet?)", nullptr},
    {CommandId::UvOperation, "TileUV", 2, 3, BodyRule::None, "TileUV(tileWidth, tileHeight, uvSet?)", nullptr},
    {CommandId::UvOperation, "NormalizeUV", 1, 2, BodyRule::None,
     "NormalizeUV(\"uv\" or \"uvUniform\" or \"u\" or \"v\", uvSet?)", nullptr},
    {CommandId::UvOperation, "DeleteUV", 0, 1, BodyRule::None, "DeleteUV(uvSet?)", nullptr},
    {CommandId::UvOperation, "ProjectUV", 0, 1, BodyRule::None, "ProjectUV(uvSet?)", nullptr},
    {CommandId::UvOperation, "CopyUV", 2, 2, BodyRule::None, "CopyUV(sourceUvSet, destinationUvSet)", nullptr},
    {CommandId::Lock, "Lock", 0, 0, BodyRule::AtLeastOne, "Lock{ A | B | ... }", nullptr},
    {CommandId::Forward, "F", 0, 1, BodyRule::None, "F(length)", nullptr},
    {CommandId::Move, "f", 0, 1, BodyRule::None, "f(length)", nullptr},
    {CommandId::Marching, "Marching", 3, 4, BodyRule::AtLeastOne,
     "Marching(length, angle, cond[, \"C1\" or \"C0\" or \"none\"]){ Top, Extruded }", nullptr},
    {CommandId::Branch, "Branch", 1, 1, BodyRule::AtLeastOne, "Branch(n){ A, B }", nullptr},
    {CommandId::Line, "Line", 0, 3, BodyRule::None, "Line(width, merge, \"asset\")", nullptr},
    {CommandId::LineSeg, "LineSeg", 0, 1, BodyRule::None, "LineSeg(length)", nullptr},
    {CommandId::Synthesize, "Synthesize", 4, 5, BodyRule::None,
     "Synthesize(\"example.txt\", nx, ny, nz) or Synthesize(\"example.obj\", nx, ny, nz, \"Part\")", nullptr},
    {CommandId::Evolve, "Evolve", 2, 5, BodyRule::None, "Evolve(tileset or \"tiles.json\", generation, k, p4, resolution)", nullptr},
    {CommandId::Cells, "Cells", 1, 3, BodyRule::AtLeastOne,
     "Cells(\"base.obj\", joint, mortar){ Feature } or Cells(joint, mortar){ Base | Feature }", nullptr},
    {CommandId::BrickBond, "BrickBond", 3, 4, BodyRule::Optional, "BrickBond(length, height, depth, flip){ Brick }",
     nullptr},
    {CommandId::HeaderRow, "HeaderRow", 3, 3, BodyRule::Optional, "HeaderRow(width, height, depth){ Header }",
     nullptr},
    {CommandId::ArchBricks, "ArchBricks", 3, 3, BodyRule::Optional, "ArchBricks(length, height, depth){ Voussoir }",
     nullptr},
    {CommandId::RandomStones, "RandomStones", 4, 4, BodyRule::Optional,
     "RandomStones(grid, maxWidth, maxHeight, depth){ Stone }", nullptr},
    {CommandId::EnglishBond, "EnglishBond", 3, 4, BodyRule::Optional, "EnglishBond(length, height, depth, flip){ Brick }",
     nullptr},
    {CommandId::FlemishBond, "FlemishBond", 3, 4, BodyRule::Optional, "FlemishBond(length, height, depth, flip){ Brick }",
     nullptr},
    {CommandId::HeaderBond, "HeaderBond", 3, 4, BodyRule::Optional, "HeaderBond(length, height, depth, flip){ Brick }",
     nullptr},
    {CommandId::Shingles, "Shingles", 3, 3, BodyRule::Optional, "Shingles(width, exposure, thickness){ Tile }",
     nullptr},
    {CommandId::Report, "Report", 2, 2, BodyRule::None, "Report(\"key\", value)", nullptr},
    {CommandId::Print, "Print", 1, 1, BodyRule::None, "Print(value)", nullptr},
    {CommandId::Label, "Label", 1, 1, BodyRule::None, "Label(\"name\")", nullptr},
    // CityEngine's footprint-shaping and scope operations (#44; frontend/shape_operations.h).
    {CommandId::ShapeOperation, "AlignScopeToAxes", 0, 1, BodyRule::None, "AlignScopeToAxes() or AlignScopeToAxes(\"y\")", nullptr},
    {CommandId::ShapeOperation, "AlignScopeToGeometry", 3, 3, BodyRule::None,
     "AlignScopeToGeometry(\"y\" or \"z\", faceIndex or \"largest\", edgeIndex or \"longest\")", nullptr},
    {CommandId::ShapeOperation, "RotateScope", 3, 3, BodyRule::None, "RotateScope(ax, ay, az)", nullptr},
    {CommandId::ShapeOperation, "MirrorScope", 3, 3, BodyRule::None, "MirrorScope(flipX, flipY, flipZ)", nullptr},
    {CommandId::ShapeOperation, "Mirror", 3, 3, BodyRule::None, "Mirror(flipX, flipY, flipZ)", nullptr},
    {CommandId::ShapeOperation, "Setback", 1, 1, BodyRule::AtLeastOne, "Setback(distance){ front: A | remainder: B }", nullptr},
    {CommandId::ShapeOperation, "SetbackToArea", 1, 1, BodyRule::AtLeastOne,
     "SetbackToArea(area){ all=: A | remainder: B }", nullptr},
    {CommandId::ShapeOperation, "SetbackPerEdge", 1, 1, BodyRule::AtLeastOne,
     "SetbackPerEdge(distance){ front: A | remainder: B } (distance evaluated on each edge)", nullptr},
    {CommandId::ShapeOperation, "ShapeL", 2, 2, BodyRule::AtLeastOne, "ShapeL(frontWidth, leftWidth){ shape: A | remainder: B }", nullptr},
    {CommandId::ShapeOperation, "ShapeU", 3, 3, BodyRule::AtLeastOne,
     "ShapeU(frontWidth, rightWidth, leftWidth){ shape: A | remainder: B }", nullptr},
    {CommandId::ShapeOperation, "ShapeO", 4, 4, BodyRule::AtLeastOne,
     "ShapeO(frontWidth, rightWidth, backWidth, leftWidth){ shape: A | remainder: B }", nullptr},
    {CommandId::ShapeOperation, "InnerRectangle", 0, 1, BodyRule::Optional,
     "InnerRectangle(\"scope\" or \"edge\") or InnerRectangle(\"scope\"){ shape: A }", nullptr},
    {CommandId::ShapeOperation, "Scatter", 3, 6, BodyRule::One,
     "Scatter(\"surface\" or \"volume\" or \"scope\", n, \"uniform\"){ A } or "
     "Scatter(domain, n, \"gaussian\", \"center\" or \"front\" ..., stddev, \"absolute\" or \"relative\"){ A }",
     nullptr},
    {CommandId::ShapeOperation, "Convexify", 0, 1, BodyRule::None, "Convexify() or Convexify(maxLength)", nullptr},
    {CommandId::ShapeOperation, "Taper", 1, 1, BodyRule::None, "Taper(height)", nullptr},
    {CommandId::ShapeOperation, "InsertAlongUV", 3, 5, BodyRule::None,
     "InsertAlongUV(uvSet, \"asset.obj\", height[, \"scope.y\" or \"vertex.normal\"[, \"alignPosition\" or "
     "\"keepPosition\"]])",
     nullptr},
    {CommandId::ShapeOperation, "Envelope", 4, 10, BodyRule::None,
     "Envelope(\"normal\" or \"world.up\", maxHeight, frontBaseHeight, frontAngle[, backBaseHeight, backAngle[, "
     "sideBaseHeight, sideAngle or rightBaseHeight, rightAngle, leftBaseHeight, leftAngle]])",
     nullptr},
    {CommandId::ShapeOperation, "EnvelopePerEdge", 2, -1, BodyRule::None,
     "EnvelopePerEdge(\"normal\" or \"world.up\", maxHeight, baseHeight0, angle0, baseHeight1, angle1, ...)", nullptr},
    {CommandId::ShapeOperation, "Translate", 5, 5, BodyRule::None,
     "Translate(\"rel\" or \"abs\", \"scope\", \"pivot\", \"object\" or \"world\", x, y, z)", nullptr},
    {CommandId::ShapeOperation, "Rotate", 5, 5, BodyRule::None,
     "Rotate(\"rel\" or \"abs\", \"scope\", \"pivot\", \"object\" or \"world\", ax, ay, az)", nullptr},
    {CommandId::ShapeOperation, "SetPivot", 2, 2, BodyRule::None,
     "SetPivot(\"xyz\" or \"yzx\" or \"zxy\", cornerIndex)", nullptr},
    {CommandId::ShapeOperation, "DeleteHoles", 0, 0, BodyRule::None, "DeleteHoles()", nullptr},
    {CommandId::ShapeOperation, "ApplyTrimPlanes", 0, 0, BodyRule::None, "ApplyTrimPlanes()", nullptr},
    {CommandId::ShapeOperation, "SetTrim", 2, 2, BodyRule::None,
     "SetTrim(\"horizontal\" or \"vertical\", on)", nullptr},
    {CommandId::ShapeOperation, "ReverseNormals", 0, 0, BodyRule::None, "ReverseNormals()", nullptr},
    {CommandId::ShapeOperation, "ResetGeometry", 0, 0, BodyRule::None, "ResetGeometry()", nullptr},
    {CommandId::ShapeOperation, "CleanupGeometry", 0, 2, BodyRule::None,
     "CleanupGeometry(\"all\" or \"vertices\" or \"edges\" or \"faces\", tolerance)", nullptr},
    {CommandId::ShapeOperation, "PrimitiveQuad", 0, 2, BodyRule::None, "PrimitiveQuad() or PrimitiveQuad(width, length)", nullptr},
    {CommandId::ShapeOperation, "PrimitiveCube", 0, 3, BodyRule::None, "PrimitiveCube() or PrimitiveCube(width, height, depth)", nullptr},
    {CommandId::ShapeOperation, "PrimitiveCylinder", 0, 3, BodyRule::None,
     "PrimitiveCylinder(), PrimitiveCylinder(sides) or PrimitiveCylinder(sides, radius, height)", nullptr},
    {CommandId::ShapeOperation, "PrimitiveSphere", 0, 3, BodyRule::None,
     "PrimitiveSphere(), PrimitiveSphere(sides, divisions) or PrimitiveSphere(sides, divisions, radius)", nullptr},
    {CommandId::ShapeOperation, "PrimitiveDisk", 0, 2, BodyRule::None, "PrimitiveDisk(sides) or PrimitiveDisk(sides, radius)", nullptr},
};

const FunctionInfo kFunctions[] = {
    {"Rand", 2, 2}, {"rand", 2, 2},   {"sin", 1, 1},    {"cos", 1, 1},   {"tan", 1, 1},
    {"asin", 1, 1}, {"acos", 1, 1},   {"atan", 1, 1},   {"atan2", 2, 2}, {"sqrt", 1, 1},
    {"abs", 1, 1},  {"min", 2, 2},    {"max", 2, 2},    {"floor", 1, 1}, {"ceil", 1, 1},
    {"round", 1, 1}, {"clamp", 3, 3}, {"lerp", 3, 3},   {"pow", 2, 2},   {"exp", 1, 1},
    {"log", 1, 1},  {"sign", 1, 1},   {"length", 1, 1}, {"dot", 2, 2},   {"normalize", 1, 1},
};

}  // namespace

const CommandInfo* findCommand(const std::string& name) {
  // Asked for every item by sema, lowering and the verifier: a search of the table was
  // 9 % of fgsg lsp's time on a change. The first entry of a name wins, as in the table.
  static const std::unordered_map<std::string_view, const CommandInfo*> byName = [] {
    std::unordered_map<std::string_view, const CommandInfo*> m;
    for (const auto& c : kCommands) m.emplace(c.name, &c);
    return m;
  }();
  const auto it = byName.find(name);
  return it == byName.end() ? nullptr : it->second;
}

std::span<const CommandInfo> allCommands() { return kCommands; }

namespace {
// In ir::MaterialProperty's order: the numbers, then the images from "normalmap" on.
const char* const kMaterialProperties[] = {
    "roughness",  "metallic",   "opacity",   "color.r",  "color.g", "color.b",     "emissive.r",
    "emissive.g", "emissive.b", "normalmap", "colormap", "bumpmap", "dirtmap",     "specularmap",
    "opacitymap", "emissivemap", "occlusionmap", "roughnessmap", "metallicmap"};
constexpr int kFirstMaterialImage = 9;  // "normalmap"
}  // namespace

int materialProperty(const std::string& name) {
  for (size_t k = 0; k < std::size(kMaterialProperties); ++k)
    if (name == kMaterialProperties[k]) return static_cast<int>(k);
  return -1;
}

const char* materialPropertyName(int property) {
  return property >= 0 && property < int(std::size(kMaterialProperties)) ? kMaterialProperties[property] : nullptr;
}

bool materialPropertyIsImage(int property) { return property >= kFirstMaterialImage; }

int uvOperation(const std::string& name) {
  static const char* const kNames[] = {"SetupProjection", "ScaleUV",  "TranslateUV", "RotateUV", "TileUV",
                                       "NormalizeUV",     "DeleteUV", "ProjectUV",   "CopyUV"};
  for (size_t k = 0; k < std::size(kNames); ++k)
    if (name == kNames[k]) return static_cast<int>(k);
  return -1;
}

const char* materialPropertyList() {
  return "roughness, metallic, opacity, color.r, color.g, color.b, emissive.r, emissive.g, emissive.b, normalmap, "
         "colormap, bumpmap, dirtmap, specularmap, opacitymap, emissivemap, occlusionmap, roughnessmap or metallicmap";
}

std::span<const FunctionInfo> allFunctions() { return kFunctions; }

const FunctionInfo* findFunction(const std::string& name) {
  for (const auto& f : kFunctions)
    if (name == f.name) return &f;
  return nullptr;
}

namespace {
const char* const kFeatureTruths[] = {"corner", "edge",    "face",     "horizontal", "vertical", "curved", "arc",
                                      "convex", "concave", "boundary", "bottom",     "top",      "side"};
const char* const kFeatureNumbers[] = {"index", "valence", "length", "area"};
const char* const kFieldVectors[] = {"vector",    "vector1",   "vector2",    "gradient",   "gradient2",
                                     "curl",      "curl1",     "curl2",      "jacobianX",  "jacobianY",
                                     "jacobianX2", "jacobianY2", "rgb"};
const char* const kFieldScalars[] = {"value",       "value1",      "value2",      "length",   "length1",  "length2",
                                     "Xangle",      "Xangle1",     "Xangle2",     "Yangle1",  "div",      "div1",
                                     "div2",        "streamcurv1", "streamcurv2", "tensorXX", "tensorXY", "tensorYX",
                                     "tensorYY",    "rotation",    "eigenangle",  "mincurv",  "maxcurv",  "meancurv",
                                     "gausscurv",   "intensity"};
}  // namespace

std::vector<std::string> featureMemberNames() {
  std::vector<std::string> out(std::begin(kFeatureTruths), std::end(kFeatureTruths));
  out.insert(out.end(), std::begin(kFeatureNumbers), std::end(kFeatureNumbers));
  out.push_back("label");
  return out;
}

std::vector<std::string> fieldMemberNames() {
  std::vector<std::string> out(std::begin(kFieldVectors), std::end(kFieldVectors));
  out.insert(out.end(), std::begin(kFieldScalars), std::end(kFieldScalars));
  return out;
}

bool isFeatureMember(const std::string& m, bool& isNumber, bool& takesString) {
  const auto& kTruths = kFeatureTruths;
  const auto& kNumbers = kFeatureNumbers;
  isNumber = takesString = false;
  if (m == "label") return takesString = true, true;
  for (const char* t : kTruths)
    if (m == t) return true;
  for (const char* n : kNumbers)
    if (m == n) return isNumber = true, true;
  return false;
}

bool isFieldMember(const std::string& m, bool& isVector) {
  const auto& kVectors = kFieldVectors;
  const auto& kScalars = kFieldScalars;
  for (const char* v : kVectors)
    if (m == v) return isVector = true, true;
  for (const char* s : kScalars)
    if (m == s) return isVector = false, true;
  return false;
}

}  // namespace fgsg::frontend
