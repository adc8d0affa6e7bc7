#include "backend/scene_starts.h"

#include "backend/interp/eval.h"

#include <string>

namespace fgsg::backend {

namespace {

rt::output::StartInfo lotInfo(const rt::Lot& lot) {
  rt::output::StartInfo info;
  if (!lot.id.empty())
    info.name = lot.id;
  else
    info.name = (lot.isFace ? "face " : "feature ") + std::to_string(lot.feature);
  if (lot.part > 0) info.name += " polygon " + std::to_string(lot.part);
  info.numbers = lot.numbers;
  info.strings = lot.strings;
  return info;
}

// The grammar's attrs (not the analyzer's "lot:..." ones) read from their value slots.
std::vector<rt::output::StartAttr> attrValues(const ir::Module& m, const std::vector<double>& slots) {
  using Kind = rt::output::StartAttr::Kind;
  std::vector<rt::output::StartAttr> attrs;
  for (size_t i = 0; i < m.attrs.size() && 3 * i + 2 < slots.size(); ++i) {
    const ir::Attr& a = m.attrs[i];
    if (a.name.find(':') != std::string::npos) continue;
    rt::output::StartAttr v;
    v.name = a.name;
    v.number = {slots[3 * i], slots[3 * i + 1], slots[3 * i + 2]};
    switch (a.type) {
      case ir::Type::Num: v.kind = Kind::Number, v.number[1] = v.number[2] = 0; break;
      case ir::Type::Bool: v.kind = Kind::Boolean, v.number = {slots[3 * i] != 0 ? 1.0 : 0.0, 0, 0}; break;
      case ir::Type::Str: {
        v.kind = Kind::String;
        const auto id = static_cast<size_t>(slots[3 * i]);
        v.text = id < m.strings.size() ? m.strings[id] : std::string();
        v.number = {};
        break;
      }
      case ir::Type::Vec3: v.kind = Kind::Vector; break;
    }
    attrs.push_back(std::move(v));
  }
  return attrs;
}

}  // namespace

std::vector<rt::output::StartInfo> sceneStarts(const ir::Module& m, const rt::DeriveOptions& options,
                                               const rt::DeriveResult& result) {
  const auto& bounds = result.instances.startBounds;
  const size_t starts = bounds.size() > 1 ? bounds.size() - 1 : 1;
  // The attrs' values as the derivation computed them, in a module of the grammar's attrs
  // and strings (a lot's string property is interned there, not in the grammar's).
  ir::Module values;
  values.attrs = m.attrs;
  values.strings = m.strings;
  std::vector<std::vector<double>> slots;
  try {
    if (!options.lots.empty())
      slots = lotAttributeSlots(values, options);
    else
      slots.assign(1, attributeSlots(values, options.attrOverrides, attributeRandomKey(options.seed, 0)));
  } catch (const DeriveError&) {
    slots.clear();  // the derivation failed on the same values: no attrs to tell
  }
  const std::vector<std::vector<rt::ReportCollection>> reports = rt::collectReports(result.reports, starts);
  std::vector<rt::output::StartInfo> infos;
  for (size_t k = 0; k < starts; ++k) {
    rt::output::StartInfo info;
    if (k < options.lots.size())
      info = lotInfo(options.lots[k]);
    else
      info.name = starts > 1 ? "seed " + std::to_string(k) : "axiom";
    const size_t slot = options.lots.empty() ? 0 : k;
    if (slot < slots.size()) info.attrs = attrValues(values, slots[slot]);
    if (k < reports.size()) info.reports = reports[k];
    infos.push_back(std::move(info));
  }
  return infos;
}

}  // namespace fgsg::backend
