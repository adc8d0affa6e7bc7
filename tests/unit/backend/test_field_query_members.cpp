// FGSG §4.3's field queries on analytic fields: a linear vector field and a linear
// diagonal tensor field on a flat grid are interpolated exactly, so their Jacobians,
// divergences, curls, eigenvalue gradients, tensor components and streamline curvatures
// are known in closed form; a picture's colours under a scope, and Color taking them.
#include "derive_helpers.h"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <stb/stb_image_write.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

using namespace fgsg;

namespace {

namespace fs = std::filesystem;

// A 5 x 5 grid of vertices on [0, 4]^2 at z = 0, faces counter-clockwise seen from +Z,
// and a world field file with one value per vertex from `value(x, y)`.
std::string writeGridAndField(const std::string& name, const char* kind,
                              const std::function<std::string(double, double)>& value) {
  const fs::path dir = fs::temp_directory_path() / ("fgsg_field_members_" + name);
  fs::create_directories(dir);
  std::ofstream off(dir / "grid.off");
  off << "OFF\n25 32 0\n";
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 5; ++i) off << i << " " << j << " 0\n";
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const int v = 5 * j + i;
      off << "3 " << v << " " << v + 1 << " " << v + 6 << "\n3 " << v << " " << v + 6 << " " << v + 5 << "\n";
    }
  std::ofstream field(dir / "field.txt");
  field << "fgsg-field 1 " << kind << " 25" << (std::string(kind) == "scalar" ? "" : " world") << "\n";
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 5; ++i) field << value(i, j) << "\n";
  return dir.string();
}

struct Queried {
  Eigen::Vector3d x, y;  // the scope's unit X and Y axes
  std::vector<double> values;
};

// The axiom turns 30 degrees from the field's direction and passes the queries (a
// comma-separated list) to A, whose instance records them as its parameters.
Queried derive(const std::string& dir, const char* kind, const std::string& queries) {
  std::string params = "q0";
  for (size_t k = 0, count = 1; k < queries.size(); ++k)
    if (queries[k] == ',') params += ", q" + std::to_string(count++);
  const auto r = test::deriveText("surface \"" + dir + "/grid.off\";\nfield V = " + kind + "(\"" + dir +
                                  "/field.txt\");\nAxiom ~> RS(30) A(" + queries + ");\nA(" + params +
                                  ") ~> I(\"cube\");\n");
  REQUIRE(r.ok);
  const rt::Instance& inst = r.instances.instances.at(0);
  const Eigen::Matrix4d t = test::transformOf(inst);
  Queried q{t.block<3, 1>(0, 0).normalized(), t.block<3, 1>(0, 1).normalized(), {}};
  q.values.assign(r.instances.params.begin() + inst.firstParam,
                  r.instances.params.begin() + inst.firstParam + inst.paramCount);
  return q;
}

Eigen::Vector3d vec(const std::vector<double>& v, size_t at) { return {v[at], v[at + 1], v[at + 2]}; }

}  // namespace

TEST_CASE("field queries of a linear vector field are exact", "[surface][field]") {
  // v(x, y) = (a x + b y + c, d x + e y + f): J = [[a, b], [d, e]] everywhere.
  const double a = 0.3, b = -0.2, c = 1, d = 0.4, e = 0.1, f = 0.5;
  const std::string dir = writeGridAndField("vector", "vector", [&](double x, double y) {
    return std::to_string(a * x + b * y + c) + " " + std::to_string(d * x + e * y + f) + " 0";
  });
  const Queried q = derive(dir, "vector",
                           "V.div, V.div1, V.curl, V.curl1, V.jacobianX, V.jacobianY, V.streamcurv1, V.tensorXX, "
                           "V.tensorXY, V.tensorYY");
  REQUIRE(q.values.size() == 18);
  Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
  J << a, b, 0, d, e, 0, 0, 0, 0;
  const Eigen::Vector3d v(a * 2 + b * 2 + c, d * 2 + e * 2 + f, 0);  // the axiom stands at (2, 2, 0)
  const Eigen::Vector3d u = v.normalized(), n = Eigen::Vector3d::UnitZ();
  CHECK(q.values[0] == Approx(a + e).margin(1e-12));
  CHECK(q.values[1] == Approx(a + e).margin(1e-12));
  CHECK((vec(q.values, 2) - (d - b) * n).norm() < 1e-12);
  CHECK((vec(q.values, 5) - (d - b) * n).norm() < 1e-12);
  CHECK((vec(q.values, 8) - J * q.x).norm() < 1e-12);
  CHECK((vec(q.values, 11) - J * q.y).norm() < 1e-12);
  CHECK(q.values[14] == Approx(n.cross(u).dot(J * u) / v.norm()).margin(1e-12));
  // A vector field's tensor is v v^T / |v|.
  const Eigen::Matrix3d T = v * v.transpose() / v.norm();
  CHECK(q.values[15] == Approx(q.x.dot(T * q.x)).margin(1e-12));
  CHECK(q.values[16] == Approx(q.x.dot(T * q.y)).margin(1e-12));
  CHECK(q.values[17] == Approx(q.y.dot(T * q.y)).margin(1e-12));
}

