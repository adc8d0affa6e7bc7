#include "runtime/synthesis/continuous/example_solid.h"

#include "runtime/io/read_input.h"
#include "runtime/surface/read_textured_mesh.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <unordered_map>

namespace fgsg::rt::synthesis::continuous {

namespace {

DVec3 sub(const DVec3& a, const DVec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot3(const DVec3& a, const DVec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
DVec3 cross3(const DVec3& a, const DVec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double len(const DVec3& a) { return std::sqrt(dot3(a, a)); }

std::string vec(const DVec3& v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.3f, %.3f, %.3f)", v[0], v[1], v[2]);
  return buf;
}

// Newell's normal (area-weighted, any polygon).
DVec3 newell(const ExampleSolid& s, const std::vector<int>& poly) {
  DVec3 n{0, 0, 0};
  for (size_t i = 0; i < poly.size(); ++i) {
    const DVec3& a = s.vertices[size_t(poly[i])];
    const DVec3& b = s.vertices[size_t(poly[(i + 1) % poly.size()])];
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  return n;
}

}  // namespace

bool makeExampleSolid(const io::MeshFileContent& mesh, const std::string& name, ExampleSolid& out, std::string& error,
                      Deadline* deadline) {
  out = ExampleSolid{};
  out.name = name;
  // Asked once per vertex, face, edge: cheap (Deadline reads the clock now and then).
  auto timeUp = [&] {
    if (!deadline || !deadline->expired()) return false;
    error = io::readStoppedMessage(name, *deadline);
    return true;
  };
  const size_t polygons = mesh.polygonCount();
  if (polygons < 4) {
    error = name + ": a continuous example is a closed solid; this file has " + std::to_string(polygons) +
            " face(s)";
    return false;
  }
  // Weld corners at the same position (an STL repeats them per triangle).
  std::map<DVec3, int> index;
  std::vector<int> welded(mesh.vertices.size());
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (timeUp()) return false;
    auto [it, added] = index.emplace(mesh.vertices[v], int(out.vertices.size()));
    if (added) out.vertices.push_back(mesh.vertices[v]);
    welded[v] = it->second;
  }
  DVec3 lo = out.vertices[0], hi = out.vertices[0];
  for (const auto& v : out.vertices)
    for (int i = 0; i < 3; ++i) {
      lo[size_t(i)] = std::min(lo[size_t(i)], v[size_t(i)]);
      hi[size_t(i)] = std::max(hi[size_t(i)], v[size_t(i)]);
    }
  out.diagonal = len(sub(hi, lo));
  if (!(out.diagonal > 0)) { error = name + ": the example has no extent"; return false; }

  for (size_t p = 0; p < polygons; ++p) {
    if (timeUp()) return false;
    std::vector<int> poly;
    for (size_t c = mesh.polygonStart[p]; c < mesh.polygonStart[p + 1]; ++c) {
      const int v = welded[size_t(mesh.corners[c])];
      if (poly.empty() || (poly.back() != v && !(c + 1 == mesh.polygonStart[p + 1] && poly.front() == v)))
        poly.push_back(v);
    }
    const std::string where = name + ": face " + std::to_string(p + 1);
    if (poly.size() < 3) { error = where + " has fewer than three distinct corners"; return false; }
    const DVec3 n = newell(out, poly);
    const double area2 = len(n);
    if (area2 < 1e-12 * out.diagonal * out.diagonal) { error = where + " has no area"; return false; }
    const DVec3 u{n[0] / area2, n[1] / area2, n[2] / area2};
    const DVec3& o = out.vertices[size_t(poly[0])];
    for (int v : poly)
      if (std::abs(dot3(sub(out.vertices[size_t(v)], o), u)) > 1e-6 * out.diagonal) {
        error = where + " is not planar (its corner at " + vec(out.vertices[size_t(v)]) + " is off its plane)";
        return false;
      }
    const auto a = snapToIntegerDirection(u, kMaxDirectionComponent, kDirectionToleranceDegrees * 3.14159265358979 / 180);
    if (!a) {
      error = where + "'s normal " + vec(u) + " is not within " + std::to_string(kDirectionToleranceDegrees).substr(0, 3) +
              " degrees of an integer direction with components up to " + std::to_string(kMaxDirectionComponent) +
              ": continuous synthesis puts faces on lattice planes (docs/synthesis.md, \"Continuous\")";
      return false;
    }
    auto it = std::find(out.dirs.begin(), out.dirs.end(), *a);
    if (it == out.dirs.end()) {
      if (int(out.dirs.size()) >= kMaxDirections) {
        error = name + ": more than " + std::to_string(kMaxDirections) + " distinct face directions";
        return false;
      }
      it = out.dirs.insert(out.dirs.end(), *a);
    }
    out.polygonDirection.push_back(int(it - out.dirs.begin()));
    out.polygonAlong.push_back(dotd(*a, u) > 0);
    out.polygons.push_back(std::move(poly));
  }
  out.faceDirections = int(out.dirs.size());
  for (IVec3 axis : {IVec3{1, 0, 0}, IVec3{0, 1, 0}, IVec3{0, 0, 1}})
    if (std::find(out.dirs.begin(), out.dirs.end(), axis) == out.dirs.end()) out.dirs.push_back(axis);

  // Closed and consistently oriented: every directed edge has exactly one reverse.
  std::unordered_map<uint64_t, int> directed;  // (a, b) -> face
  auto key = [](int a, int b) { return (uint64_t(uint32_t(a)) << 32) | uint32_t(b); };
  auto corner = [&](int v) { return vec(out.vertices[size_t(v)]); };
  for (size_t p = 0; p < out.polygons.size(); ++p) {
    if (timeUp()) return false;
    const auto& poly = out.polygons[p];
    for (size_t i = 0; i < poly.size(); ++i) {
      const int a = poly[i], b = poly[(i + 1) % poly.size()];
      auto [it, added] = directed.emplace(key(a, b), int(p));
      if (!added) {
        error = name + ": faces " + std::to_string(it->second + 1) + " and " + std::to_string(p + 1) +
                " both run from " + corner(a) + " to " + corner(b) +
                " (oriented inconsistently, or more than two faces share the edge)";
        return false;
      }
    }
  }
  for (size_t p = 0; p < out.polygons.size(); ++p) {  // in file order: the first open edge
    if (timeUp()) return false;
    const auto& poly = out.polygons[p];
    for (size_t i = 0; i < poly.size(); ++i) {
      const int a = poly[i], b = poly[(i + 1) % poly.size()];
      if (!directed.count(key(b, a))) {
        error = name + ": the solid is not closed: the edge from " + corner(a) + " to " + corner(b) + " of face " +
                std::to_string(p + 1) + " has no face on its other side";
        return false;
      }
    }
  }
  // Manifold vertices: the faces around each vertex form one fan (one cycle of edges).
  std::vector<std::vector<std::pair<int, int>>> around(out.vertices.size());  // v -> (prev, next)
  for (const auto& poly : out.polygons)
    for (size_t i = 0; i < poly.size(); ++i)
      around[size_t(poly[(i + 1) % poly.size()])].push_back({poly[i], poly[(i + 2) % poly.size()]});
  for (size_t v = 0; v < around.size(); ++v) {
    if (timeUp()) return false;
    const auto& fan = around[v];
    if (fan.empty()) continue;
    // Walk next -> prev links from the first corner; a single cycle visits them all.
    size_t steps = 0;
    int at = fan[0].second;
    for (; steps < fan.size(); ++steps) {
      auto it = std::find_if(fan.begin(), fan.end(), [&](const auto& c) { return c.first == at; });
      if (it == fan.end()) break;
      at = it->second;
      if (at == fan[0].second) { ++steps; break; }
    }
    if (steps != fan.size()) {
      error = name + ": the solid is not a manifold at the vertex " + corner(int(v)) +
              " (two parts of it touch only there)";
      return false;
    }
  }
  // Outward: a positive volume (else every face is turned).
  double volume = 0;
  for (const auto& poly : out.polygons)
    for (size_t i = 1; i + 1 < poly.size(); ++i)
      volume += dot3(out.vertices[size_t(poly[0])], cross3(out.vertices[size_t(poly[i])], out.vertices[size_t(poly[i + 1])]));
  if (volume < 0) {
    for (auto& poly : out.polygons) std::reverse(poly.begin(), poly.end());
    for (size_t p = 0; p < out.polygonAlong.size(); ++p) out.polygonAlong[p] = !out.polygonAlong[p];
  }
  return true;
}

bool loadExampleSolid(const std::string& path, ExampleSolid& out, std::string& error, Deadline* deadline) {
  io::MeshFileContent mesh;
  std::string ext = path.substr(std::min(path.size(), path.find_last_of('.')));
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".glb" || ext == ".gltf") {
    // glTF through assimp (as textured surfaces are read): triangles, corners welded by
    // makeExampleSolid, so coplanar triangles act as one face.
    std::string bytes;
    surface::SurfaceMesh read;
    bool polygonal = false;
    if (!io::readInputFile(path, "a mesh file", bytes, error) ||
        !surface::readTexturedMesh(path, bytes, read, polygonal, error))
      return false;
    for (const auto& v : read.vertices) mesh.vertices.push_back({v.x(), v.y(), v.z()});
    for (const auto& f : read.faces) {
      mesh.corners.insert(mesh.corners.end(), f.begin(), f.end());
      mesh.polygonStart.push_back(mesh.corners.size());
    }
  } else if (!io::readMeshFile(path, mesh, error, deadline)) {
    return false;
  }
  if (deadline && deadline->expiredNow()) {
    error = io::readStoppedMessage(path, *deadline);
    return false;
  }
  return makeExampleSolid(mesh, path, out, error, deadline);
}

double windingNumber(const ExampleSolid& s, const DVec3& p) {
  double total = 0;
  for (const auto& poly : s.polygons) {
    const DVec3 a = sub(s.vertices[size_t(poly[0])], p);
    const double la = len(a);
    for (size_t i = 1; i + 1 < poly.size(); ++i) {
      const DVec3 b = sub(s.vertices[size_t(poly[i])], p), c = sub(s.vertices[size_t(poly[i + 1])], p);
      const double lb = len(b), lc = len(c);
      const double num = dot3(a, cross3(b, c));
      const double den = la * lb * lc + dot3(a, b) * lc + dot3(a, c) * lb + dot3(b, c) * la;
      total += 2 * std::atan2(num, den);
    }
  }
  return total / (4 * 3.14159265358979323846);
}

}  // namespace fgsg::rt::synthesis::continuous
