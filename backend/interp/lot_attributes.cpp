// Each lot's attribute values (--lots): its properties set the attrs named like them, so a
// grammar reads a lot's height or usage as it reads any attr, and Lot.area / Lot.prop(...)
// (the attrs "lot:area", "lot:NAME" the analyzer adds for them). A `.cga` grammar's
// initialShape.name and initialShape.origin.* are such attrs too ("lot:initialShape.name"
// ...), set here from the lot itself (docs/cga.md, "initialShape").
#include "backend/interp/eval.h"

#include "runtime/cga/cga.h"
#include "runtime/cga/ground_face.h"
#include "runtime/derivation.h"
#include "runtime/planar.h"

#include <cmath>
#include <cstdio>

namespace fgsg::backend {
namespace {

std::string numberText(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

// CityEngine's initialShape.name for a lot: its "name" property (a string), else the
// feature's id, else where it is in the file ("feature 3", a mesh's "face 3").
std::string initialShapeNameOf(const rt::Lot& lot) {
  for (const auto& [key, value] : lot.strings)
    if (key == "name") return value;
  if (!lot.id.empty()) return lot.id;
  return (lot.isFace ? "face " : "feature ") + std::to_string(lot.feature);
}

// initialShape.origin.p{x,y,z} and .o{x,y,z}: the lot's object frame (the derivation's
// own, rt::cga::initialShapeFrame: origin at the first corner of the outline's first edge,
// x along it, y up) in world coordinates, its turn as Euler angles in degrees: a lot lies
// on the ground, so only o.y, counter-clockwise from east seen from above.
void addInitialShapeOrigin(const ir::Module& m, const rt::Lot& lot,
                           std::vector<std::pair<std::string, std::string>>& overrides) {
  static const char* const kMembers[] = {"px", "py", "pz", "ox", "oy", "oz"};
  bool asked = false;
  for (const char* k : kMembers) asked = asked || m.findAttr(std::string("lot:initialShape.origin.") + k) >= 0;
  if (!asked) return;
  auto onGround = [](const std::vector<Eigen::Vector2d>& ring) {  // as Derivation::deriveLots
    std::vector<Eigen::Vector2d> xz;
    for (const Eigen::Vector2d& p : ring) xz.emplace_back(p.x(), -p.y());
    return xz;
  };
  std::vector<std::vector<Eigen::Vector2d>> holes;
  for (const auto& hole : lot.holes) holes.push_back(onGround(hole));
  rt::GeometryArena arena;
  rt::cga::Part part;
  std::string error;
  if (!rt::cga::footprint(rt::Scope{}, onGround(lot.outer), holes, arena, part, error)) return;  // deriving says it
  const rt::Scope frame = rt::cga::initialShapeFrame(part.scope, part.geom, arena);
  const rt::Vec3 x = frame.axes.col(0);
  const double turn = std::atan2(-x.z(), x.x()) * 180.0 / M_PI;
  const double values[] = {frame.P.x(), frame.P.y(), frame.P.z(), 0.0, turn, 0.0};
  for (size_t k = 0; k < 6; ++k) {
    const std::string name = std::string("lot:initialShape.origin.") + kMembers[k];
    if (m.findAttr(name) >= 0) overrides.push_back({name, numberText(values[k] == 0.0 ? 0.0 : values[k])});
  }
}

}  // namespace

std::vector<std::vector<double>> lotAttributeSlots(ir::Module& m, const rt::DeriveOptions& options) {
  std::vector<std::vector<double>> slots;
  slots.reserve(options.lots.size());
  for (const rt::Lot& lot : options.lots) {
    std::vector<std::pair<std::string, std::string>> overrides = options.attrOverrides;
    // A property sets the attr of its name and Lot.prop("name", ...)'s ("lot:name").
    auto set = [&](const std::string& name, const std::string& text) {
      if (m.findAttr(name) >= 0) overrides.push_back({name, text});
      if (m.findAttr("lot:" + name) >= 0) overrides.push_back({"lot:" + name, text});
    };
    for (const auto& [name, value] : lot.numbers) set(name, numberText(value));
    for (const auto& [name, value] : lot.strings) set(name, value);
    if (m.findAttr("lot_area") >= 0 || m.findAttr("lot:area") >= 0) {
      double area = std::abs(rt::twiceRingArea(lot.outer)) / 2;
      for (const auto& hole : lot.holes) area -= std::abs(rt::twiceRingArea(hole)) / 2;
      if (m.findAttr("lot_area") >= 0) overrides.push_back({"lot_area", numberText(area)});
      if (m.findAttr("lot:area") >= 0) overrides.push_back({"lot:area", numberText(area)});
    }
    if (m.findAttr("lot:initialShape.name") >= 0) overrides.push_back({"lot:initialShape.name", initialShapeNameOf(lot)});
    addInitialShapeOrigin(m, lot, overrides);
    try {
      slots.push_back(attributeSlots(m, overrides, attributeRandomKey(options.seed, slots.size())));
    } catch (const DeriveError& e) {
      // "--set height=tall: expected a number" reads, for a property, "height=tall: ...".
      const std::string what = e.message.rfind("--set ", 0) == 0 ? e.message.substr(6) : e.message;
      throw DeriveError{e.loc, e.code, rt::lotName(options.lotsName, lot) + ": property " + what};
    }
  }
  return slots;
}

}  // namespace fgsg::backend
