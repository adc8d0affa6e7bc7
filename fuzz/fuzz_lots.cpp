// libFuzzer target: `--lots` files. Text starting with '{' or '[' is GeoJSON
// (runtime/io/geojson_lots.h: FeatureCollection, Feature or bare geometry, "crs", rings,
// properties), read from memory by parseGeoJsonLots (readGeoJsonLots is readInputFile and
// that); anything else is written as a mesh (OBJ, or OFF/PLY by their first word) and read
// as lots from its faces (runtime/io/mesh_lots.h) through readLots, as `fgsg run --lots`
// does. Oracles: a failure has a message starting with the file's name
// and quotes no more than a bounded part of the input; a success gives lots whose outer
// ring is counter-clockwise and holes clockwise, each ring of 3 or more finite points
// within kMaxLotMetres, at most kMaxLotPoints per lot, and no hole for a mesh face.
#include "runtime/io/geojson_lots.h"
#include "runtime/io/read_lots.h"
#include "runtime/io/lot_rings.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <string_view>
#include <unistd.h>

namespace {

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_lots finding: %s\n", what.c_str());
  std::abort();
}

const char* guessExtension(std::string_view bytes) {
  const size_t p = bytes.find_first_not_of(" \t\r\n");
  const std::string_view head = p == std::string_view::npos ? "" : bytes.substr(p, 16);
  if (head.substr(0, 1) == "{" || head.substr(0, 1) == "[") return ".geojson";
  const std::string_view word = head.substr(0, head.find_first_of(" \t\r\n"));
  if (word == "ply") return ".ply";
  if (word.size() >= 3 && word.size() <= 6 && word.substr(word.size() - 3) == "OFF") return ".off";
  return ".obj";
}

std::string scratchFolder() {
  char name[] = "/dev/shm/fgsg-fuzz-lots-XXXXXX";
  if (!mkdtemp(name)) finding("cannot create a scratch folder in /dev/shm");
  return name;
}

double signedArea(const std::vector<Eigen::Vector2d>& ring) {
  double a = 0;
  for (size_t i = 0; i < ring.size(); ++i) {
    const auto& p = ring[i];
    const auto& q = ring[(i + 1) % ring.size()];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return a / 2;
}

void checkRing(const std::vector<Eigen::Vector2d>& ring, bool outer, const std::string& where) {
  if (ring.size() < 3) finding(where + ": a ring of " + std::to_string(ring.size()) + " points");
  for (const auto& p : ring)
    if (!p.allFinite() || std::abs(p.x()) > fgsg::rt::kMaxLotMetres || std::abs(p.y()) > fgsg::rt::kMaxLotMetres)
      finding(where + ": a point out of range");
  const double a = signedArea(ring);
  if (outer ? !(a > 0) : !(a < 0)) finding(where + (outer ? ": the outer ring is not counter-clockwise" : ": a hole is not clockwise"));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace fgsg::rt;
  if (size > 16384) return -1;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  static const std::string folder = scratchFolder();
  const std::string path = folder + "/lots" + guessExtension(bytes);
  const bool geojson = path.size() > 8 && path.compare(path.size() - 8, 8, ".geojson") == 0;
  if (!geojson) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) finding("cannot write " + path);
  }
  std::vector<Lot> lots;
  size_t skipped = 0;
  std::string error;
  if (!(geojson ? parseGeoJsonLots(std::string(bytes), path, lots, skipped, error)
                : readLots(path, lots, skipped, error))) {
    if (error.empty()) finding("the read failed without a message");
    if (error.rfind(path, 0) != 0) finding("a message that does not name the file: " + error);
    if (error.size() > 4096 + path.size() * 4) finding("a message of " + std::to_string(error.size()) + " bytes");
    if (!lots.empty()) finding("a failed read left lots");
    return 0;
  }
  if (lots.empty()) finding("a read without lots succeeded");
  for (const Lot& lot : lots) {
    const std::string where = lotName(path, lot);
    size_t points = lot.outer.size();
    checkRing(lot.outer, true, where);
    for (const auto& h : lot.holes) checkRing(h, false, where), points += h.size();
    if (points > kMaxLotPoints) finding(where + ": " + std::to_string(points) + " points");
    if (lot.isFace && !lot.holes.empty()) finding(where + ": a face with holes");
  }
  return 0;
}
