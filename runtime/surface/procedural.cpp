#include "runtime/surface/procedural.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <unordered_map>

namespace fgsg::rt::surface {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kMaxSegments = 4096;
// The union of three tori is computed exactly and remeshed: keep it to seconds.
constexpr int kMaxTori3Segments = 256;
constexpr int kMaxSphereSubdivisions = 8;
constexpr int kMaxGenus2Levels = 6;

// Splits every cell of a (columns + 1) x (rows + 1) vertex grid, vertex (i, j) at
// index j * (columns + 1) + i, into two triangles, counter-clockwise when i runs along
// the first and j along the second tangent of an outward frame. `wrapI` closes the grid
// around in i (the last column joins the first), `wrapJ` in j (the last row joins the
// first; the vertices then hold `rows` rows, not rows + 1).
void gridFaces(SurfaceMesh& m, int columns, int rows, bool wrapI, bool wrapJ = false) {
  const int stride = wrapI ? columns : columns + 1;
  auto at = [&](int i, int j) { return (wrapJ ? j % rows : j) * stride + (wrapI ? i % columns : i); };
  m.faces.reserve(size_t(2) * columns * rows);
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const int a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      // Alternating diagonals keep the grid free of a preferred direction.
      if ((i + j) % 2 == 0) {
        m.faces.push_back({a, b, c});
        m.faces.push_back({a, c, d});
      } else {
        m.faces.push_back({a, b, d});
        m.faces.push_back({b, c, d});
      }
    }
}

// ---- genus 2: Catmull-Clark subdivision of a polycube cage ----

using Quad = std::array<int, 4>;

struct QuadMesh {
  std::vector<Vec3> v;
  std::vector<Quad> q;
};

QuadMesh catmullClark(const QuadMesh& in) {
  QuadMesh out;
  const int nv = int(in.v.size()), nq = int(in.q.size());
  // Edges of a closed quad mesh: each has exactly two faces.
  std::unordered_map<uint64_t, int> edgeIndex;
  std::vector<std::array<int, 2>> edgeEnds, edgeFaces;
  auto edgeOf = [&](int a, int b, int face) {
    const uint64_t key = (uint64_t(uint32_t(std::min(a, b))) << 32) | uint32_t(std::max(a, b));
    auto [it, fresh] = edgeIndex.try_emplace(key, int(edgeEnds.size()));
    if (fresh) {
      edgeEnds.push_back({a, b});
      edgeFaces.push_back({face, -1});
    } else {
      edgeFaces[it->second][1] = face;
    }
    return it->second;
  };
  std::vector<std::array<int, 4>> quadEdges(nq);
  for (int f = 0; f < nq; ++f)
    for (int k = 0; k < 4; ++k) quadEdges[f][k] = edgeOf(in.q[f][k], in.q[f][(k + 1) % 4], f);
  const int ne = int(edgeEnds.size());

  std::vector<Vec3> facePoint(nq);
  for (int f = 0; f < nq; ++f) {
    facePoint[f] = Vec3::Zero();
    for (int k = 0; k < 4; ++k) facePoint[f] += in.v[in.q[f][k]] / 4;
  }
  // Vertex rule (Q + 2R + (n - 3) S) / n with Q the mean face point, R the mean edge
  // midpoint, n the valence.
  std::vector<Vec3> sumQ(nv, Vec3::Zero()), sumR(nv, Vec3::Zero());
  std::vector<int> valence(nv, 0);
  for (int f = 0; f < nq; ++f)
    for (int k = 0; k < 4; ++k) sumQ[in.q[f][k]] += facePoint[f];
  for (int e = 0; e < ne; ++e) {
    const Vec3 mid = (in.v[edgeEnds[e][0]] + in.v[edgeEnds[e][1]]) / 2;
    for (int end : edgeEnds[e]) {
      sumR[end] += mid;
      ++valence[end];
    }
  }
  out.v.resize(nv + ne + nq);
  for (int i = 0; i < nv; ++i) {
    const double n = valence[i];
    out.v[i] = (sumQ[i] / n + 2 * sumR[i] / n + (n - 3) * in.v[i]) / n;
  }
  for (int e = 0; e < ne; ++e)
    out.v[nv + e] = 0.25 * (in.v[edgeEnds[e][0]] + in.v[edgeEnds[e][1]] +
                            facePoint[edgeFaces[e][0]] + facePoint[edgeFaces[e][1]]);
  for (int f = 0; f < nq; ++f) out.v[nv + ne + f] = facePoint[f];
  // Each quad becomes four with the same winding: corner, next edge point, face point,
  // previous edge point.
  out.q.reserve(size_t(4) * nq);
  for (int f = 0; f < nq; ++f)
    for (int k = 0; k < 4; ++k)
      out.q.push_back(
          {in.q[f][k], nv + quadEdges[f][k], nv + ne + f, nv + quadEdges[f][(k + 3) % 4]});
  return out;
}

