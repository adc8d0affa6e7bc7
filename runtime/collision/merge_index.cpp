#include "runtime/collision/merge_index.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fgsg::rt {
namespace {

constexpr double kPi = 3.14159265358979323846;

// An instance transform as rotation, per-axis size and centre (scope transforms are
// rotation x size; a mirror is folded into the first size).
struct Pose {
  Eigen::Quaterniond rotation;
  Vec3 size;
  Vec3 centre;
};

Pose poseOf(const Mat4& M) {
  Pose p;
  Mat3 A = M.block<3, 3>(0, 0);
  Mat3 R = Mat3::Identity();
  for (int k = 0; k < 3; ++k) {
    p.size[k] = A.col(k).norm();
    if (p.size[k] > 0) R.col(k) = A.col(k) / p.size[k];
  }
  // A flattened axis has no direction of its own: complete it from the other two.
  for (int k = 0; k < 3; ++k)
    if (p.size[k] == 0) R.col(k) = R.col((k + 1) % 3).cross(R.col((k + 2) % 3));
  if (R.determinant() < 0) {
    R.col(0) = -R.col(0);
    p.size[0] = -p.size[0];
  }
  p.rotation = Eigen::Quaterniond(R).normalized();
  p.centre = instanceCentre(M);
  return p;
}

Mat4 transformOf(const Pose& p) {
  Mat4 M = Mat4::Identity();
  const Mat3 linear = p.rotation.toRotationMatrix() * p.size.asDiagonal();
  M.block<3, 3>(0, 0) = linear;
  M.block<3, 1>(0, 3) = p.centre - linear * Vec3::Constant(0.5);
  return M;
}

double angleDegrees(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  return a.angularDistance(b) * 180.0 / kPi;
}

}  // namespace

Vec3 instanceCentre(const Mat4& M) {
  return (M * Eigen::Vector4d(0.5, 0.5, 0.5, 1.0)).head<3>();
}

void MergeIndex::cellOf(const Vec3& p, int64_t* c) const {
  for (int k = 0; k < 3; ++k) c[k] = static_cast<int64_t>(std::floor(p[k] / cell_));
}

uint64_t MergeIndex::key(int64_t x, int64_t y, int64_t z) {
  return (static_cast<uint64_t>(x) * 0x9E3779B97F4A7C15ull) ^
         (static_cast<uint64_t>(y) * 0xC2B2AE3D27D4EB4Full) ^
         (static_cast<uint64_t>(z) * 0x165667B19E3779F9ull);
}

void MergeIndex::linkToCell(size_t id) {
  int64_t c[3];
  cellOf(instanceCentre(entries_.at(id).transform), c);
  cellOfId_[id] = {c[0], c[1], c[2]};
  auto& bucket = grid_[key(c[0], c[1], c[2])];
  bucket.insert(std::lower_bound(bucket.begin(), bucket.end(), id), id);
}

void MergeIndex::unlinkFromCell(size_t id) {
  const auto& c = cellOfId_.at(id);
  auto& bucket = grid_[key(c[0], c[1], c[2])];
  bucket.erase(std::lower_bound(bucket.begin(), bucket.end(), id));
  cellOfId_.erase(id);
}

bool MergeIndex::find(uint32_t asset, const Mat4& transform, double maxDist,
                      double maxAngleDegrees, Merge& out) const {
  if (entries_.empty() || !(maxDist >= 0)) return false;
  const Pose query = poseOf(transform);
  int64_t c[3];
  cellOf(query.centre, c);
  const int64_t reach = static_cast<int64_t>(std::ceil(maxDist / cell_));
  double best = std::numeric_limits<double>::infinity();
  size_t bestId = 0;
  for (int64_t dx = -reach; dx <= reach; ++dx)
    for (int64_t dy = -reach; dy <= reach; ++dy)
      for (int64_t dz = -reach; dz <= reach; ++dz) {
        auto it = grid_.find(key(c[0] + dx, c[1] + dy, c[2] + dz));
        if (it == grid_.end()) continue;
        for (size_t id : it->second) {
          const Entry& e = entries_.at(id);
          if (e.asset != asset) continue;
          const Pose other = poseOf(e.transform);
          const double d = (other.centre - query.centre).norm();
          if (d > maxDist || angleDegrees(other.rotation, query.rotation) > maxAngleDegrees) continue;
          if (d < best || (d == best && id < bestId)) best = d, bestId = id;
        }
      }
  if (!std::isfinite(best)) return false;
  // The earlier instance moves to the mean of all it stands for, this one included.
  const Entry& target = entries_.at(bestId);
  const Pose a = poseOf(target.transform);
  const double w = 1.0 / (target.count + 1);
  Pose merged;
  merged.centre = (1 - w) * a.centre + w * query.centre;
  merged.size = (1 - w) * a.size + w * query.size;
  merged.rotation = a.rotation.slerp(w, query.rotation);
  out = {bestId, transformOf(merged)};
  return true;
}

void MergeIndex::add(uint32_t asset, size_t id, const Mat4& transform, double maxDist) {
  if (cell_ == 0) cell_ = maxDist > 0 && std::isfinite(maxDist) ? maxDist : 1.0;
  entries_[id] = {asset, transform, 1};
  linkToCell(id);
  log_.push_back({true, id, Mat4::Identity()});
}

void MergeIndex::apply(const Merge& m) {
  Entry& e = entries_.at(m.target);
  log_.push_back({false, m.target, e.transform});
  unlinkFromCell(m.target);
  e.transform = m.transform;
  ++e.count;
  linkToCell(m.target);
}

std::vector<std::pair<size_t, Mat4>> MergeIndex::rollback(size_t mark) {
  std::vector<std::pair<size_t, Mat4>> undone;
  while (log_.size() > mark) {
    const LogItem item = log_.back();
    log_.pop_back();
    unlinkFromCell(item.id);
    if (item.added) {
      entries_.erase(item.id);
      continue;
    }
    Entry& e = entries_.at(item.id);
    e.transform = item.before;
    --e.count;
    linkToCell(item.id);
    undone.emplace_back(item.id, item.before);
  }
  return undone;
}

}  // namespace fgsg::rt
