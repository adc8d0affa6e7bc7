// decomposeTrs (runtime/output/trs.h): which instance transforms glTF's TRS can express
// (EXT_mesh_gpu_instancing), which only as a mirrored node, and which must be baked.
#include "runtime/output/trs.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <array>
#include <cmath>

using fgsg::rt::output::composeTrs;
using fgsg::rt::output::decomposeTrs;
using fgsg::rt::output::Trs;
using fgsg::rt::output::TrsFit;

namespace {

std::array<double, 16> matrix(const Eigen::Matrix3d& linear, const Eigen::Vector3d& t) {
  std::array<double, 16> m{};
  Eigen::Map<Eigen::Matrix4d> M(m.data());
  M.setIdentity();
  M.block<3, 3>(0, 0) = linear;
  M.block<3, 1>(0, 3) = t;
  return m;
}

double maxDifference(const std::array<double, 16>& a, const std::array<double, 16>& b) {
  double d = 0;
  for (int k = 0; k < 16; ++k) d = std::max(d, std::abs(a[k] - b[k]));
  return d;
}

const Eigen::Matrix3d kTurn =
    Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();

}  // namespace

TEST_CASE("a rigid transform is a translation and a unit quaternion", "[output]") {
  const auto m = matrix(kTurn, {5, -2, 300.25});
  Trs trs;
  REQUIRE(decomposeTrs(m, trs) == TrsFit::Rigid);
  CHECK(trs.translation == std::array<double, 3>{5, -2, 300.25});
  for (double s : trs.scale) CHECK(s == Approx(1).epsilon(1e-12));
  const double norm = std::sqrt(trs.rotation[0] * trs.rotation[0] + trs.rotation[1] * trs.rotation[1] +
                                trs.rotation[2] * trs.rotation[2] + trs.rotation[3] * trs.rotation[3]);
  CHECK(norm == Approx(1).epsilon(1e-12));
  CHECK(trs.rotation[3] >= 0);
  CHECK(maxDifference(composeTrs(trs), m) < 1e-12);
}

TEST_CASE("uniform and per-axis scales are the SCALE of a rotation", "[output]") {
  Trs trs;
  const auto uniform = matrix(kTurn * 2.5, {1, 2, 3});
  REQUIRE(decomposeTrs(uniform, trs) == TrsFit::Rigid);
  for (double s : trs.scale) CHECK(s == Approx(2.5));
  CHECK(maxDifference(composeTrs(trs), uniform) < 1e-12);
  // A scope's size: scales along the asset's own axes, then turned.
  const auto box = matrix(kTurn * Eigen::Vector3d(3, 0.5, 12).asDiagonal(), {0, 0, 0});
  REQUIRE(decomposeTrs(box, trs) == TrsFit::Rigid);
  CHECK(trs.scale[0] == Approx(3));
  CHECK(trs.scale[1] == Approx(0.5));
  CHECK(trs.scale[2] == Approx(12));
  CHECK(maxDifference(composeTrs(trs), box) < 1e-12);
}

TEST_CASE("a mirror has a negative scale and is not instanced", "[output]") {
  const auto m = matrix(kTurn * Eigen::Vector3d(-2, 1, 1).asDiagonal(), {4, 0, 0});
  Trs trs;
  REQUIRE(decomposeTrs(m, trs) == TrsFit::Mirrored);
  CHECK(trs.scale[0] < 0);
  CHECK(maxDifference(composeTrs(trs), m) < 1e-12);
}

TEST_CASE("a shear or a scale across the turned axes falls back", "[output]") {
  Trs trs;
  Eigen::Matrix3d shear = Eigen::Matrix3d::Identity();
  shear(0, 1) = 0.3;
  CHECK(decomposeTrs(matrix(shear, {0, 0, 0}), trs) == TrsFit::Sheared);
  // Scaled along world axes after a turn: the columns are no longer orthogonal.
  const Eigen::Matrix3d across = Eigen::Vector3d(1, 4, 1).asDiagonal() * kTurn;
  CHECK(decomposeTrs(matrix(across, {0, 0, 0}), trs) == TrsFit::Sheared);
  // A projective last row has no TRS either.
  auto projective = matrix(kTurn, {0, 0, 0});
  projective[3] = 0.1;
  CHECK(decomposeTrs(projective, trs) == TrsFit::Sheared);
}

TEST_CASE("a flattened axis is baked, unless the mesh has no extent along it", "[output]") {
  Trs trs;
  const auto face = matrix(kTurn * Eigen::Vector3d(3, 2, 0).asDiagonal(), {1, 1, 1});
  CHECK(decomposeTrs(face, trs) == TrsFit::Degenerate);
  // A CGA face's own geometry lies at z = 0: the zero column becomes the face's normal.
  REQUIRE(decomposeTrs(face, trs, 2) == TrsFit::Rigid);
  CHECK(trs.scale[2] == 1);
  const auto recomposed = composeTrs(trs);
  for (int k = 0; k < 8; ++k) CHECK(recomposed[k] == Approx(face[k]).margin(1e-12));
  for (int k = 12; k < 16; ++k) CHECK(recomposed[k] == face[k]);
  const Eigen::Vector3d normal = Eigen::Map<const Eigen::Matrix4d>(recomposed.data()).block<3, 1>(0, 2);
  CHECK((normal - kTurn.col(2)).norm() < 1e-12);
  // Two flat axes (a line) or a non-finite entry: baked.
  CHECK(decomposeTrs(matrix(Eigen::Vector3d(3, 0, 0).asDiagonal(), {0, 0, 0}), trs, 2) == TrsFit::Degenerate);
  auto nan = matrix(kTurn, {0, 0, 0});
  nan[13] = NAN;
  CHECK(decomposeTrs(nan, trs) == TrsFit::Degenerate);
}
