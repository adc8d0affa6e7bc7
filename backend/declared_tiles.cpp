#include "backend/declared_tiles.h"

#include <algorithm>
#include <cstdlib>
#include <optional>

namespace fgsg::backend {
namespace {

namespace ev = rt::evolve;

template <class Part>
std::vector<Part> curves(const std::vector<ir::TileCurveSpec>& specs) {
  std::vector<Part> out;
  for (const ir::TileCurveSpec& c : specs) {
    Part p;
    p.name = c.name;
    p.curve.kind = c.cubic ? ev::Curve::Kind::kCubic : ev::Curve::Kind::kPolyline;
    for (const auto& xy : c.points) p.curve.points.push_back({xy[0], xy[1]});
    out.push_back(std::move(p));
  }
  return out;
}

// The item a validation message names by its place in the tile file's terms
// ("loci[1]...", "sections[0]..." right after the source), else the declaration.
ir::Loc blamed(const ir::TileSetSpec& spec, const std::string& message, size_t from) {
  for (const auto& [key, list] : {std::pair{"loci[", &spec.loci}, std::pair{"sections[", &spec.sections}}) {
    const std::string k = key;
    if (message.compare(from, k.size(), k) != 0) continue;
    const size_t i = std::strtoul(message.c_str() + from + k.size(), nullptr, 10);
    if (i < list->size()) return (*list)[i].loc;
  }
  return spec.loc;
}

}  // namespace

bool declaredTileSet(const ir::TileSetSpec& spec, ev::TileSet& out, std::string& message, ir::Loc& at) {
  const std::string source = "tileset '" + spec.name + "'";
  std::optional<std::vector<int>> turns;
  if (!spec.orientations.empty()) {
    turns.emplace();
    for (int degrees : spec.orientations) turns->push_back(degrees / 90);
    std::sort(turns->begin(), turns->end());
  }
  try {
    out = ev::makeTileSet(curves<ev::Locus>(spec.loci), curves<ev::Section>(spec.sections), turns,
                          spec.symbols.empty() ? std::nullopt : std::optional(spec.symbols), source);
    return true;
  } catch (const ev::TileFileError& e) {
    message = e.what();
    at = blamed(spec, message, source.size() + 2);  // after "tileset 'x': "
    return false;
  }
}

}  // namespace fgsg::backend