// The boundary of a polycube, outward quads. Cells along axis a lie between coordinates
// grid[a][i] and grid[a][i + 1]; filled(i, j, k) says which are solid.
QuadMesh polycube(const std::array<std::vector<double>, 3>& grid,
                  const std::function<bool(int, int, int)>& filled) {
  const int n[3] = {int(grid[0].size()) - 1, int(grid[1].size()) - 1, int(grid[2].size()) - 1};
  QuadMesh m;
  std::map<std::array<int, 3>, int> index;
  auto vertex = [&](std::array<int, 3> g) {
    auto [it, fresh] = index.try_emplace(g, int(m.v.size()));
    if (fresh) m.v.emplace_back(grid[0][g[0]], grid[1][g[1]], grid[2][g[2]]);
    return it->second;
  };
  auto solid = [&](int i, int j, int k) {
    return i >= 0 && j >= 0 && k >= 0 && i < n[0] && j < n[1] && k < n[2] && filled(i, j, k);
  };
  for (int i = 0; i < n[0]; ++i)
    for (int j = 0; j < n[1]; ++j)
      for (int k = 0; k < n[2]; ++k) {
        if (!solid(i, j, k)) continue;
        const std::array<int, 3> cell = {i, j, k};
        for (int a = 0; a < 3; ++a)
          for (int side = 0; side < 2; ++side) {
            std::array<int, 3> across = cell;
            across[a] += side ? 1 : -1;
            if (solid(across[0], across[1], across[2])) continue;
            // Corners (0,0) (1,0) (1,1) (0,1) in the next two axes b, c: e_b x e_c = e_a,
            // so this order faces +a; reversed it faces -a.
            const int b = (a + 1) % 3, c = (a + 2) % 3;
            Quad quad;
            const int offsets[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
            for (int corner = 0; corner < 4; ++corner) {
              std::array<int, 3> g = cell;
              g[a] += side;
              g[b] += offsets[corner][0];
              g[c] += offsets[corner][1];
              quad[corner] = vertex(g);
            }
            if (!side) std::swap(quad[1], quad[3]);
            m.q.push_back(quad);
          }
      }
  return m;
}

// Grid lines at `stops`, each interval split into pieces about `cell` long, so the cage
// (and hence the subdivided surface) has near-square quads.
std::vector<double> gridLines(const std::vector<double>& stops, double cell) {
  std::vector<double> lines = {stops[0]};
  for (size_t i = 1; i < stops.size(); ++i) {
    const double length = stops[i] - stops[i - 1];
    const int pieces = std::max(1, int(std::lround(length / cell)));
    for (int p = 1; p <= pieces; ++p) lines.push_back(stops[i - 1] + length * p / pieces);
  }
  return lines;
}

// The genus-2 cage: a slab 2r thick with two square holes of half-width R - r centred at
// x = -R and x = R, bars 2r wide around and between them. Cells are about as wide as the
// narrower of bar and hole, so thin holes and thick bars alike get square cells.
std::array<std::vector<double>, 3> genus2Grid(double R, double r) {
  const double cell = 2 * std::min(r, R - r);
  return {gridLines({-2 * R - r, -2 * R + r, -r, r, 2 * R - r, 2 * R + r}, cell),
          gridLines({-R - r, -R + r, R - r, R + r}, cell), gridLines({-r, r}, cell)};
}

// An upper bound on the cage's quads without building it: top, bottom and the side walls
// of a full box, and as much again for the hole walls.
double genus2CageQuads(double R, double r) {
  const double cell = 2 * std::min(r, R - r);
  const double nx = std::ceil((4 * R + 2 * r) / cell) + 5,
               ny = std::ceil((2 * R + 2 * r) / cell) + 3, nz = std::ceil(2 * r / cell) + 1;
  return 2 * nx * ny + 4 * nz * (nx + ny);
}

SurfaceMesh finish(SurfaceMesh m) {
  m.buildTopology();
  return m;
}

// ---- the table makeProceduralSurface() reads ----

struct Parameter {
  const char* name;
  double fallback;
  bool integer;
};

struct Spec {
  std::vector<Parameter> parameters;
  // A message for arguments this surface cannot be built from, or "".
  std::function<std::string(const std::vector<double>&)> check;
  std::function<SurfaceMesh(const std::vector<double>&)> build;
};

std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

std::string tooMany(double faces) {
  return "it would have " + num(faces) + " faces, more than the " +
         std::to_string(kMaxProceduralFaces) + " allowed";
}

int torusRings(double R, double r, int segments) {
  return std::max(3, int(std::lround(segments * R / r)));
}
int cylinderRows(double r, double h, int segments) {
  return std::max(1, int(std::lround(h / (2 * kPi * r / segments))));
}
std::array<int, 2> planeCells(double w, double h, int segments) {
  const double cell = std::max(w, h) / segments;
  return {std::max(1, int(std::lround(w / cell))), std::max(1, int(std::lround(h / cell)))};
}

const std::map<std::string, Spec>& specs() {
  static const std::map<std::string, Spec> table = {
      {"torus",
       {{{"R", 1.0, false}, {"r", 0.4, false}, {"segments", kDefaultTorusSegments, true}},
        [](const std::vector<double>& a) -> std::string {
          if (!(a[0] > a[1] && a[1] > 0)) return "torus(R, r) needs R > r > 0";
          if (a[2] < 3 || a[2] > kMaxSegments)
            return "torus segments must be between 3 and " + std::to_string(kMaxSegments);
          const double faces = 2.0 * a[2] * torusRings(a[0], a[1], int(a[2]));
          return faces > kMaxProceduralFaces ? "torus: " + tooMany(faces) : "";
        },
        [](const std::vector<double>& a) { return torus(a[0], a[1], int(a[2])); }}},
      {"sphere",
       {{{"r", 1.0, false}, {"subdivisions", kDefaultSphereSubdivisions, true}},
        [](const std::vector<double>& a) -> std::string {
          if (!(a[0] > 0)) return "sphere(r) needs r > 0";
          if (a[1] < 0 || a[1] > kMaxSphereSubdivisions)
            return "sphere subdivisions must be between 0 and " +
                   std::to_string(kMaxSphereSubdivisions);
          return "";
        },
        [](const std::vector<double>& a) { return sphere(a[0], int(a[1])); }}},
      {"plane",
       {{{"w", 2.0, false}, {"h", 2.0, false}, {"segments", kDefaultPlaneSegments, true}},
        [](const std::vector<double>& a) -> std::string {
          if (!(a[0] > 0 && a[1] > 0)) return "plane(w, h) needs w > 0 and h > 0";
          if (a[2] < 1 || a[2] > kMaxSegments)
            return "plane segments must be between 1 and " + std::to_string(kMaxSegments);
          const auto cells = planeCells(a[0], a[1], int(a[2]));
          const double faces = 2.0 * cells[0] * cells[1];
          return faces > kMaxProceduralFaces ? "plane: " + tooMany(faces) : "";
        },
        [](const std::vector<double>& a) { return plane(a[0], a[1], int(a[2])); }}},
      {"genus2",
       {{{"R", 1.0, false}, {"r", 0.4, false}, {"levels", kDefaultGenus2Levels, true}},
        [](const std::vector<double>& a) -> std::string {
          if (!(a[0] > a[1] && a[1] > 0)) return "genus2(R, r) needs R > r > 0";
          if (a[2] < 0 || a[2] > kMaxGenus2Levels)
            return "genus2 levels must be between 0 and " + std::to_string(kMaxGenus2Levels);
          // Each Catmull-Clark step quarters the cage's quads; two triangles per quad.
          const double faces = 2 * genus2CageQuads(a[0], a[1]) * std::pow(4.0, a[2]);
          return faces > kMaxProceduralFaces ? "genus2: " + tooMany(faces) : "";
        },
        [](const std::vector<double>& a) { return genus2(a[0], a[1], int(a[2])); }}},
      {"cylinder",
       {{{"r", 1.0, false}, {"h", 2.0, false}, {"segments", kDefaultCylinderSegments, true}},
        [](const std::vector<double>& a) -> std::string {
          if (!(a[0] > 0 && a[1] > 0)) return "cylinder(r, h) needs r > 0 and h > 0";
          if (a[2] < 3 || a[2] > kMaxSegments)
            return "cylinder segments must be between 3 and " + std::to_string(kMaxSegments);
          const double faces = 2.0 * a[2] * cylinderRows(a[0], a[1], int(a[2]));
          return faces > kMaxProceduralFaces ? "cylinder: " + tooMany(faces) : "";
        },
        [](const std::vector<double>& a) { return cylinder(a[0], a[1], int(a[2])); }}},
      {"tori3",
       {{{"R", 1.0, false}, {"r", 0.3, false}, {"segments", kDefaultTorusSegments, true}},
        [](const std::vector<double>& a) -> std::string {
          if (!(a[0] > 2 * a[1] && a[1] > 0)) return "tori3(R, r) needs R > 2r > 0 (the tubes' junctions apart)";
          if (a[2] < 8 || a[2] > kMaxTori3Segments)
            return "tori3 segments must be between 8 and " + std::to_string(kMaxTori3Segments);
          const double faces = 3 * 2.0 * a[2] * torusRings(a[0], a[1], int(a[2]));
          return faces > kMaxProceduralFaces ? "tori3: " + tooMany(faces) : "";
        },
        [](const std::vector<double>& a) { return threeTori(a[0], a[1], int(a[2])); }}},
  };
  return table;
}

}  // namespace

