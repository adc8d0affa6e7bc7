#include "backend/declared_tiles.h"

#include <algorithm>
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

// The item a validation error names (a locus or a cross-section), else the declaration.
ir::Loc blamed(const ir::TileSetSpec& spec, const rt::evolve::TileFileError& e) {
  const std::vector<ir::TileCurveSpec>* list = e.part == "loci" ? &spec.loci : e.part == "sections" ? &spec.sections : nullptr;
  if (list && e.index >= 0 && size_t(e.index) < list->size()) return (*list)[size_t(e.index)].loc;
  return spec.loc;
}

}  // namespace

void applyTileSetSettings(const ir::TileSetSpec& spec, ev::EvolveOptions& o) {
  bool parentsGiven = false, eliteGiven = false;
  for (const auto& [name, v] : spec.settings) {
    parentsGiven |= name == "parents";
    eliteGiven |= name == "elite";
    if (name == "population") o.population = int(v[0]);
    else if (name == "max_generations") o.maxGenerations = int(v[0]);
    else if (name == "threshold") o.threshold = v[0];
    else if (name == "crossover") o.crossoverRate = v[0];
    else if (name == "mutation") o.mutationRate = v[0];
    else if (name == "parents") o.parents = int(v[0]);
    else if (name == "elite") o.elite = int(v[0]);
    else if (name == "weights") {
      o.weights.symmetry = v[0], o.weights.connectivity = v[1], o.weights.complexity = v[2];
      if (v.size() > 3) o.weights.p4 = v[3];
    }
  }
  // A small population keeps defaults that would not fit it within it.
  if (!parentsGiven) o.parents = std::min(o.parents, o.population);
  if (!eliteGiven) o.elite = std::min(o.elite, o.population - 1);
}

EvolveVariation evolveVariation(const ir::TileSetSpec& spec) {
  EvolveVariation v;
  for (const auto& [name, values] : spec.settings) {
    if (name == "faces")
      for (const double d : values) v.faces.push_back(int(d));
    else if (name == "colours") v.colourLevel = int(values[0]);
  }
  return v;
}

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
    at = blamed(spec, e);
    return false;
  }
}

}  // namespace fgsg::backend