TEST_CASE("field queries of a linear tensor field answer both eigenvector fields", "[surface][field]") {
  // T(x, y) = diag(3 + x, 1 + y / 2): at (2, 2) value1 = 5 along X, value2 = 2 along Y.
  const std::string dir = writeGridAndField("tensor", "tensor", [](double x, double y) {
    return std::to_string(3 + x) + " 0 0 " + std::to_string(1 + y / 2) + " 0 0";
  });
  const Queried q = derive(dir, "tensor",
                           "V.gradient, V.gradient2, V.div1, V.div2, V.curl2, V.jacobianX2, V.streamcurv1, "
                           "V.streamcurv2, V.tensorXX, V.tensorXY, V.tensorYY");
  REQUIRE(q.values.size() == 19);
  CHECK((vec(q.values, 0) - Eigen::Vector3d(1, 0, 0)).norm() < 1e-12);    // of value1 = 3 + x
  CHECK((vec(q.values, 3) - Eigen::Vector3d(0, 0.5, 0)).norm() < 1e-12);  // of value2 = 1 + y / 2
  // The eigenvector fields |value| v: (3 + x) X and (1 + y / 2) Y, signs arbitrary.
  CHECK(std::abs(q.values[6]) == Approx(1).margin(1e-12));
  CHECK(std::abs(q.values[7]) == Approx(0.5).margin(1e-12));
  CHECK(vec(q.values, 8).norm() < 1e-12);
  // J2 = +-[[0, 0], [0, 1/2]]: along X the minor field does not change.
  const Eigen::Vector3d j2 = vec(q.values, 11);
  CHECK((j2.cwiseAbs() - Eigen::Vector3d(0, 0.5 * std::abs(q.x.y()), 0)).norm() < 1e-12);
  CHECK(q.values[14] == Approx(0).margin(1e-12));  // straight lines
  CHECK(q.values[15] == Approx(0).margin(1e-12));
  const Eigen::Matrix3d T = Eigen::Vector3d(5, 2, 0).asDiagonal();
  CHECK(q.values[16] == Approx(q.x.dot(T * q.x)).margin(1e-12));
  CHECK(q.values[17] == Approx(q.x.dot(T * q.y)).margin(1e-12));
  CHECK(q.values[18] == Approx(q.y.dot(T * q.y)).margin(1e-12));
}

TEST_CASE("an image field answers the colour under the scope, and Color takes it as a vector", "[surface][field]") {
  // 4 x 4 pixels, red 60 x, green 30 y, blue 200: the surface's centre is pixel (1.5, 1.5).
  const fs::path dir = fs::temp_directory_path() / "fgsg_field_members_rgb";
  fs::create_directories(dir);
  std::vector<unsigned char> rgb;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) rgb.insert(rgb.end(), {(unsigned char)(60 * x), (unsigned char)(30 * y), 200});
  const std::string png = (dir / "ramp.png").string();
  REQUIRE(stbi_write_png(png.c_str(), 4, 4, 3, rgb.data(), 4 * 3) != 0);
  const auto r = test::deriveText("surface plane(4, 4);\nfield P = image(\"" + png +
                                  "\");\nAxiom ~> A(P.rgb);\nA(c) ~> Color(c) I(\"cube\") Color((dot(c, (1, 0, 0)), 0, 0)) I(\"cube\");\n");
  REQUIRE(r.ok);
  const rt::Instance& inst = r.instances.instances.at(0);
  const Eigen::Vector3d want(90 / 255.0, 45 / 255.0, 200 / 255.0);
  const double* c = r.instances.params.data() + inst.firstParam;
  CHECK((Eigen::Vector3d(c[0], c[1], c[2]) - want).norm() < 1e-6);
  CHECK((Eigen::Vector3f(inst.color[0], inst.color[1], inst.color[2]).cast<double>() - want).norm() < 1e-6);
  const rt::Instance& red = r.instances.instances.at(1);
  CHECK(red.color[0] == Approx(want.x()).margin(1e-6));
  CHECK(red.color[1] == 0);
  // A colour vector that draws random numbers must be written out.
  CHECK_THROWS_WITH(test::compileText("A ~> Color(normalize((Rand(0, 1), 1, 1))) I(\"cube\");"),
                    Catch::Contains("E016"));
  CHECK_NOTHROW(test::compileText("A ~> Color((Rand(0, 1), 1, 1)) I(\"cube\");"));
}