SurfaceMesh torus(double R, double r, int segments) {
  SurfaceMesh m;
  const int rings = torusRings(R, r, segments);  // around the axis
  m.vertices.reserve(size_t(rings) * segments);
  // Row j (around the tube) holds the ring of vertices at tube angle v_j.
  for (int j = 0; j < segments; ++j) {
    const double v = 2 * kPi * j / segments;
    for (int i = 0; i < rings; ++i) {
      const double u = 2 * kPi * i / rings;
      const double d = R + r * std::cos(v);
      m.vertices.emplace_back(d * std::cos(u), d * std::sin(u), r * std::sin(v));
    }
  }
  // d/du x d/dv points away from the tube's centre line: (u, v) is an outward frame. The
  // last row joins the first, so the grid wraps in both directions.
  gridFaces(m, rings, segments, true, true);
  return finish(std::move(m));
}

SurfaceMesh sphere(double r, int subdivisions) {
  SurfaceMesh m;
  const double t = (1 + std::sqrt(5.0)) / 2;
  m.vertices = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  m.faces = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
             {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (Vec3& p : m.vertices) p.normalize();
  for (int level = 0; level < subdivisions; ++level) {
    std::unordered_map<uint64_t, int> midpoint;
    auto mid = [&](int a, int b) {
      const uint64_t key = (uint64_t(uint32_t(std::min(a, b))) << 32) | uint32_t(std::max(a, b));
      auto [it, fresh] = midpoint.try_emplace(key, int(m.vertices.size()));
      if (fresh) m.vertices.push_back((m.vertices[a] + m.vertices[b]).normalized());
      return it->second;
    };
    std::vector<std::array<int, 3>> faces;
    faces.reserve(4 * m.faces.size());
    for (const auto& f : m.faces) {
      const int ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
      faces.push_back({f[0], ab, ca});
      faces.push_back({f[1], bc, ab});
      faces.push_back({f[2], ca, bc});
      faces.push_back({ab, bc, ca});
    }
    m.faces = std::move(faces);
  }
  for (Vec3& p : m.vertices) p *= r;
  return finish(std::move(m));
}

SurfaceMesh plane(double w, double h, int segments) {
  SurfaceMesh m;
  const auto [nx, ny] = planeCells(w, h, segments);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      m.vertices.emplace_back(-w / 2 + w * i / nx, -h / 2 + h * j / ny, 0.0);
  gridFaces(m, nx, ny, false);  // (x, y) is counter-clockwise seen from +Z
  return finish(std::move(m));
}

SurfaceMesh cylinder(double r, double h, int segments) {
  SurfaceMesh m;
  const int rows = cylinderRows(r, h, segments);
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i < segments; ++i) {
      const double u = 2 * kPi * i / segments;
      m.vertices.emplace_back(r * std::cos(u), r * std::sin(u), -h / 2 + h * j / rows);
    }
  gridFaces(m, segments, rows, true);  // d/du x d/dz points away from the axis
  return finish(std::move(m));
}

