// The arrangement of the output's planes inside its box (Merrell §4.5, Algorithm 4.1 step
// 1): for each direction a_i the planes a_i·x = step_i·k (x in lattice units, k integer),
// the vertices where three or more of them meet, and the edges between consecutive
// vertices on every line where two meet. Positions are exact rationals (num / den), so
// "four planes meet here" is decided exactly.
//
// The box is [0, box] in lattice units; the coordinate axes are always among the
// directions, so its sides are planes and the vertices on them are the arrangement's
// boundary (kept outside the solid by the solver).
#pragma once

#include "runtime/synthesis/continuous/directions.h"

#include <array>
#include <functional>
#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::rt::synthesis::continuous {

struct Arrangement {
  std::vector<IVec3> dirs;
  std::vector<int64_t> step;
  std::array<int64_t, 3> box{};

  std::vector<IVec3> num;           // vertex v is num[v] / den[v]
  std::vector<int64_t> den;
  std::vector<uint32_t> planes;     // the directions with a plane through the vertex
  std::vector<uint8_t> boundary;    // on a side of the box
  // Edges, per vertex (CSR): the vertex at the other end and the line it runs along,
  // +(i + 1) along lines[i], -(i + 1) against it.
  std::vector<uint32_t> edgeStart;
  std::vector<int32_t> edgeTo;
  std::vector<int32_t> edgeLine;
  std::vector<IVec3> lines;         // canonical directions of the lines

  size_t vertexCount() const { return den.size(); }
  size_t edgeCount() const { return edgeTo.size() / 2; }
  DVec3 position(size_t v) const {
    const double d = double(den[v]);
    return {double(num[v][0]) / d, double(num[v][1]) / d, double(num[v][2]) / d};
  }
  IVec3 edgeDirection(size_t e) const {
    const int32_t l = edgeLine[e];
    const IVec3& d = lines[size_t(std::abs(l) - 1)];
    return l > 0 ? d : IVec3{-d[0], -d[1], -d[2]};
  }
};

// Builds it; false with a message when it would have more than `maxVertices` vertices,
// or when `timeUp` (asked every few thousand vertices, from several threads at once)
// says the time is up.
bool buildArrangement(const std::vector<IVec3>& dirs, const std::vector<int64_t>& step,
                      std::array<int64_t, 3> box, size_t maxVertices, Arrangement& out, std::string& error,
                      const std::function<bool()>& timeUp = [] { return false; });

}  // namespace fgsg::rt::synthesis::continuous
