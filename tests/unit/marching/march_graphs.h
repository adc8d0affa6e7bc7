// Marching graphs for the smooth-terminal tests: polylines and branches on a sphere
// (normals radial) and on planes.
#pragma once

#include "runtime/marching/march_graph.h"

#include <cmath>
#include <random>
#include <vector>

namespace fgsg::test {

using rt::Vec3;
using rt::marching::MarchNode;
using rt::marching::MarchSegment;

struct Graph {
  std::vector<MarchNode> nodes;
  std::vector<MarchSegment> segments;
  uint32_t add(const Vec3& p, const Vec3& n) {
    nodes.push_back({p, n.normalized()});
    return uint32_t(nodes.size() - 1);
  }
  void join(uint32_t from, uint32_t to) { segments.push_back({from, to}); }
};

inline Vec3 onSphere(const Vec3& p, double radius) { return radius * p.normalized(); }

// A random walk of `steps` segments on the sphere of radius `radius` about the origin:
// each step turns by up to 60 degrees and is 0.05 to 0.3 long; node i -> node i+1.
inline Graph sphereWalk(unsigned seed, int steps, double radius) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1, 1), len(0.05, 0.3);
  Graph g;
  Vec3 p = onSphere(Vec3(unit(rng), unit(rng), unit(rng)) + Vec3(0, 0, 2), radius);
  Vec3 dir = p.unitOrthogonal();
  g.add(p, p);
  for (int i = 0; i < steps; ++i) {
    const Vec3 n = p.normalized();
    const double turn = unit(rng) * M_PI / 3;
    dir = (std::cos(turn) * (dir - n * n.dot(dir)).normalized() + std::sin(turn) * n.cross(dir).normalized())
              .normalized();
    p = onSphere(p + len(rng) * dir, radius);
    const uint32_t next = g.add(p, p);
    g.join(next - 1, next);
  }
  return g;
}

}  // namespace fgsg::test
