#include "march_fixtures.h"

#include "runtime/marching/geometry_image.h"
#include "runtime/marching/image_cache.h"
#include "tests/unit/runtime/scratch_files.h"

#include <fstream>
#include <random>

using namespace fgsg::rt;
using namespace fgsg::rt::marching;
using namespace fgsg::rt::marching::testing;

namespace {

void writeBytes(const std::filesystem::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary | std::ios::trunc) << bytes;
}

// The payload starts after the magic (8), version (4), byte order mark (4), key (32)
// and payload length (8).
constexpr size_t kPayloadAt = 56;

}  // namespace

TEST_CASE("the cache key follows the mesh's content and the resolution, not the folder", "[marching][cache]") {
  const ChartedMesh c = chartedCube(4, 128);
  MarchingOptions options;
  const std::string key = imageCacheKey(c.mesh, options);
  CHECK(key.size() == 32);
  CHECK(key.find_first_not_of("0123456789abcdef") == std::string::npos);
  CHECK(imageCacheKey(c.mesh, options) == key);
  options.cacheDir = "/elsewhere";
  CHECK(imageCacheKey(c.mesh, options) == key);
  options.resolution = 2048;
  CHECK(imageCacheKey(c.mesh, options) != key);

  surface::SurfaceMesh moved = c.mesh;
  moved.vertices[7].x() = std::nextafter(moved.vertices[7].x(), 1.0);
  CHECK(imageCacheKey(moved, MarchingOptions{}) != key);
  surface::SurfaceMesh turned = c.mesh;
  std::rotate(turned.faces[3].begin(), turned.faces[3].begin() + 1, turned.faces[3].end());
  CHECK(imageCacheKey(turned, MarchingOptions{}) != key);
  surface::SurfaceMesh textured = c.mesh;
  textured.textureUV = c.atlas.cornerUV;
  CHECK(imageCacheKey(textured, MarchingOptions{}) != key);
  CHECK(imageCachePath("/tmp/cache", key) == "/tmp/cache/marching-" + key + ".fgsgimage");
}

TEST_CASE("a cached surface reads back as the surface written", "[marching][cache]") {
  const ChartedMesh c = chartedCube(8, 256);
  const auto built = prepared(c);
  const auto dir = fgsg::test::scratchDir("marching-cache", "round-trip");
  const std::string key = imageCacheKey(c.mesh, MarchingOptions{});
  const std::string path = imageCachePath((dir / "nested").string(), key);  // the folder is created
  std::string error, why;
  REQUIRE(writeImageCache(path, key, *built, error));
  const auto read = readImageCache(path, key, c.mesh, MarchingOptions{}, why);
  INFO(why);
  REQUIRE(read);
  CHECK(read->atlas().chartCount == 6);
  CHECK(read->atlas().faceChart == c.atlas.faceChart);
  for (size_t f = 0; f < c.atlas.cornerUV.size(); ++f)
    for (int k = 0; k < 3; ++k) REQUIRE(read->atlas().cornerUV[f][k] == c.atlas.cornerUV[f][k]);
  const ImageTexels& a = built->image().texels();
  const ImageTexels& b = read->image().texels();
  CHECK(a.kind == b.kind);
  CHECK(a.face == b.face);
  CHECK(a.pointerCount == b.pointerCount);
  REQUIRE(a.pointers.size() == b.pointers.size());
  for (size_t i = 0; i < a.pointers.size(); ++i) {
    REQUIRE(a.pointers[i].chart == b.pointers[i].chart);
    REQUIRE(a.pointers[i].target == b.pointers[i].target);
  }
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> coord(-0.5, 0.5), angle(0, 2 * kPi), len(0, 2);
  for (int k = 0; k < 1000; ++k) {
    const Vec3 p(coord(rng), coord(rng), 0.5), dir(std::cos(angle(rng)), std::sin(angle(rng)), 0);
    const double length = len(rng);
    MarchPoint x, y;
    REQUIRE(built->march(placeAt(*built, p, dir), length, LengthUnit::Surface, x) ==
            read->march(placeAt(*read, p, dir), length, LengthUnit::Surface, y));
    REQUIRE(x.at.face == y.at.face);
    REQUIRE(x.at.bary == y.at.bary);
  }
}

TEST_CASE("a damaged or foreign cache file is refused with the reason", "[marching][cache]") {
  const ChartedMesh c = chartedCube(4, 128);
  const auto built = prepared(c);
  const auto dir = fgsg::test::scratchDir("marching-cache", "damaged");
  const std::string key = imageCacheKey(c.mesh, MarchingOptions{});
  const auto path = dir / "surface.fgsgimage";
  std::string error, why;
  REQUIRE(writeImageCache(path.string(), key, *built, error));
  const std::string good = fgsg::test::readFile(path);
  REQUIRE(good.size() > kPayloadAt + 1000);
  auto refused = [&](const std::string& bytes, const std::string& expected) {
    writeBytes(path, bytes);
    why.clear();
    const bool none = readImageCache(path.string(), key, c.mesh, MarchingOptions{}, why) == nullptr;
    INFO("why: " << why);
    CHECK(none);
    CHECK(why.find(expected) != std::string::npos);
  };
  refused(good.substr(0, good.size() - 1), "truncated");
  refused(good.substr(0, good.size() / 2), "truncated");
  refused(good.substr(0, 20), "not a marching cache file");
  refused("", "not a marching cache file");
  refused(good + "x", "truncated (or padded)");
  std::string flipped = good;
  flipped[kPayloadAt + 5000] ^= 0x10;
  refused(flipped, "corrupt");
  std::string version = good;
  version[8] = char(kImageCacheVersion + 1);
  refused(version, "format version");
  std::string magic = good;
  magic[0] = 'X';
  refused(magic, "not a marching cache file");

  // Another key, another mesh under the same key: refused after the checksum passed.
  writeBytes(path, good);
  CHECK_FALSE(readImageCache(path.string(), imageCacheKey(chartedCube(5, 128).mesh, MarchingOptions{}), c.mesh,
                             MarchingOptions{}, why));
  CHECK(why == "made for another mesh or other options");
  CHECK_FALSE(readImageCache(path.string(), key, chartedCube(5, 128).mesh, MarchingOptions{}, why));
  CHECK(why == "inconsistent: its sizes do not fit the mesh or each other");
  // Same counts, but face 0 flattened to a segment: the stored atlas no longer fits.
  surface::SurfaceMesh flattened = c.mesh;
  const auto& f0 = flattened.faces[0];
  flattened.vertices[f0[2]] = 0.5 * (flattened.vertices[f0[0]] + flattened.vertices[f0[1]]);
  flattened.buildTopology();
  CHECK_FALSE(readImageCache(path.string(), key, flattened, MarchingOptions{}, why));
  CHECK(why == "inconsistent: face 0 has zero area on the surface");

  CHECK_FALSE(readImageCache((dir / "missing").string(), key, c.mesh, MarchingOptions{}, why));
  CHECK_FALSE(why.empty());
  // Unwritable: a folder where the file should go.
  std::filesystem::create_directories(dir / "taken");
  CHECK_FALSE(writeImageCache((dir / "taken").string(), key, *built, error));
  CHECK_FALSE(error.empty());
}