TEST_CASE("a scalar field answers its value and gradient exactly, and T follows the gradient", "[surface][field]") {
  // f(x, y) = 0.3 x - 0.2 y + 1, linear: value and gradient exact in every triangle.
  const std::string dir = writeGridAndField("scalar", "scalar", [](double x, double y) {
    return std::to_string(0.3 * x - 0.2 * y + 1);
  });
  const auto r = test::deriveText("surface \"" + dir + "/grid.off\";\nfield S = scalar(\"" + dir +
                                  "/field.txt\");\nAxiom ~> A(S.value, S.gradient, S.length) T(1, 0, 0) B(S.value);\n"
                                  "A(v, g, l) ~> I(\"cube\");\nB(v) ~> I(\"cube\");\n");
  REQUIRE(r.ok);
  const rt::Instance& a = r.instances.instances.at(0);
  const double* p = r.instances.params.data() + a.firstParam;
  CHECK(p[0] == Approx(0.3 * 2 - 0.2 * 2 + 1).margin(1e-12));
  CHECK((Eigen::Vector3d(p[1], p[2], p[3]) - Eigen::Vector3d(0.3, -0.2, 0)).norm() < 1e-12);
  CHECK(p[4] == Approx(std::hypot(0.3, -0.2)).margin(1e-12));
  // The axiom's X runs along the gradient, and T(1, 0, 0) climbs |gradient| in value.
  CHECK((test::transformOf(a).block<3, 1>(0, 0).normalized() - Eigen::Vector3d(0.3, -0.2, 0).normalized()).norm() <
        1e-9);
  const rt::Instance& b = r.instances.instances.at(1);
  CHECK(r.instances.params[b.firstParam] == Approx(1.2 + std::hypot(0.3, -0.2)).margin(1e-9));
}

TEST_CASE("an asymmetric tensor field: its queries, and T along its eigenvector basis", "[surface][field]") {
  // T = [[1, 0], [1, -1]] in the grid's plane: eigenvalues +-1, eigenvectors (2, 1)/sqrt 5
  // and (0, 1), 63.43 degrees apart; rotational part 0.5.
  const std::string dir = writeGridAndField("asymmetric", "asymmetric", [](double, double) {
    return "1 0 0 1 -1 0 0 0 0";
  });
  const auto r = test::deriveText(
      "surface \"" + dir + "/grid.off\";\nfield V = tensor(\"" + dir + "/field.txt\");\n"
      "Axiom ~> A(V.value1, V.value2, V.rotation, V.eigenangle, V.tensorXY, V.tensorYX) [ T(1, 0, 0) B ] "
      "[ T(0, 1, 0) B ];\nA(a, b, c, d, e, f) ~> I(\"cube\");\nB ~> I(\"cube\");\n");
  REQUIRE(r.ok);
  REQUIRE(r.instances.instances.size() == 4);  // and the surface, last
  CHECK(r.instances.assets[r.instances.instances[3].asset] != "cube");
  const double* p = r.instances.params.data() + r.instances.instances[0].firstParam;
  CHECK(p[0] == Approx(1).margin(1e-12));
  CHECK(p[1] == Approx(-1).margin(1e-12));
  CHECK(p[2] == Approx(0.5).margin(1e-12));
  CHECK(p[3] == Approx(90 - std::atan(0.5) * 180 / M_PI).margin(1e-9));
  // X along the major eigenvector and Y a quarter turn from it: X.T.Y = -1, Y.T.X = 0.
  CHECK(p[4] == Approx(-1).margin(1e-12));
  CHECK(p[5] == Approx(0).margin(1e-12));
  // The axiom's X runs along the major eigenvector; T(1, 0, 0) moves along it, T(0, 1, 0)
  // along the scope's Y, whose coordinates in the eigenvector basis it keeps (a constant
  // field: a straight move), and each end keeps X on the major eigenvector.
  const Eigen::Matrix4d a = test::transformOf(r.instances.instances[0]);
  const Eigen::Vector3d x = a.block<3, 1>(0, 0).normalized(), y = a.block<3, 1>(0, 1).normalized();
  CHECK(std::abs(x.dot(Eigen::Vector3d(2, 1, 0).normalized())) == Approx(1).margin(1e-9));
  const Eigen::Vector3d origin = test::unitPoint(r.instances.instances[0], 0, 0, 0);
  const Eigen::Vector3d along = test::unitPoint(r.instances.instances[1], 0, 0, 0) - origin;
  const Eigen::Vector3d across = test::unitPoint(r.instances.instances[2], 0, 0, 0) - origin;
  CHECK((along - x).norm() < 1e-9);
  CHECK((across - y).norm() < 1e-9);
  for (size_t k : {1, 2})
    CHECK(std::abs(test::transformOf(r.instances.instances[k]).block<3, 1>(0, 0).normalized().dot(x)) ==
          Approx(1).margin(1e-9));
}

