#include "frontend/shape_operations.h"

#include "runtime/cga/edge_index_label.h"

#include <cstring>
#include <initializer_list>
#include <utility>

namespace fgsg::frontend {
namespace {

using Words = std::initializer_list<std::pair<const char*, double>>;

bool pick(Words words, const std::string& word, double& value, std::string& allowed) {
  for (const auto& [w, v] : words)
    if (word == w) return value = v, true;
  for (const auto& [w, v] : words) allowed += (allowed.empty() ? "" : ", ") + std::string(w);
  return false;
}

bool labelIn(std::initializer_list<const char*> labels, const std::string& label, std::string& allowed) {
  std::string bare = label;
  if (!bare.empty() && bare.back() == '=') bare.pop_back();  // merged parts (from a .cga `=`)
  for (const char* l : labels)
    if (bare == l) return true;
  for (const char* l : labels) allowed += (allowed.empty() ? "" : ", ") + std::string(l);
  return false;
}

}  // namespace

bool shapeOperationWord(const std::string& command, size_t k, const std::string& word, double& value,
                        std::string& allowed) {
  allowed.clear();
  // Axis words: the scope axis's index; 7 all three.
  if (command == "AlignScopeToAxes" && k == 0) return pick({{"x", 0}, {"y", 1}, {"z", 2}, {"xyz", 7}}, word, value, allowed);
  if (command == "AlignScopeToGeometry") {
    if (k == 0) return pick({{"y", 1}, {"yUp", 1}, {"z", 2}, {"zUp", 2}}, word, value, allowed);
    if (k == 1) return pick({{"largest", -1}}, word, value, allowed);  // else a face index
    if (k == 2) return pick({{"longest", -1}}, word, value, allowed);  // else an edge index
  }
  if ((command == "Translate" || command == "Rotate") && k == 0)
    return pick({{"rel", 0}, {"abs", 1}}, word, value, allowed);
  if ((command == "Translate" || command == "Rotate") && k == 1)
    return pick({{"scope", 0}, {"pivot", 1}, {"object", 2}, {"world", 3}}, word, value, allowed);
  // setPivot's axisMap: runtime/cga/shape_operations.h's order codes.
  if (command == "SetPivot" && k == 0) return pick({{"xyz", 0}, {"yzx", 1}, {"zxy", 2}}, word, value, allowed);
  // The trim attribute's two classes (backend SetTrim: 0 horizontal, 1 vertical).
  if (command == "SetTrim" && k == 0) return pick({{"horizontal", 0}, {"vertical", 1}}, word, value, allowed);
  if (command == "InnerRectangle" && k == 0) return pick({{"scope", 0}, {"edge", 1}}, word, value, allowed);
  // InsertAlongUV's asset is any file name (the lowering makes it the op's asset), then
  // the height's direction and alignment as runtime/cga/insert_along_uv.h's options.
  if (command == "InsertAlongUV" && k == 1) return value = 0, true;
  if (command == "InsertAlongUV" && k == 3) return pick({{"scope.y", 0}, {"vertex.normal", 1}}, word, value, allowed);
  if (command == "InsertAlongUV" && k == 4)
    return pick({{"alignPosition", 0}, {"keepPosition", 1}}, word, value, allowed);
  if ((command == "Envelope" || command == "EnvelopePerEdge") && k == 0)
    return pick({{"normal", 0}, {"world.up", 1}}, word, value, allowed);
  // Scatter's words as runtime/cga/scatter.h's ScatterDomain and ScatterMean.
  if (command == "Scatter" && k == 0) return pick({{"surface", 0}, {"volume", 1}, {"scope", 2}}, word, value, allowed);
  if (command == "Scatter" && k == 2) return pick({{"uniform", 0}, {"gaussian", 1}}, word, value, allowed);
  if (command == "Scatter" && k == 3)
    return pick({{"center", 0}, {"front", 1}, {"back", 2}, {"left", 3}, {"right", 4}, {"top", 5}, {"bottom", 6}}, word,
                value, allowed);
  if (command == "Scatter" && k == 5) return pick({{"absolute", 0}, {"relative", 1}}, word, value, allowed);
  if (command == "CleanupGeometry" && k == 0)
    // op_cleanupGeometry's components as runtime/cga/shape_operations.h's steps: each merges
    // corners (1); vertices also drops straight corners (2), faces degenerate and doubled
    // faces (4), edges the edges between coplanar faces (8).
    return pick({{"vertices", 3}, {"edges", 9}, {"faces", 5}, {"all", 15}}, word, value, allowed);
  return false;
}

bool shapeOperationLabel(const std::string& command, const std::string& label, std::string& allowed) {
  allowed.clear();
  if (command == "Setback" || command == "SetbackToArea" || command == "SetbackPerEdge") {
    long long index = 0;
    if (rt::cga::edgeIndexOfLabel(label, index)) return true;  // `2:`, an edge by its index
    if (labelIn({"front", "back", "left", "right", "side", "all", "remainder", "streetFront", "streetBack",
                 "streetLeft", "streetRight", "streetSide", "north", "south", "east", "west"},
                label, allowed))
      return true;
    allowed += ", or an edge's index: `0:`, `-1:`";
    return false;
  }
  if (command == "ShapeL" || command == "ShapeU" || command == "ShapeO")
    return labelIn({"shape", "remainder"}, label, allowed);
  if (command == "InnerRectangle") return labelIn({"shape"}, label, allowed);
  return false;
}

bool shapeOperationPlainBody(const std::string& command) { return command == "Scatter"; }

bool shapeOperationArity(const std::string& command, size_t count, std::string& forms) {
  // CityEngine's forms: primitiveQuad(width, length), primitiveCube(width, height, depth),
  // primitiveCylinder(sides, radius, height), primitiveSphere(sides, divisions, radius),
  // primitiveDisk(nVertices, radius), each also without arguments.
  static const struct {
    const char* command;
    unsigned counts;  // bit n: n arguments
    const char* forms;
  } kForms[] = {{"PrimitiveQuad", 0b101, "0 or 2 arguments"},
                {"PrimitiveCube", 0b1001, "0 or 3 arguments"},
                {"PrimitiveCylinder", 0b1011, "0, 1 or 3 arguments"},
                {"PrimitiveSphere", 0b1101, "0, 2 or 3 arguments"}};
  // envelope's forms: front; front and back; front, back and side; front, back, right and
  // left (each a base height and an angle); per edge: any number of such pairs.
  if (command == "Envelope") {
    forms = "4, 6, 8 or 10 arguments";
    return count == 4 || count == 6 || count == 8 || count == 10;
  }
  if (command == "EnvelopePerEdge") {
    forms = "a direction, maxHeight and pairs of a base height and an angle";
    return count >= 2 && count % 2 == 0;
  }
  for (const auto& f : kForms)
    if (command == f.command) {
      forms = f.forms;
      return count < 8 && ((f.counts >> count) & 1u);
    }
  return true;
}

}  // namespace fgsg::frontend
