// Tiles and alleles of Chan & Hui 2013, "Surface pattern generation using L-system"
// (§3.1.1, Eq. 2).
//
// A tile is one cell of a k x k pattern over the unit square [0,1]^2. It holds
//   - a locus: a 2D curve inside the unit square, along which the cross-section is later
//     blended (a polyline, or a cubic Bezier curve);
//   - a cross-section: a 2D profile curve (x in [-1,1]) whose end points are (-1,0) and
//     (1,0), as Elber's blending needs (§2.4);
//   - an orientation: 0, 90, 180 or 270 degrees, a counter-clockwise turn of the tile
//     about its centre (0.5, 0.5).
// A *symbol* (one letter of the paper's strings) names a (locus, cross-section) pair; an
// *allele* is a symbol with an orientation. The alleles of a tile set are
//   loci x cross-sections x orientations            (Eq. 2)
// when every pair is a symbol (the default: symbols A, B, C, ... in locus-major order).
//
// Coordinates: x to the right, y up, in the tile's unit square. A pattern's row 0 is its
// top row (as the strings are written); see lsystem2d.h.
//
// The tile file (JSON; docs/evolve.md):
//   {
//     "loci": [ {"name": "arc",  "cubic":    [[0.5,0],[0.5,0.28],[0.72,0.5],[1,0.5]]},
//               {"name": "line", "polyline": [[0,0.5],[1,0.5]]} ],
//     "sections": [ {"name": "round", "polyline": [[-1,0],[0,1],[1,0]]} ],
//     "orientations": [0, 90, 180, 270],     // optional, default all four
//     "symbols": "AB"                        // optional, one letter per locus x section
//   }
// Errors name the file and the place: "tiles.json:3:14: syntax error ..." for bad JSON,
// "tiles.json: loci[1].cubic: a cubic needs 4 points, got 3" for bad content.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace fgsg::rt::evolve {

struct Point2 {
  double x = 0, y = 0;
  friend bool operator==(const Point2&, const Point2&) = default;
};

// A point of the unit square turned `quarterTurns` x 90 degrees counter-clockwise about
// the centre (0.5, 0.5): one turn maps (x, y) to (1 - y, x).
Point2 turnInTile(Point2 p, int quarterTurns);

// A 2D curve: a polyline through `points`, or the cubic Bezier curve with control points
// points[0..3].
struct Curve {
  enum class Kind { kPolyline, kCubic };
  Kind kind = Kind::kPolyline;
  std::vector<Point2> points;

  Point2 start() const { return points.front(); }
  Point2 end() const { return points.back(); }
  // The point at parameter t in [0,1]: for a polyline, t is spread evenly over its
  // segments (segment i covers [i/m, (i+1)/m]); for a cubic, the Bezier parameter.
  Point2 at(double t) const;
  // `count` >= 2 points at evenly spaced parameters, both ends included.
  std::vector<Point2> sample(int count) const;
};

struct Locus {
  std::string name;
  Curve curve;  // inside the unit square
};

struct Section {
  std::string name;
  Curve curve;  // from (-1, 0) to (1, 0)
};

// A symbol: a letter naming one locus with one cross-section.
struct Tile {
  char letter = 'A';
  int locus = 0;
  int section = 0;
};

// A symbol with an orientation. `turns` is the orientation in quarter turns (0..3:
// 0, 90, 180, 270 degrees counter-clockwise).
struct Allele {
  uint8_t symbol = 0;
  uint8_t turns = 0;
  int index() const { return symbol * 4 + turns; }  // dense index, 4 per symbol
  friend bool operator==(const Allele&, const Allele&) = default;
};

// Most symbols a tile set may have: the letters A-Z and a-z.
constexpr int kMaxSymbols = 52;

struct TileSet {
  std::vector<Locus> loci;
  std::vector<Section> sections;
  std::vector<Tile> tiles;          // the symbols, in rule order (rule i rewrites tiles[i])
  std::vector<int> orientations{0, 1, 2, 3};  // allowed quarter turns, ascending

  int symbolCount() const { return int(tiles.size()); }
  // The letters of the symbols in order ("AB").
  std::string letters() const;
  // Every allele: each symbol with each allowed orientation, symbol-major (Eq. 2).
  std::vector<Allele> alleles() const;
  // The locus end points of an allele in its tile, orientation applied.
  std::array<Point2, 2> endpoints(Allele a) const;
  // The whole locus of an allele, orientation applied: `count` points (see Curve::sample).
  std::vector<Point2> locusPoints(Allele a, int count) const;
};

// A tile file that cannot be read or is not a valid tile set. what() is the whole
// message, starting with the file name (and line:column for JSON syntax errors). A
// problem of one locus or cross-section also names it: `part` "loci" or "sections" and
// its `index` (a grammar's tileset blames that item); otherwise part is empty.
struct TileFileError : std::runtime_error {
  explicit TileFileError(const std::string& message, std::string part = {}, int index = -1)
      : std::runtime_error(message), part(std::move(part)), index(index) {}
  std::string part;
  int index = -1;
};

// Checks a tile set built in code (loci inside the unit square, cross-sections from
// (-1,0) to (1,0), curve sizes, symbols indexing existing loci and sections, distinct
// letters, orientations in 0..3); throws TileFileError naming the first problem, with
// `source` as the file name.
void validateTileSet(const TileSet& tiles, std::string_view source = "tile set");

// A tile set from its parts, as a tile file gives them: one symbol per locus x
// cross-section (locus-major), lettered by `symbols` (none: A, B, C, ...), `turns` the
// allowed orientations in quarter turns, ascending (none: all four). Validated
// (validateTileSet); throws TileFileError naming the first problem after `source`.
TileSet makeTileSet(std::vector<Locus> loci, std::vector<Section> sections, std::optional<std::vector<int>> turns,
                    std::optional<std::string> symbols, std::string_view source);

// Parses a tile file's text; `source` names it in errors.
TileSet parseTileSet(std::string_view json, std::string_view source = "tile set");

// Reads and parses a tile file (through io::readInputFile: no FIFOs, size-capped).
TileSet readTileFile(const std::string& path);

// The paper's running example (§3.1.2, Fig. 1): loci A and B, one cross-section C and
// the four orientations, 8 alleles. A is a quarter arc joining the middles of the bottom
// and right edges, B a straight line joining the middles of the left and right edges; C
// is a round profile. Used by tests, the benchmark and docs/evolve.md.
TileSet exampleTileSet();

}  // namespace fgsg::rt::evolve
