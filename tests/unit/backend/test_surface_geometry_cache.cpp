// fgsg view's surface geometries kept across recompiles (#49, surface_geometry.h): taken
// again only while the mesh file (path, size, modification time, content) and the options
// that change the mesh are the same, and a world designed on a kept geometry has exactly
// the field a fresh world has.
#include "derive_helpers.h"

#include "backend/commands/surface_geometry.h"
#include "backend/commands/surface_world.h"
#include "runtime/field/tangent_field.h"
#include "runtime/surface/procedural.h"
#include "runtime/surface/surface_mesh.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

using namespace fgsg;
using namespace fgsg::test;
namespace fs = std::filesystem;

namespace {

// A subdivided icosahedron (642 vertices) as OFF text, coordinates to 9 decimals (fixed
// width, so that a changed digit keeps the file's size).
std::string geometryCacheSphereOff() {
  const rt::surface::SurfaceMesh m = rt::surface::sphere(1.0, 3);
  std::ostringstream off;
  off << "OFF\n" << m.vertexCount() << " " << m.faceCount() << " 0\n";
  char line[96];
  for (const rt::Vec3& v : m.vertices) {
    std::snprintf(line, sizeof line, "%+.9f %+.9f %+.9f\n", v.x(), v.y(), v.z());
    off << line;
  }
  for (const auto& f : m.faces) off << "3 " << f[0] << " " << f[1] << " " << f[2] << "\n";
  return off.str();
}

std::string geometryCacheGrammar(int wedgeVertex) {
  return "surface \"ball.off\";\nfield F = design tensor { wedge at vertex " + std::to_string(wedgeVertex) +
         " decay 2; trisector at vertex 40 decay 2; };\nAxiom ~> I(\"cube\");\n";
}

}  // namespace

TEST_CASE("Surface geometries are kept while the mesh file and its options stay the same",
          "[surface][field][geometry_cache]") {
  const fs::path dir = fs::temp_directory_path() / ("fgsg-geometry-cache-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / "ball.off";
  const std::string text = geometryCacheSphereOff();
  std::ofstream(file, std::ios::binary) << text;
  const std::vector<std::string> dirs{dir.string()};
  const ir::Module first = compileText(geometryCacheGrammar(3));
  const ir::Module moved = compileText(geometryCacheGrammar(300));  // the wedge dragged
  rt::DeriveOptions options;
  backend::SurfaceGeometryCache cache;

  const auto a = cache.obtain(first.surface, options, dirs);
  const auto b = cache.obtain(moved.surface, options, dirs);
  CHECK(a == b);
  CHECK(cache.builds() == 1);
  CHECK(a->mesh().vertexCount() == 642);

  SECTION("a field designed on the kept geometry is the fresh world's, bit for bit") {
    const backend::SurfaceWorld kept(moved, options, dirs, b);
    const backend::SurfaceWorld fresh(moved, options, dirs);
    const auto& keptField = *kept.fields().at(0).second;
    const auto& freshField = *fresh.fields().at(0).second;
    REQUIRE(keptField.vertexCount() == 642);
    size_t same = 0, nonZero = 0;
    for (size_t v = 0; v < 642; ++v) {
      same += keptField.vertexTensor(int(v)) == freshField.vertexTensor(int(v));
      nonZero += keptField.vertexTensor(int(v)).norm() > 0;
    }
    CHECK(same == 642);
    CHECK(nonZero > 600);  // the elements reach (almost) every vertex: not a trivially equal field
    // And it differs from the field before the move, designed on the same geometry.
    const backend::SurfaceWorld before(first, options, dirs, a);
    CHECK(before.fields().at(0).second->vertexTensor(100) != keptField.vertexTensor(100));
  }

  SECTION("the file's content changed, its size and modification time kept: loaded again") {
    std::string changed = text;
    const size_t digit = changed.find('.', changed.find("0\n") + 2) + 1;  // vertex 0's x, first decimal
    changed[digit] = changed[digit] == '5' ? '6' : '5';
    const auto time = fs::last_write_time(file);
    std::ofstream(file, std::ios::binary | std::ios::trunc) << changed;
    fs::last_write_time(file, time);
    REQUIRE(fs::file_size(file) == text.size());
    const auto c = cache.obtain(first.surface, options, dirs);
    CHECK(c != a);
    CHECK(cache.builds() == 2);
    CHECK(c->mesh().vertices[0].x() != a->mesh().vertices[0].x());
  }

  SECTION("--surface-size and --repair-surface change the mesh: built again") {
    rt::DeriveOptions sized = options;
    sized.surfaceSize = 10;
    const auto c = cache.obtain(first.surface, sized, dirs);
    CHECK(c != a);
    CHECK(c->mesh().boundsMax.x() - c->mesh().boundsMin.x() > 9);
    rt::DeriveOptions repaired = options;
    repaired.repairSurface = true;
    CHECK(cache.obtain(first.surface, repaired, dirs) != a);
    CHECK(cache.builds() == 3);
    CHECK(cache.obtain(first.surface, options, dirs) == a);  // the first still kept
  }

  SECTION("procedural surfaces are kept by generator and arguments") {
    const ir::Module torus = compileText("surface torus(2, 0.5);\nAxiom ~> I(\"cube\");\n");
    const ir::Module thinner = compileText("surface torus(2, 0.4);\nAxiom ~> I(\"cube\");\n");
    const auto t = cache.obtain(torus.surface, options, dirs);
    CHECK(cache.obtain(torus.surface, options, dirs) == t);
    CHECK(cache.obtain(thinner.surface, options, dirs) != t);
    CHECK(cache.builds() == 3);
  }
  fs::remove_all(dir);
}