TEST_CASE("a scalar field from an expression of x, y, z equals the same field from a file", "[surface][field]") {
  // The grid of the test above, and f = k x - 0.2 y + 1 with the attr k = 0.3 (or --set).
  const std::string dir = writeGridAndField("scalar_expression", "scalar", [](double, double) { return "0"; });
  const std::string grammar = "surface \"" + dir +
                              "/grid.off\";\nattr k = 0.1;\nfield S = scalar(k * x - 0.2 * y + 1 + 0 * z);\n"
                              "Axiom ~> A(S.value, S.gradient) T(1, 0, 0) B(S.value);\n"
                              "A(v, g) ~> I(\"cube\");\nB(v) ~> I(\"cube\");\n";
  rt::DeriveOptions options;
  options.attrOverrides = {{"k", "0.3"}};
  const auto r = test::deriveText(grammar, options);
  REQUIRE(r.ok);
  const double* p = r.instances.params.data() + r.instances.instances.at(0).firstParam;
  CHECK(p[0] == Approx(0.3 * 2 - 0.2 * 2 + 1).margin(1e-12));
  CHECK((Eigen::Vector3d(p[1], p[2], p[3]) - Eigen::Vector3d(0.3, -0.2, 0)).norm() < 1e-12);
  CHECK(r.instances.params[r.instances.instances.at(1).firstParam] ==
        Approx(1.2 + std::hypot(0.3, -0.2)).margin(1e-9));
  // The attr's default: k = 0.1.
  const auto d = test::deriveText(grammar);
  REQUIRE(d.ok);
  CHECK(d.instances.params[d.instances.instances.at(0).firstParam] == Approx(0.1 * 2 - 0.2 * 2 + 1).margin(1e-12));
  // A value that is not finite at some vertex is a located error.
  const auto bad = test::deriveText("surface \"" + dir + "/grid.off\";\nfield S = scalar(1 / x);\n"
                                    "Axiom ~> A(S.value);\nA(v) ~> I(\"cube\");\n");
  REQUIRE_FALSE(bad.ok);
  CHECK(bad.messages[0].code == "R015");
  CHECK(bad.messages[0].line == 2);
  CHECK_THAT(bad.messages[0].message, Catch::Contains("field S: the expression is inf at vertex 0 (0.000000, "));
}

TEST_CASE("a scalar field from a picture is its brightness, and bad scalar files are located errors",
          "[surface][field]") {
  const fs::path dir = fs::temp_directory_path() / "fgsg_field_members_scalar_png";
  fs::create_directories(dir);
  const unsigned char grey[4] = {0, 102, 204, 255};  // 2 x 2
  const std::string png = (dir / "grey.png").string();
  REQUIRE(stbi_write_png(png.c_str(), 2, 2, 1, grey, 2) != 0);
  const auto r = test::deriveText("surface plane(4, 4);\nfield S = scalar(\"" + png +
                                  "\");\nAxiom ~> A(S.value);\nA(v) ~> I(\"cube\");\n");
  REQUIRE(r.ok);
  // The plane's centre is the picture's centre: the mean of the four pixels.
  CHECK(r.instances.params[r.instances.instances[0].firstParam] == Approx((0 + 102 + 204 + 255) / 4.0 / 255).margin(1e-6));
  std::ofstream(dir / "short.sfield") << "fgsg-field 1 scalar 3\n1\n2\n3\n";
  const auto bad = test::deriveText("surface plane(4, 4);\nfield S = scalar(\"" + (dir / "short.sfield").string() +
                                    "\");\nAxiom ~> A(S.value);\nA(v) ~> I(\"cube\");\n");
  REQUIRE_FALSE(bad.ok);
  CHECK(bad.messages[0].code == "R015");
  CHECK_THAT(bad.messages[0].message, Catch::Contains("short.sfield:1: the field has 3 vertices"));
}
