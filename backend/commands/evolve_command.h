// Evolve(tileset or "tiles.json", generation, k, p4): Chan & Hui's surface patterns
// (runtime/evolve/) on a scope. A genetic algorithm finds a 2D L-system over the tiles of a
// `tileset` the grammar declares or of a tile file (rules k x k,
// default 3; the §6.1 p4 constraint when p4 is true), and its pattern at `generation`
// (k^generation cells a side) fills the scope's XY face. A cell whose locus is named
// after a symbol with rules and no parameters becomes a shape of that symbol, its scope
// the cell turned by the allele's orientation; any other cell gets its tile's ornament
// (the cross-section blended along the locus, runtime/evolve/ornament.h). The GA's seed
// comes from the shape's random stream; tile files are loaded once per derivation.
#pragma once

#include "backend/commands/command_family.h"
#include "backend/declared_tiles.h"
#include "runtime/evolve/colour_symmetry.h"
#include "runtime/evolve/lsystem2d.h"
#include "runtime/evolve/offset_surface.h"
#include "runtime/evolve/polycube_map.h"
#include "runtime/evolve/tiles.h"
#include "runtime/scope.h"

#include <map>
#include <memory>
#include <string>
#include <utility>

namespace fgsg::backend {

class Derivation;

class EvolveCommand final : public CommandFamily {
 public:
  explicit EvolveCommand(Derivation& derivation) : d_(derivation) {}

  std::vector<ir::OpKind> kinds() const override { return {ir::OpKind::Evolve}; }
  void apply(const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex, Frame& f) override;

 private:
  // The op's tiles (a declared tileset or a tile file), loaded once as `name`.
  const rt::evolve::TileSet& loadTiles(const ir::Op& op, const std::string& name);
  // The ornament of `allele` as a generated asset (its index in the output's asset
  // table) and where its bounding box sits in the unit tile.
  struct Ornament {
    uint32_t asset = 0;
    rt::Vec3 lo = rt::Vec3::Zero(), extent = rt::Vec3::Zero();
  };
  const Ornament& ornament(const std::string& file, const rt::evolve::TileSet& tiles, rt::evolve::Allele allele);
  void ornamentSurface(const ir::Op& op, const std::string& file, const rt::evolve::TileSet& tiles,
                       const rt::evolve::AlleleGrid& grid, int resolution, const EvolveVariation& variation,
                       const rt::evolve::ColourClasses& colours, Exec& ex);

  Derivation& d_;
  std::map<std::string, rt::evolve::TileSet> tiles_;
  std::map<std::pair<std::string, int>, Ornament> ornaments_;
  // On a surface: the polycube per resolution and the offset surface, built on first use.
  std::map<int, std::unique_ptr<rt::evolve::PolycubeMap>> polycubes_;
  std::unique_ptr<rt::evolve::OffsetSurface> offset_;
  int surfaceOrnaments_ = 0;
};

}  // namespace fgsg::backend
