// The field file format (docs/fields.md): round trips in world and frame coordinates,
// projection onto the tangent plane on load, comments, and the errors a hand-written file
// can trip on, each naming the file and line.
#include "runtime/field/field_file.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace fgsg::rt;
using namespace fgsg::rt::field;

namespace fgsg::rt::field::testing {
SurfaceMesh flatGrid(int nx, int ny, double x0, double y0, double w, double h, double jitter);
SurfaceMesh icosphere(int subdivisions, double radius);
}  // namespace fgsg::rt::field::testing

namespace {

constexpr double kRoundTrip = 1e-12;

std::string parseError(const std::string& text, std::shared_ptr<const TangentFrames> frames) {
  std::optional<TangentField> out;
  std::string error;
  CHECK_FALSE(parseField(text, "f.txt", frames, out, error));
  return error;
}

}  // namespace

TEST_CASE("fields round-trip through files in world and frame coordinates", "[field]") {
  const SurfaceMesh m = testing::icosphere(2, 1.5);
  auto frames = TangentFrames::make(m);
  TangentField vec(frames, FieldType::Vector), ten(frames, FieldType::Tensor);
  for (size_t v = 0; v < m.vertexCount(); ++v) {
    vec.setVertexVector(int(v), Vec2(std::sin(0.3 * v), std::cos(0.7 * v) * 1e-3));
    Mat2 t;
    t << std::sin(1.1 * v), 0.25 * std::cos(v), 0.25 * std::cos(v), -3e5 * std::sin(0.2 * v);
    ten.setVertexTensor(int(v), t);
  }
  for (auto coordinates : {FieldCoordinates::World, FieldCoordinates::Frame}) {
    for (const TangentField* field : {&vec, &ten}) {
      const std::string text = formatField(*field, coordinates);
      std::optional<TangentField> back;
      std::string error;
      REQUIRE(parseField(text, "rt.txt", frames, back, error));
      REQUIRE(back->type() == field->type());
      for (size_t v = 0; v < m.vertexCount(); ++v) {
        if (field->isTensor())
          CHECK((back->vertexTensor(int(v)) - field->vertexTensor(int(v))).norm() <=
                kRoundTrip * (1 + field->vertexTensor(int(v)).norm()));
        else
          CHECK((back->vertexVector(int(v)) - field->vertexVector(int(v))).norm() <= kRoundTrip);
      }
      // Frame coordinates are written exactly.
      if (coordinates == FieldCoordinates::Frame && !field->isTensor())
        CHECK(back->vertexVectors() == field->vertexVectors());
    }
  }
}

TEST_CASE("saved field files load back from disk", "[field]") {
  const SurfaceMesh m = testing::flatGrid(3, 3, 0, 0, 1, 1, 0);
  auto frames = TangentFrames::make(m);
  TangentField field(frames, FieldType::Vector);
  for (size_t v = 0; v < m.vertexCount(); ++v) field.setVertexVectorWorld(int(v), Vec3(1, v, 0));
  const std::string path = std::string(FGSG_BINARY_DIR) + "/test_field_file.txt";
  std::string error;
  REQUIRE(saveField(path, field, error));
  std::optional<TangentField> back;
  REQUIRE(loadField(path, frames, back, error));
  CHECK(back->vertexVectorWorld(7).isApprox(Vec3(1, 7, 0)));
  CHECK_FALSE(loadField(path + ".missing", frames, back, error));
  CHECK(error == path + ".missing: no such file");
}

TEST_CASE("world values are projected onto the tangent plane, comments are skipped",
          "[field]") {
  const SurfaceMesh m = testing::flatGrid(1, 1, 0, 0, 1, 1, 0);  // 4 vertices, normal +Z
  auto frames = TangentFrames::make(m);
  const std::string text =
      "# a hand-written field\n"
      "\n"
      "fgsg-field 1 vector 4   # world by default\n"
      "1 0 5\n"
      "0 2 -1  # the z part is dropped\n"
      "  +1.5e0\t-0.5 0\r\n"
      "0 0 9\n";
  std::optional<TangentField> field;
  std::string error;
  REQUIRE(parseField(text, "hand.txt", frames, field, error));
  CHECK(field->vertexVectorWorld(0).isApprox(Vec3(1, 0, 0)));
  CHECK(field->vertexVectorWorld(1).isApprox(Vec3(0, 2, 0)));
  CHECK(field->vertexVectorWorld(2).isApprox(Vec3(1.5, -0.5, 0)));
  CHECK(field->vertexVectorWorld(3).norm() == 0);

  const std::string tensors =
      "fgsg-field 1 tensor 4 world\n"
      "1 0 7 2 7 7\n1 0 0 1 0 0\n0 1 0 0 0 0\n3 0 0 0 0 0\n";
  REQUIRE(parseField(tensors, "t.txt", frames, field, error));
  CHECK(field->isTensor());
  Mat3 want = Mat3::Zero();
  want(0, 0) = 1;
  want(1, 1) = 2;
  CHECK(field->vertexTensorWorld(0).isApprox(want));
}

