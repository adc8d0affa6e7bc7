#include "backend/commands/evolve_command.h"

#include "backend/commands/surface_world.h"
#include "backend/declared_tiles.h"
#include "backend/engine/derivation.h"
#include "runtime/abandonable.h"
#include "runtime/evolve/colour_symmetry.h"
#include "runtime/evolve/fitness.h"
#include "runtime/evolve/genetic.h"
#include "runtime/evolve/lsystem2d.h"
#include "runtime/evolve/offset_surface.h"
#include "runtime/evolve/ornament.h"
#include "runtime/evolve/polycube_map.h"
#include "runtime/evolve/surface_ornament.h"
#include "runtime/io/find_file.h"
#include "runtime/surface/surface_mesh.h"

#include <cmath>
#include <stdexcept>

namespace fgsg::backend {
namespace {

// Patterns beyond this many cells a side are a grammar's mistake, not an ornament.
constexpr int kMaxSide = 4096;
// Polycube cells along the surface's largest extent when Evolve does not say.
constexpr int kDefaultPolycubeResolution = 8;

// A whole number in [lo, hi] from an argument, or R025 naming it.
int wholeArg(double v, int lo, int hi, const char* what, ir::Loc at) {
  if (!(v >= lo && v <= hi && v == std::floor(v)))
    throw DeriveError{at, "R025", std::string("Evolve: ") + what + " must be a whole number from " +
                                      std::to_string(lo) + " to " + std::to_string(hi)};
  return static_cast<int>(v);
}

// The cell's scope turned `turns` quarter turns counter-clockwise about its centre: the
// box still covers the cell (its X and Y sizes swap on odd turns).
rt::Scope turned(const rt::Scope& cell, int turns) {
  rt::Scope s = cell;
  const rt::Vec3 X = cell.axes.col(0), Y = cell.axes.col(1);
  const double w = cell.S.x(), h = cell.S.y();
  switch (turns & 3) {
    case 1: s.axes.col(0) = Y, s.axes.col(1) = -X, s.P = cell.P + w * X, s.S.x() = h, s.S.y() = w; break;
    case 2: s.axes.col(0) = -X, s.axes.col(1) = -Y, s.P = cell.P + w * X + h * Y; break;
    case 3: s.axes.col(0) = -Y, s.axes.col(1) = X, s.P = cell.P + h * Y, s.S.x() = h, s.S.y() = w; break;
    default: break;
  }
  return s;
}

}  // namespace

void EvolveCommand::apply(const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex, Frame&) {
  const ir::Module& m = d_.module();
  // Names the tiles in the cache and in the ornaments' asset names.
  const std::string file = op.index ? "tileset " + m.strings[op.str] : m.strings[op.str];
  const rt::evolve::TileSet& tiles = loadTiles(op, file);
  rt::evolve::EvolveOptions o;
  o.generation = wholeArg(a[0], 0, 12, "the generation", op.loc);
  if (n > 1) o.ruleSide = wholeArg(a[1], 1, 16, "the rule size k", op.loc);
  o.p4 = n > 2 && a[2] != 0.0;
  o.seed = rt::childKey(ex.key, 0x4000000000000000ull | (uint64_t(op.loc.line) << 20) | op.loc.col);
  o.deadline = &d_.deadline();
  if (op.index) applyTileSetSettings(m.tileSets[op.index - 1], o);
  const double side = std::pow(double(o.ruleSide), o.generation) * o.axiomSide;
  if (side > kMaxSide)
    throw DeriveError{op.loc, "R025", "Evolve: a pattern of k^generation = " + std::to_string(int64_t(side)) +
                                          " cells a side is past the " + std::to_string(kMaxSide) + " allowed"};
  const EvolveVariation variation = op.index ? evolveVariation(m.tileSets[op.index - 1]) : EvolveVariation{};
  if (variation.colourLevel > o.generation)
    throw DeriveError{op.loc, "R025", "Evolve: the tileset's colours come from generation " +
                                          std::to_string(variation.colourLevel) + ", past the pattern's generation " +
                                          std::to_string(o.generation)};
  rt::evolve::AlleleGrid grid;
  rt::evolve::ColourClasses colours;
  try {
    rt::evolve::checkOptions(o);
    const rt::evolve::EvolveResult result = rt::evolve::evolve(tiles, o);
    grid = rt::evolve::expand(result.best, o.generation);
    if (variation.colourLevel >= 0) {
      const int block = int(std::lround(std::pow(double(o.ruleSide), o.generation - variation.colourLevel)));
      colours = rt::evolve::colourClasses(rt::evolve::PatternMeasure(tiles), grid, block);
    }
  } catch (const std::invalid_argument& e) {
    throw DeriveError{op.loc, "R025", std::string("Evolve: ") + e.what()};
  }
  if (d_.surface()) {
    const int resolution = n > 3 ? wholeArg(a[3], 1, rt::evolve::kMaxPolycubeResolution, "the polycube resolution",
                                            op.loc)
                                 : kDefaultPolycubeResolution;
    ornamentSurface(op, file, tiles, grid, resolution, variation, colours, ex);
    return;
  }

  // Row 0 is the pattern's top row: it lies at the scope's largest Y.
  const int cells = grid.side;
  const rt::Scope& s = st.scope;
  const double w = s.S.x() / cells, h = s.S.y() / cells;
  for (int r = 0; r < cells; ++r)
    for (int c = 0; c < cells; ++c) {
      const rt::evolve::Allele allele = grid.at(r, c);
      rt::Scope cell = s;
      cell.P = s.P + s.axes.col(0) * (c * w) + s.axes.col(1) * ((cells - 1 - r) * h);
      cell.S = rt::Vec3(w, h, w);  // tile units are the cell's width, up too
      if (!colours.ofCell.empty()) {  // §6.4's colour symmetry: the cell's class's colour
        cell.colored = true;
        cell.color = rt::evolve::classColour(colours.ofCell[size_t(r) * size_t(cells) + size_t(c)]);
      }
      const rt::evolve::Tile& tile = tiles.tiles[allele.symbol];
      const int sym = m.findSymbolFrom(d_.placingSymbol(ex), tiles.loci[tile.locus].name);
      if (sym >= 0 && !m.symbols[sym].rules.empty() && m.symbols[sym].slotCount == 0) {
        d_.emitShape(static_cast<uint32_t>(sym), turned(cell, allele.turns), ex, op.loc);
        continue;
      }
      const Ornament& orn = ornament(file, tiles, allele);
      rt::Scope box = cell;
      box.P = cell.P + cell.axes * orn.lo.cwiseProduct(cell.S);
      box.S = orn.extent.cwiseProduct(cell.S);
      d_.placeInstance(orn.asset, box, d_.placingSymbol(ex), nullptr, 0, op.loc);
    }
}

// On a surface (§5): the pattern on every face-let of a polycube around the surface,
// carried onto it and no higher than the offset surface allows (§6.3); one generated asset
// in world space. The polycube (per resolution) and the offset surface are built once.
void EvolveCommand::ornamentSurface(const ir::Op& op, const std::string& file, const rt::evolve::TileSet& tiles,
                                    const rt::evolve::AlleleGrid& grid, int resolution,
                                    const EvolveVariation& variation, const rt::evolve::ColourClasses& colours,
                                    Exec& ex) {
  const rt::surface::SurfaceMesh& mesh = d_.surface()->mesh();
  try {
    auto& map = polycubes_[resolution];
    if (!map) {
      // Seconds at a fine resolution on a large mesh, in steps that read no clock: on a
      // worker --max-seconds abandons (it shares the surface, which outlives the map).
      try {
        map = rt::runAbandonable(&d_.deadline(), false, [world = d_.surface(), resolution] {
          return std::make_unique<rt::evolve::PolycubeMap>(world->mesh(), rt::evolve::PolycubeOptions{0, resolution});
        });
      } catch (const rt::TimeLimitReached&) {
        throw d_.timeLimit();
      }
    }
    if (!offset_) {
      rt::evolve::OffsetOptions o;
      o.deadline = &d_.deadline();
      offset_ = std::make_unique<rt::evolve::OffsetSurface>(rt::evolve::offsetSurface(mesh, o));
    }
    if (d_.deadline().expiredNow()) throw rt::TimeLimitReached{d_.deadline().seconds()};
    const rt::evolve::OffsetSurface& room = *offset_;
    std::vector<char> shown;
    if (!variation.faces.empty()) shown = rt::evolve::faceletsFacing(*map, variation.faces);
    const bool parted = !variation.faces.empty() || !colours.ofCell.empty();
    std::vector<uint32_t> triangleCell;
    const rt::Mesh ornament = rt::evolve::surfaceOrnament(
        tiles, grid, *map,
        [&](const rt::evolve::MappedPoint& p) {
          return rt::evolve::heightAt(room, mesh, rt::surface::SurfacePoint{p.face, p.bary});
        },
        {}, nullptr, 0, parted && !shown.empty() ? &shown : nullptr, parted ? &triangleCell : nullptr);
    const std::string base = "<surface ornament " + file + " " + std::to_string(++surfaceOrnaments_);
    const std::string name = base + ">";
    if (!parted) {
      rt::Scope box;  // the world box the ornament was built in
      const uint32_t asset = d_.addGeneratedAsset(name, ornament, &box);
      d_.placeInstance(asset, box, d_.placingSymbol(ex), nullptr, 0, op.loc);
      return;
    }
    // Selected face-lets and/or colour classes (§6.4): a part per class, in its colour.
    const int classes = colours.ofCell.empty() ? 1 : colours.classCount;
    const std::vector<int> cellClass =
        colours.ofCell.empty() ? std::vector<int>(grid.cells.size(), 0) : colours.ofCell;
    const std::vector<rt::Mesh> parts = rt::evolve::partOrnament(ornament, triangleCell, cellClass, classes);
    for (size_t c = 0; c < parts.size(); ++c) {
      if (parts[c].indices.empty()) continue;
      rt::Scope box;
      const uint32_t asset =
          d_.addGeneratedAsset(colours.ofCell.empty() ? name : base + " colour " + std::to_string(c) + ">", parts[c], &box);
      if (!colours.ofCell.empty()) box.colored = true, box.color = rt::evolve::classColour(int(c));
      d_.placeInstance(asset, box, d_.placingSymbol(ex), nullptr, 0, op.loc);
    }
  } catch (const std::invalid_argument& e) {
    throw DeriveError{op.loc, "R025", std::string("Evolve on the surface: ") + e.what()};
  }
}

const rt::evolve::TileSet& EvolveCommand::loadTiles(const ir::Op& op, const std::string& name) {
  auto it = tiles_.find(name);
  if (it != tiles_.end()) return it->second;
  const ir::Loc at = op.loc;
  if (op.index) {  // declared in the grammar: its errors are located at its items
    rt::evolve::TileSet tiles;
    std::string message;
    ir::Loc blamed;
    if (!declaredTileSet(d_.module().tileSets[op.index - 1], tiles, message, blamed))
      throw DeriveError{blamed, "R025", "Evolve: " + message};
    return tiles_.emplace(name, std::move(tiles)).first->second;
  }
  try {
    return tiles_.emplace(name, rt::evolve::readTileFile(rt::io::findFile(name, d_.options().assetDirs)))
        .first->second;
  } catch (const rt::evolve::TileFileError& e) {
    throw DeriveError{at, "R025", std::string("Evolve: ") + e.what()};
  }
}

// Built once per allele and registered like a swept line: normalised into the unit box,
// with the box it came from.
const EvolveCommand::Ornament& EvolveCommand::ornament(const std::string& file, const rt::evolve::TileSet& tiles,
                                                       rt::evolve::Allele allele) {
  const auto key = std::make_pair(file, allele.index());
  auto it = ornaments_.find(key);
  if (it != ornaments_.end()) return it->second;
  const rt::Mesh mesh = rt::evolve::tileOrnament(tiles, allele);
  const std::string name = "<ornament " + file + " " + tiles.tiles[allele.symbol].letter +
                           std::to_string(90 * allele.turns) + ">";
  rt::Scope box;
  Ornament o;
  o.asset = d_.addGeneratedAsset(name, mesh, &box);
  o.lo = box.P, o.extent = box.S;
  return ornaments_.emplace(key, o).first->second;
}

}  // namespace fgsg::backend