SurfaceMesh genus2(double R, double r, int levels) {
  const auto grid = genus2Grid(R, r);
  const double holeX0 = -2 * R + r, holeX1 = -r, holeY0 = -R + r, holeY1 = R - r;
  auto filled = [&](int i, int j, int) {
    const double x = (grid[0][i] + grid[0][i + 1]) / 2, y = (grid[1][j] + grid[1][j + 1]) / 2;
    const bool inHoleY = y > holeY0 && y < holeY1;
    const bool inLeft = holeX0 < x && x < holeX1;
    const bool inRight = -holeX1 < x && x < -holeX0;
    return !(inHoleY && (inLeft || inRight));
  };
  QuadMesh q = polycube(grid, filled);
  for (int level = 0; level < levels; ++level) q = catmullClark(q);
  SurfaceMesh m;
  m.vertices = std::move(q.v);
  m.faces.reserve(2 * q.q.size());
  for (const Quad& quad : q.q) {
    // Split along the shorter diagonal: the better-shaped pair of triangles.
    const Vec3 &a = m.vertices[quad[0]], &b = m.vertices[quad[1]], &c = m.vertices[quad[2]],
               &d = m.vertices[quad[3]];
    if ((c - a).squaredNorm() <= (d - b).squaredNorm()) {
      m.faces.push_back({quad[0], quad[1], quad[2]});
      m.faces.push_back({quad[0], quad[2], quad[3]});
    } else {
      m.faces.push_back({quad[0], quad[1], quad[3]});
      m.faces.push_back({quad[1], quad[2], quad[3]});
    }
  }
  return finish(std::move(m));
}

