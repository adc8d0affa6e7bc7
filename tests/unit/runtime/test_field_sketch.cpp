// `fgsg field`'s sketch of a field: streamlines of a constant field are straight and
// stay on the surface; a field without singularities lists none; the sketch mesh holds
// the surface, one line segment per streamline step and a marker per singularity.
#include "runtime/field/field_sketch.h"

#include <catch2/catch.hpp>

using namespace fgsg::rt;
using namespace fgsg::rt::field;

namespace fgsg::rt::field::testing {
SurfaceMesh flatGrid(int nx, int ny, double x0, double y0, double w, double h, double jitter);
}  // namespace fgsg::rt::field::testing

TEST_CASE("the streamlines of a constant field are straight lines along it", "[field]") {
  const SurfaceMesh m = testing::flatGrid(12, 12, 0, 0, 4, 4, 0.3);
  TangentField field(TangentFrames::make(m), FieldType::Vector);
  const Vec3 along = Vec3(1, 2, 0).normalized();
  for (size_t v = 0; v < m.vertexCount(); ++v) field.setVertexVectorWorld(int(v), along);
  FieldSketchOptions options;
  options.seeds = 20;
  options.length = 1;
  const FieldSketch sketch = sketchField(m, field, options);
  REQUIRE(sketch.majorLines.size() == 20);
  CHECK(sketch.minorLines.empty());  // a vector field has no minor lines
  CHECK(sketch.singularities.empty());
  for (const auto& line : sketch.majorLines) {
    REQUIRE(line.size() >= 2);
    double length = 0;
    for (size_t i = 0; i < line.size(); ++i) {
      const Vec3 off = line[i] - line.front();
      CHECK((off - off.dot(along) * along).norm() < 1e-9);  // on the line through the seed
      CHECK(std::abs(line[i].z()) < 1e-12);
      if (i > 0) length += (line[i] - line[i - 1]).norm();
    }
    CHECK(length <= 2 + 1e-9);  // at most `length` either way
  }
  const Mesh surface;
  const Mesh drawn = sketchMesh(surface, sketch, 0.1);
  size_t segments = 0;
  for (const auto& line : sketch.majorLines) segments += line.size() - 1;
  CHECK(drawn.lineCount() == segments);
  CHECK(drawn.triangleCount() == 0);
  CHECK(drawn.colors.size() == drawn.positions.size());
}

TEST_CASE("singularities are drawn as markers coloured by their kind", "[field]") {
  FieldSketch sketch;
  sketch.singularities.push_back({Vec3(1, 2, 3), Degeneracy::Wedge, 1});
  sketch.singularities.push_back({Vec3(0, 0, 0), Degeneracy::Trisector, -1});
  const Mesh drawn = sketchMesh(Mesh{}, sketch, 0.2);
  CHECK(drawn.triangleCount() == 16);  // an octahedron each
  const auto bounds = drawn.boundsMax();
  CHECK(bounds[0] == Approx(1.1));
  CHECK(std::string(singularityName(Degeneracy::Trisector)) == "trisector");
  CHECK(drawn.colors[0] != drawn.colors[3 * 24]);  // the wedge's colour is not the trisector's
}
