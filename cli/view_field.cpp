#include "cli/view_field.h"

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

}  // namespace

std::string fieldOverlayJson(const ir::Module& module, const rt::DeriveOptions& options,
                             const std::vector<std::string>& dataDirs) {
  if (!module.surface.present && options.surfaceOverride.empty())
    return error("the grammar declares no surface (fields live on one)").dump();
  std::unique_ptr<backend::SurfaceWorld> world;
  try {
    world = std::make_unique<backend::SurfaceWorld>(module, options, dataDirs);
  } catch (const backend::DeriveError& e) {
    return error("line " + std::to_string(e.loc.line) + ": " + e.message).dump();
  }
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
  return Json{{"type", "field"},           {"name", name},
              {"tensor", field->isTensor()}, {"lines", lines},
              {"singularities", singularities}, {"truncated", truncated}}
      .dump();
}

}  // namespace fgsg::cli
