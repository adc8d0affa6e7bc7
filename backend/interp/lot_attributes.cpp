// Each lot's attribute values (--lots): its properties set the attrs named like them, so a
// grammar reads a lot's height or usage as it reads any attr, and Lot.area / Lot.prop(...)
// (the attrs "lot:area", "lot:NAME" the analyzer adds for them).
#include "backend/interp/eval.h"

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
    try {
      slots.push_back(attributeSlots(m, overrides));
    } catch (const DeriveError& e) {
      // "--set height=tall: expected a number" reads, for a property, "height=tall: ...".
      const std::string what = e.message.rfind("--set ", 0) == 0 ? e.message.substr(6) : e.message;
      throw DeriveError{e.loc, e.code, rt::lotName(options.lotsName, lot) + ": property " + what};
    }
  }
  return slots;
}

}  // namespace fgsg::backend
