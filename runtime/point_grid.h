// A uniform hash grid over points (the centres of line segments, of collision-tested or
// mergeable instances): which entries lie within a radius of a query point. Entries are
// numbered densely in insertion order, may move, and are removed newest first, which is
// what line networks, collision worlds, merging and their rollbacks need.
#pragma once

#include "runtime/scope.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace fgsg::rt {

class PointGrid {
 public:
  // Adds an entry and returns its id (the number of entries before it).
  uint32_t add(const Vec3& centre) {
    const uint32_t id = uint32_t(centres_.size());
    centres_.push_back(centre);
    if (cell_ > 0) cells_[keyOf(centre)].push_back(id);
    return id;
  }

  // Removes the newest entry. Ids ascend within a cell, so it is the last of its cell.
  void removeLast() {
    if (centres_.empty()) return;
    if (cell_ > 0) {
      auto it = cells_.find(keyOf(centres_.back()));
      it->second.pop_back();
      if (it->second.empty()) cells_.erase(it);
    }
    centres_.pop_back();
  }

  // Moves entry `id` to `centre` (a merged instance attracted towards its twin).
  void move(uint32_t id, const Vec3& centre) {
    if (cell_ > 0) {
      auto it = cells_.find(keyOf(centres_[id]));
      it->second.erase(std::lower_bound(it->second.begin(), it->second.end(), id));
      if (it->second.empty()) cells_.erase(it);
      auto& to = cells_[keyOf(centre)];
      to.insert(std::lower_bound(to.begin(), to.end(), id), id);  // keep ids ascending
    }
    centres_[id] = centre;
  }

  const Vec3& centre(uint32_t id) const { return centres_[id]; }
  size_t size() const { return centres_.size(); }
  double cellSize() const { return cell_; }

  // Makes queries up to `radius` possible: a query looks at the 3x3x3 cells around its
  // point, which cover the radius only while cells are at least that large. Cells grow
  // by doubling at least, so a slowly growing radius costs few rebuilds.
  void reserveRadius(double radius) {
    if (!(radius > cell_)) return;
    cell_ = std::max(radius, 2 * cell_);
    cells_.clear();
    for (uint32_t id = 0; id < centres_.size(); ++id) cells_[keyOf(centres_[id])].push_back(id);
  }

  // Ids of the entries whose centre lies within `radius` (at most the reserved radius) of
  // `p`, ascending: callers see the same order whatever the cell size or hash order.
  void near(const Vec3& p, double radius, std::vector<uint32_t>& out) const {
    out.clear();
    if (cell_ <= 0) return;
    const Key k = keyOf(p);
    for (int64_t dx = -1; dx <= 1; ++dx)
      for (int64_t dy = -1; dy <= 1; ++dy)
        for (int64_t dz = -1; dz <= 1; ++dz) {
          auto it = cells_.find({k.x + dx, k.y + dy, k.z + dz});
          if (it == cells_.end()) continue;
          for (uint32_t id : it->second)
            if ((centres_[id] - p).squaredNorm() <= radius * radius) out.push_back(id);
        }
    std::sort(out.begin(), out.end());
  }

 private:
  struct Key {
    int64_t x, y, z;
    bool operator==(const Key& o) const { return x == o.x && y == o.y && z == o.z; }
  };
  struct KeyHash {
    size_t operator()(const Key& k) const {
      uint64_t h = uint64_t(k.x) * 0x9e3779b97f4a7c15ull;
      h = (h ^ (h >> 29)) + uint64_t(k.y) * 0xbf58476d1ce4e5b9ull;
      h = (h ^ (h >> 29)) + uint64_t(k.z) * 0x94d049bb133111ebull;
      return size_t(h ^ (h >> 31));
    }
  };

  // Cell coordinates beyond this are clamped (and NaN maps to 0): the conversion to an
  // integer must stay defined, and such far-off points only share cells with each other.
  static constexpr double kMaxCellIndex = 1e15;

  int64_t cellIndex(double c) const {
    const double i = std::floor(c / cell_);
    if (!(i == i)) return 0;
    return int64_t(std::clamp(i, -kMaxCellIndex, kMaxCellIndex));
  }
  Key keyOf(const Vec3& p) const { return {cellIndex(p.x()), cellIndex(p.y()), cellIndex(p.z())}; }

  double cell_ = 0;  // edge length of a cell; 0 until the first reserveRadius
  std::vector<Vec3> centres_;
  std::unordered_map<Key, std::vector<uint32_t>, KeyHash> cells_;
};

}  // namespace fgsg::rt