TEST_CASE("malformed field files are reported with file and line", "[field]") {
  const SurfaceMesh m = testing::flatGrid(1, 1, 0, 0, 1, 1, 0);
  auto frames = TangentFrames::make(m);
  CHECK(parseError("fgsg-field 1 vector 4\n1 0 0\n1 0\n0 0 0\n0 0 0\n", frames) ==
        "f.txt:3: expected 3 numbers, got 2");
  CHECK(parseError("fgsg-field 1 tensor 4 frame\n1 0 0\n1 0 0 0\n", frames) ==
        "f.txt:3: expected 3 numbers, got 4");
  CHECK(parseError("fgsg-field 1 vector 5\n", frames) ==
        "f.txt:1: the field has 5 vertices, the surface 4");
  CHECK(parseError("# c\nfgsg-field 1 vector 4\n1 0 0\nnan 0 0\n", frames) ==
        "f.txt:4: value 1 is not finite (nan)");
  CHECK(parseError("fgsg-field 1 vector 4\n1 0 inf\n", frames) ==
        "f.txt:2: value 3 is not finite (inf)");
  CHECK(parseError("fgsg-field 1 vector 4\n1 0 x\n", frames) == "f.txt:2: 'x' is not a number");
  CHECK(parseError("fgsg-field 1 vector 4\n1 0 0\n", frames) ==
        "f.txt: expected 4 vertex lines, got 1");
  CHECK(parseError("fgsg-field 1 vector 4 frame\n1 0\n1 0\n1 0\n1 0\n1 0\n", frames) ==
        "f.txt:6: more vertex lines than the 4 the header announces");
  CHECK(parseError("fgsg-field 2 vector 4\n", frames) ==
        "f.txt:1: unsupported version '2' (this reader knows 1)");
  CHECK(parseError("fgsg-field 1 matrix 4\n", frames) ==
        "f.txt:1: expected 'vector', 'tensor' or 'asymmetric', got 'matrix'");
  CHECK(parseError("fgsg-field 1 vector 4 local\n", frames) ==
        "f.txt:1: expected 'world' or 'frame', got 'local'");
  CHECK(parseError("1 0 0\n", frames) ==
        "f.txt:1: expected the header 'fgsg-field 1 vector|tensor|asymmetric <vertexCount> [world|frame]'");
  CHECK(parseError("# nothing\n", frames) ==
        "f.txt: empty field file (expected the header 'fgsg-field 1 vector|tensor|asymmetric "
        "<vertexCount> [world|frame]')");
}

TEST_CASE("scalar field files: one number per vertex, malformed ones reported with file and line", "[field]") {
  const auto parse = [](const std::string& text, std::string& error) {
    ScalarField f;
    return parseScalarField(text, "s.txt", 4, f, error) ? f.values : std::vector<double>{};
  };
  std::string error;
  CHECK(parse("# heights\nfgsg-field 1 scalar 4\n1\n-2.5 # a comment\n3e-1\n0\n", error) ==
        std::vector<double>{1, -2.5, 0.3, 0});
  const auto fails = [&](const std::string& text) {
    std::string e;
    CHECK(parse(text, e).empty());
    return e;
  };
  CHECK(fails("fgsg-field 1 vector 4\n") == "s.txt:1: expected the header 'fgsg-field 1 scalar <vertexCount>'");
  CHECK(fails("fgsg-field 1 scalar 5\n") == "s.txt:1: the field has 5 vertices, the surface 4");
  CHECK(fails("fgsg-field 1 scalar 4\n1 2\n") == "s.txt:2: expected one number, got '1' and 1 more");
  CHECK(fails("fgsg-field 1 scalar 4\nx\n") == "s.txt:2: expected one number, got 'x'");
  CHECK(fails("fgsg-field 1 scalar 4\ninf\n") == "s.txt:2: the value is not finite (inf)");
  CHECK(fails("fgsg-field 1 scalar 4\n1\n") == "s.txt: expected 4 vertex lines, got 1");
  CHECK(fails("fgsg-field 1 scalar 4\n1\n1\n1\n1\n1\n") == "s.txt:6: more vertex lines than the 4 the header announces");
  CHECK(fails("") == "s.txt: empty field file (expected the header 'fgsg-field 1 scalar <vertexCount>')");
}
