// libFuzzer target: Evolve's tile files (runtime/evolve/tiles.h: loci, cross-sections,
// orientations, symbols as JSON), parsed as `fgsg evolve TILES.json` and the Evolve()
// command read them. Oracles: the only exception is TileFileError, whose message starts
// with the file's name; a tile set read passes validateTileSet again, has one allele per
// symbol and orientation, and its alleles' end points and sampled loci lie in the unit
// square (the loci are checked to) and are finite.
#include "runtime/evolve/tiles.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_evolve_tiles finding: %s\n", what.c_str());
  std::abort();
}

void inSquare(const fgsg::rt::evolve::Point2& p, const std::string& what) {
  const double e = 1e-9;
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || p.x < -e || p.x > 1 + e || p.y < -e || p.y > 1 + e)
    finding(what + " lies outside the unit square");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace fgsg::rt::evolve;
  if (size > 16384) return -1;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  TileSet tiles;
  try {
    tiles = parseTileSet(text, "tiles.json");
  } catch (const TileFileError& e) {
    const std::string what = e.what();
    if (what.rfind("tiles.json:", 0) != 0) finding("a message that does not name the file: " + what);
    if (what.size() > 4096) finding("a message of " + std::to_string(what.size()) + " bytes");
    return 0;
  }
  try {
    validateTileSet(tiles, "tiles.json");
  } catch (const TileFileError& e) {
    finding(std::string("a tile set read fails validation: ") + e.what());
  }
  if (tiles.symbolCount() < 1 || tiles.symbolCount() > kMaxSymbols) finding("a tile set of " + std::to_string(tiles.symbolCount()) + " symbols");
  const auto alleles = tiles.alleles();
  if (alleles.size() != tiles.tiles.size() * tiles.orientations.size()) finding("alleles are not symbols x orientations");
  for (const Allele& a : alleles) {
    for (const Point2& p : tiles.endpoints(a)) inSquare(p, "an allele's end point");
    for (const Point2& p : tiles.locusPoints(a, 9)) inSquare(p, "an allele's locus");
  }
  if (tiles.letters().size() != tiles.tiles.size()) finding("letters and symbols differ in number");
  return 0;
}