bool makeProceduralSurface(const std::string& name, const std::vector<double>& args,
                           SurfaceMesh& out, std::string& error) {
  out = SurfaceMesh{};
  const auto& table = specs();
  auto it = table.find(name);
  if (it == table.end()) {
    std::string known;
    for (const auto& n : proceduralSurfaceNames())
      known += (known.empty() ? "" : ", ") + proceduralSurfaceSignature(n);
    error = "unknown procedural surface '" + name + "' (known: " + known + ")";
    return false;
  }
  const Spec& spec = it->second;
  if (args.size() > spec.parameters.size()) {
    error = name + " takes at most " + std::to_string(spec.parameters.size()) + " arguments, got " +
            std::to_string(args.size()) + ": " + proceduralSurfaceSignature(name);
    return false;
  }
  std::vector<double> values;
  for (size_t i = 0; i < spec.parameters.size(); ++i) {
    const Parameter& p = spec.parameters[i];
    const double x = i < args.size() ? args[i] : p.fallback;
    if (!std::isfinite(x) || (p.integer && x != std::floor(x))) {
      error = name + ": " + p.name + " must be a finite " + (p.integer ? "whole " : "") +
              "number, got " + num(x) + " (" + proceduralSurfaceSignature(name) + ")";
      return false;
    }
    values.push_back(x);
  }
  error = spec.check(values);
  if (!error.empty()) {
    error += " (got " + name + "(";
    for (size_t i = 0; i < values.size(); ++i) error += (i ? ", " : "") + num(values[i]);
    error += "))";
    return false;
  }
  out = spec.build(values);
  return true;
}

const std::vector<std::string>& proceduralSurfaceNames() {
  static const std::vector<std::string> names = {"torus", "sphere", "plane", "genus2", "cylinder", "tori3"};
  return names;
}

std::string proceduralSurfaceSignature(const std::string& name) {
  auto it = specs().find(name);
  if (it == specs().end()) return "";
  std::string s = name + "(";
  for (size_t i = 0; i < it->second.parameters.size(); ++i) {
    const Parameter& p = it->second.parameters[i];
    s += (i ? ", " : "") + std::string(p.name) + " = " + num(p.fallback);
  }
  return s + ")";
}

}  // namespace fgsg::rt::surface
