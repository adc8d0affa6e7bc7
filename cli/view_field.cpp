#include "cli/view_field.h"

#include "backend/commands/surface_geometry.h"
#include "backend/commands/surface_world.h"
#include "runtime/field/field_sketch.h"
#include "runtime/surface/surface_mesh.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <memory>

namespace fgsg::cli {

using Json = nlohmann::json;

namespace {

Json error(const std::string& why) { return Json{{"type", "field"}, {"error", why}}; }

// Coordinates to a millionth of the surface's size: far below a pixel, and a short
// decimal each (a power of ten divides, so the shortest form is printed).
struct Rounding {
  double scale;  // 10^k
  explicit Rounding(double size) {
    const int k = std::clamp(5 - static_cast<int>(std::floor(std::log10(size > 0 && std::isfinite(size) ? size : 1))), -8, 12);
    scale = std::pow(10.0, k);
  }
  double operator()(double v) const { return std::isfinite(v) ? std::round(v * scale) / scale : 0.0; }
};

// The design elements of `spec` where they are put, with their strength and decay.
Json overlayDesignElements(const ir::FieldSpec& spec, const rt::surface::SurfaceMesh& mesh, const Rounding& rounded) {
  Json out = Json::array();
  for (const ir::FieldDesignSpec& item : spec.design) {
    if (item.kind == "smooth") continue;
    Json element{{"kind", item.kind}, {"position", nullptr}, {"strength", 1.0}, {"decay", 1.0}};
    for (const auto& [key, values] : item.words) {
      if (key == "at" && values.size() == 3) {
        element["position"] = {rounded(values[0]), rounded(values[1]), rounded(values[2])};
      } else if (key == "vertex" && values.size() == 1 && values[0] >= 0 && values[0] < mesh.vertexCount()) {
        const rt::Vec3 p = mesh.vertices[static_cast<size_t>(values[0])];
        element["position"] = {rounded(p.x()), rounded(p.y()), rounded(p.z())};
        element["vertex"] = values[0];
      } else if ((key == "strength" || key == "decay") && values.size() == 1) {
        element[key] = values[0];
      }
    }
    out.push_back(std::move(element));
  }
  return out;
}

}  // namespace

std::string fieldOverlayJson(const ir::Module& module, const rt::DeriveOptions& options,
                             const std::vector<std::string>& dataDirs, std::string* fieldName,
                             FieldEditBounds* bounds, std::shared_ptr<const backend::SurfaceWorld>* shown,
                             backend::SurfaceGeometryCache* geometries) {
  std::shared_ptr<const backend::SurfaceWorld> world = shown ? std::move(*shown) : nullptr;
  if (shown) shown->reset();
  if (!module.surface.present && options.surfaceOverride.empty())
    return error("the grammar declares no surface (fields live on one)").dump();
  try {
    if (!world)
      world = geometries ? std::make_shared<backend::SurfaceWorld>(
                               module, options, dataDirs, geometries->obtain(module.surface, options, dataDirs))
                         : std::make_shared<backend::SurfaceWorld>(module, options, dataDirs);
  } catch (const backend::DeriveError& e) {
    return error("line " + std::to_string(e.loc.line) + ": " + e.message).dump();
  }
  if (shown) *shown = world;
  const auto fields = world->fields();
  if (fields.empty()) return error("the grammar declares no field").dump();
  const auto& [name, field] = fields.front();
  const rt::surface::SurfaceMesh& mesh = world->mesh();
  const Rounding rounded((mesh.boundsMax - mesh.boundsMin).norm());
  const rt::field::FieldSketch sketch = rt::field::sketchField(mesh, *field, rt::field::FieldSketchOptions{});
  bool truncated = false;
  size_t points = 0;
  Json lines = Json::array();
  for (const auto& line : sketch.majorLines) {
    if (line.size() < 2) continue;
    if (points + line.size() > kMaxFieldOverlayPoints) {
      truncated = true;
      break;
    }
    points += line.size();
    Json flat = Json::array();
    for (const rt::Vec3& p : line)
      for (int k = 0; k < 3; ++k) flat.push_back(rounded(p[k]));
    lines.push_back(std::move(flat));
  }
  Json singularities = Json::array();
  for (const auto& s : sketch.singularities) {
    if (singularities.size() == kMaxFieldOverlaySingularities) {
      truncated = true;
      break;
    }
    singularities.push_back({{"kind", rt::field::singularityName(s.kind)},
                             {"index", s.indexTimesTwo / 2.0},
                             {"position", {rounded(s.position.x()), rounded(s.position.y()), rounded(s.position.z())}}});
  }
  Json overlay{{"type", "field"},           {"name", name},
               {"tensor", field->isTensor()}, {"lines", lines},
               {"singularities", singularities}, {"truncated", truncated}};
  for (const ir::FieldSpec& spec : module.fields)
    if (spec.name == name && spec.source == "design") overlay["elements"] = overlayDesignElements(spec, mesh, rounded);
  if (fieldName) *fieldName = name;
  if (bounds)
    for (int k = 0; k < 3; ++k) bounds->min[k] = mesh.boundsMin[k], bounds->max[k] = mesh.boundsMax[k];
  return overlay.dump();
}

}  // namespace fgsg::cli
