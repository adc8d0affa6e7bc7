#include "runtime/collision/merge_index.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace fgsg::rt {
namespace {

// The search grid's smallest reach: a merge distance of 0 still finds an instance at the
// very same place.
constexpr double kSmallestReach = 1e-9;

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
  return a.angularDistance(b) * 180.0 / std::numbers::pi;
}

}  // namespace

bool MergeIndex::find(uint32_t asset, const Mat4& transform, double maxDist,
                      double maxAngleDegrees, Merge& out, const Distance& distance) {
  if (entries_.empty() || !(maxDist >= 0)) return false;
  const Pose query = poseOf(transform);
  centres_.reserveRadius(std::max(maxDist, kSmallestReach));
  centres_.near(query.centre, maxDist, nearby_);
  double best = std::numeric_limits<double>::infinity();
  uint32_t bestSlot = 0;
  for (uint32_t slot : nearby_) {  // ascending: on a tie the earlier instance stays
    const Entry& e = entries_[slot];
    if (e.asset != asset) continue;
    const Pose other = poseOf(e.transform);
    double d = (other.centre - query.centre).norm();
    if (d > maxDist || angleDegrees(other.rotation, query.rotation) > maxAngleDegrees) continue;
    if (distance && (d = distance(slot, d)) > maxDist) continue;
    if (d < best) best = d, bestSlot = slot;
  }
  if (!std::isfinite(best)) return false;
  // The earlier instance moves to the mean of all it stands for, this one included.
  const Entry& target = entries_[bestSlot];
  const Pose a = poseOf(target.transform);
  const double w = 1.0 / (target.count + 1);
  Pose merged;
  merged.centre = (1 - w) * a.centre + w * query.centre;
  merged.size = (1 - w) * a.size + w * query.size;
  merged.rotation = a.rotation.slerp(w, query.rotation);
  out = {target.id, transformOf(merged), bestSlot};
  return true;
}

void MergeIndex::add(uint32_t asset, size_t id, const Mat4& transform) {
  const uint32_t slot = centres_.add(instanceCentre(transform));
  entries_.push_back({asset, id, transform, 1});
  log_.push_back({true, slot, Mat4::Identity()});
}

void MergeIndex::apply(const Merge& m) {
  Entry& e = entries_[m.slot];
  log_.push_back({false, m.slot, e.transform});
  e.transform = m.transform;
  ++e.count;
  centres_.move(m.slot, instanceCentre(m.transform));
}

std::vector<std::pair<size_t, Mat4>> MergeIndex::rollback(size_t mark) {
  std::vector<std::pair<size_t, Mat4>> undone;
  while (log_.size() > mark) {
    const LogItem item = log_.back();
    log_.pop_back();
    if (item.added) {  // adds are undone newest first, as the grid removes them
      centres_.removeLast();
      entries_.pop_back();
      continue;
    }
    Entry& e = entries_[item.slot];
    e.transform = item.before;
    --e.count;
    centres_.move(item.slot, instanceCentre(item.before));
    undone.emplace_back(e.id, item.before);
  }
  return undone;
}

}  // namespace fgsg::rt
