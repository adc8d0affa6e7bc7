// Seed plants kept from one derivation for the next (fgsg view, #49 item 5;
// backend/engine/seed_plants.cpp): with a SurfaceReuse in effect, a plant whose seed,
// random key and texels read are unchanged is taken as it was. Each derivation here is
// compared byte for byte with the same derivation done afresh, without anything kept.
#include "derive_helpers.h"

#include "backend/engine/surface_reuse.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

using namespace fgsg;
using fgsg::test::deriveText;

namespace {

// A plant per seed on the unit sphere that grows while the mask reads white.
const char* kReuseMaskedPlants = R"(
  surface sphere(1);
  texture mask = "reuse_mask.pgm";
  start = Walk(0)
  Walk(n) : n < 5 ~> Marching(0.1, Rand(-40, 40), context.mask(texCoord) > 0.5){ Stem } Branch(n == 2 ? 2 : 1){ Walk(n + 1), Walk(n + 1) }
  Stem ~> S(1, 0.02, 0.02) I("bark")
)";

// A 64 x 64 binary PGM, white but for `black` texels (column, row).
void writeReuseMask(const std::filesystem::path& file, const std::vector<std::pair<int, int>>& black) {
  std::string texels(64 * 64, char(255));
  for (const auto& [c, r] : black) texels[size_t(r) * 64 + size_t(c)] = 0;
  std::ofstream out(file, std::ios::binary);
  out << "P5\n64 64\n255\n" << texels;
}

rt::DeriveOptions reuseSeedsAround(const std::filesystem::path& dir) {
  rt::DeriveOptions o;
  o.assetDirs = {dir.string()};
  for (int k = 0; k < 6; ++k) {
    rt::DeriveOptions::Seed s;
    const double a = 2 * 3.14159265358979 * k / 6;
    s.point[0] = std::cos(a), s.point[1] = std::sin(a), s.point[2] = 0.3;
    o.seeds.push_back(s);
  }
  return o;
}

template <class V>
bool reuseSameBytes(const V& a, const V& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0);
}

void requireReuseSameBytes(const rt::DeriveResult& kept, const rt::DeriveResult& fresh) {
  REQUIRE(kept.ok);
  REQUIRE(fresh.ok);
  CHECK(reuseSameBytes(kept.instances.instances, fresh.instances.instances));
  CHECK(reuseSameBytes(kept.instances.params, fresh.instances.params));
  CHECK(reuseSameBytes(kept.instances.curves, fresh.instances.curves));
  CHECK(kept.instances.startBounds == fresh.instances.startBounds);
  CHECK(kept.stats.shapesCreated == fresh.stats.shapesCreated);
  CHECK(kept.stats.rewrites == fresh.stats.rewrites);
}

size_t countReused(const std::vector<uint8_t>& v) { return size_t(std::count(v.begin(), v.end(), uint8_t(1))); }

}  // namespace

TEST_CASE("Kept seed plants: a moved seed and painted texels derive again only the plants they change", "[seeds]") {
  const std::filesystem::path dir = std::filesystem::path(FGSG_BINARY_DIR) / "test-scratch" / "seed_plant_reuse";
  std::filesystem::create_directories(dir);
  writeReuseMask(dir / "reuse_mask.pgm", {});
  rt::DeriveOptions o = reuseSeedsAround(dir);
  backend::SurfaceReuse reuse;
  const auto keptDerive = [&] {
    const backend::SurfaceReuseScope scope(reuse);
    return deriveText(kReuseMaskedPlants, o);
  };

  const rt::DeriveResult first = keptDerive();
  requireReuseSameBytes(first, deriveText(kReuseMaskedPlants, o));
  REQUIRE(reuse.plantsReused == std::vector<uint8_t>(6, 0));

  // The same again: every plant kept.
  requireReuseSameBytes(keptDerive(), first);
  CHECK(reuse.plantsReused == std::vector<uint8_t>(6, 1));

  // Seed 2 moved: its plant alone is derived.
  o.seeds[2].point[2] = -0.3;
  const rt::DeriveResult moved = keptDerive();
  requireReuseSameBytes(moved, deriveText(kReuseMaskedPlants, o));
  CHECK(reuse.plantsReused == std::vector<uint8_t>{1, 1, 0, 1, 1, 1});
  CHECK(!reuseSameBytes(moved.instances.instances, first.instances.instances));

  // A heading given to seed 4: its plant alone again.
  o.seeds[4].hasDirection = true;
  o.seeds[4].direction[0] = 0, o.seeds[4].direction[1] = 0, o.seeds[4].direction[2] = 1;
  requireReuseSameBytes(keptDerive(), deriveText(kReuseMaskedPlants, o));
  CHECK(reuse.plantsReused == std::vector<uint8_t>{1, 1, 1, 1, 0, 1});

  // Black painted over every texel: every plant reads a changed texel, none is kept, and
  // the plants stop at their first step.
  std::vector<std::pair<int, int>> all;
  for (int r = 0; r < 64; ++r)
    for (int c = 0; c < 64; ++c) all.emplace_back(c, r);
  writeReuseMask(dir / "reuse_mask.pgm", all);
  const rt::DeriveResult black = keptDerive();
  requireReuseSameBytes(black, deriveText(kReuseMaskedPlants, o));
  CHECK(countReused(reuse.plantsReused) == 0);
  CHECK(black.instances.instances.size() < moved.instances.instances.size());

  // White again but one texel, in each plant's read tiles or not: the plants that read
  // it are derived again, the others kept, and the whole is the fresh derivation's.
  size_t kept = 0, derived = 0;
  for (const auto& texel : std::vector<std::pair<int, int>>{{0, 0}, {32, 32}, {10, 40}, {50, 20}}) {
    writeReuseMask(dir / "reuse_mask.pgm", {});
    keptDerive();
    writeReuseMask(dir / "reuse_mask.pgm", {texel});
    requireReuseSameBytes(keptDerive(), deriveText(kReuseMaskedPlants, o));
    kept += countReused(reuse.plantsReused);
    derived += 6 - countReused(reuse.plantsReused);
  }
  CHECK(kept > 0);  // a single texel is read by a few plants at most
  CHECK(kept + derived == 24);
  std::filesystem::remove_all(dir);
}
