#include "runtime/assets.h"

#include "runtime/io/file_extension.h"
#include "runtime/io/openmesh_quiet.h"
#include "runtime/io/read_mesh_file.h"
#include "runtime/texture/color_texture.h"

// OpenMesh requires its IO header before the mesh kernel so the readers get registered.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/importer/ImporterT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <numbers>
#include <optional>
#include <utility>

namespace fgsg::rt {

namespace {

namespace fs = std::filesystem;
using V3 = Eigen::Vector3d;
using V2 = Eigen::Vector2d;

// An axis whose extent is below this fraction of the largest extent is flat: it is
// snapped to 0 instead of being stretched to fill the unit box.
constexpr double kFlatRelTolerance = 1e-6;
// Loaded meshes without usable normals are shaded smooth across edges whose dihedral
// angle is below this, and sharp (split vertices) above it.
constexpr double kCreaseAngleDegrees = 30.0;

// A primitive under construction, in natural coordinates and double precision. Texture
// coordinates (`uv`, u v with v up) are either given for every vertex or for none.
struct Builder {
  std::vector<V3> p, n;
  std::vector<V2> uv;
  std::vector<uint32_t> idx;

  uint32_t vertex(const V3& pos, const V3& nrm) {
    p.push_back(pos);
    n.push_back(nrm.normalized());
    return uint32_t(p.size() - 1);
  }
  uint32_t vertex(const V3& pos, const V3& nrm, const V2& texCoord) {
    uv.push_back(texCoord);
    return vertex(pos, nrm);
  }
  void tri(uint32_t a, uint32_t b, uint32_t c) { idx.insert(idx.end(), {a, b, c}); }
};

// Unit circle samples shared by every ring, so rings built from the same table have
// bit-identical positions (caps and sides of the cylinder meet exactly).
std::vector<std::pair<double, double>> circle(int segments) {
  std::vector<std::pair<double, double>> cs(segments);
  for (int j = 0; j < segments; ++j) {
    const double a = 2.0 * std::numbers::pi * j / segments;
    cs[j] = {std::cos(a), std::sin(a)};
  }
  return cs;
}

void buildCube(Builder& b) {
  // For each face: outward normal n and in-plane axes u, v with u x v = n, so the corners
  // (-u-v, +u-v, +u+v, -u+v) are counter-clockwise seen from outside.
  for (int axis = 0; axis < 3; ++axis) {
    for (double s : {1.0, -1.0}) {
      V3 n = V3::Zero();
      n[axis] = s;
      V3 u = V3::Zero(), v = V3::Zero();
      u[(axis + 1) % 3] = 1.0;
      v[(axis + 2) % 3] = 1.0;
      if (s < 0) std::swap(u, v);
      const uint32_t first = uint32_t(b.p.size());
      for (auto [su, sv] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
        b.vertex(n + su * u + sv * v, n);
      b.tri(first, first + 1, first + 2);
      b.tri(first, first + 2, first + 3);
    }
  }
}

void buildCylinder(Builder& b, int segments) {
  const auto cs = circle(segments);
  const auto ring = [&](double y, bool side) {
    const uint32_t first = uint32_t(b.p.size());
    for (auto [c, s] : cs) b.vertex({c, y, s}, side ? V3(c, 0, s) : V3(0, y, 0));
    return first;
  };
  const uint32_t bottom = ring(-1, true), top = ring(1, true);
  for (int j = 0; j < segments; ++j) {
    const uint32_t k = (j + 1) % segments;
    b.tri(bottom + j, top + j, bottom + k);
    b.tri(bottom + k, top + j, top + k);
  }
  const uint32_t topCap = ring(1, false), topCentre = b.vertex({0, 1, 0}, {0, 1, 0});
  const uint32_t botCap = ring(-1, false), botCentre = b.vertex({0, -1, 0}, {0, -1, 0});
  for (int j = 0; j < segments; ++j) {
    const uint32_t k = (j + 1) % segments;
    b.tri(topCentre, topCap + k, topCap + j);
    b.tri(botCentre, botCap + j, botCap + k);
  }
}

// An open tube along Y (no caps), `sides` around, smooth: a turtle's segment drawn
// cheaply (`turtle segments "tubes";`).
void buildTube(Builder& b, int sides) {
  const auto cs = circle(sides);
  for (double y : {-1.0, 1.0})
    for (auto [c, s] : cs) b.vertex({c, y, s}, {c, 0, s});
  const uint32_t n = uint32_t(sides);
  for (uint32_t j = 0; j < n; ++j) {
    const uint32_t k = (j + 1) % n;
    b.tri(j, n + j, k);
    b.tri(k, n + j, n + k);
  }
}

// "tube3" ... "tube64": the number of sides of a tube, or 0 for another name.
int tubeSides(const std::string& name) {
  if (name.size() < 5 || name.size() > 6 || name.compare(0, 4, "tube") != 0) return 0;
  int sides = 0;
  for (size_t i = 4; i < name.size(); ++i) {
    if (name[i] < '0' || name[i] > '9' || (i == 4 && name[i] == '0')) return 0;
    sides = 10 * sides + (name[i] - '0');
  }
  return sides >= 3 && sides <= 64 ? sides : 0;
}

void buildSphere(Builder& b, int segments, int rings) {
  const auto cs = circle(segments);
  const uint32_t north = b.vertex({0, 1, 0}, {0, 1, 0});
  for (int i = 1; i < rings; ++i) {
    const double theta = std::numbers::pi * i / rings;
    const double y = std::cos(theta), r = std::sin(theta);
    for (auto [c, s] : cs) b.vertex({r * c, y, r * s}, {r * c, y, r * s});
  }
  const uint32_t south = b.vertex({0, -1, 0}, {0, -1, 0});
  const auto at = [&](int i, int j) { return uint32_t(1 + (i - 1) * segments + j % segments); };
  for (int j = 0; j < segments; ++j) {
    b.tri(at(1, j), north, at(1, j + 1));
    for (int i = 1; i + 1 < rings; ++i) {  // ring i is above ring i + 1
      b.tri(at(i + 1, j), at(i, j), at(i + 1, j + 1));
      b.tri(at(i + 1, j + 1), at(i, j), at(i, j + 1));
    }
    b.tri(south, at(rings - 1, j), at(rings - 1, j + 1));
  }
}

void buildTorus(Builder& b, int majorSegments, int minorSegments) {
  const double R = 3.0, r = 1.0;  // tube radius = 1/8 of the width before normalising
  const auto cu = circle(majorSegments), cv = circle(minorSegments);
  for (auto [cosU, sinU] : cu)
    for (auto [cosV, sinV] : cv)
      b.vertex({(R + r * cosV) * cosU, (R + r * cosV) * sinU, r * sinV},
               {cosV * cosU, cosV * sinU, sinV});
  const auto at = [&](int i, int j) {
    return uint32_t((i % majorSegments) * minorSegments + j % minorSegments);
  };
  for (int i = 0; i < majorSegments; ++i)
    for (int j = 0; j < minorSegments; ++j) {
      b.tri(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      b.tri(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
}

void buildIcosphere(Builder& b) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  const V3 corners[12] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                          {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                          {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  const uint32_t faces[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (const V3& c : corners) b.vertex(c.normalized(), c);
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
  const auto mid = [&](uint32_t a, uint32_t c) {
    const auto key = std::minmax(a, c);
    auto it = midpoints.find(key);
    if (it != midpoints.end()) return it->second;
    const V3 m = (b.p[a] + b.p[c]).normalized();
    return midpoints[key] = b.vertex(m, m);
  };
  for (const auto& f : faces) {
    const uint32_t ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
    b.tri(f[0], ab, ca);
    b.tri(f[1], bc, ab);
    b.tri(f[2], ca, bc);
    b.tri(ab, bc, ca);
  }
}

void buildQuad(Builder& b) {
  const V3 n(0, 0, 1);
  b.vertex({0, 0, 0}, n);
  b.vertex({1, 0, 0}, n);
  b.vertex({1, 1, 0}, n);
  b.vertex({0, 1, 0}, n);
  b.tri(0, 1, 2);
  b.tri(0, 2, 3);
}

// Bark for marching terminals (Buron et al. 2015: "a bark cylinder (216 polygons)"): an
// open tube along X, `sides` around and `rings` along, smooth. u runs around (the angle
// about +X from +Y towards +Z, over [0,1] with a seam column of its own), v along X from
// 0 to 1, so a bark image's grain follows the branch; quads are not mirrored in UV space.
void buildBark(Builder& b, int sides, int rings) {
  const auto cs = circle(sides);
  for (int i = 0; i <= rings; ++i) {
    const double x = double(i) / rings;
    for (int j = 0; j <= sides; ++j) {
      const auto [c, s] = cs[j % sides];
      b.vertex({x, c, s}, {0, c, s}, {double(j) / sides, x});
    }
  }
  const auto at = [&](int i, int j) { return uint32_t(i * (sides + 1) + j); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      // Around (j) then along (i) is counter-clockwise seen from outside.
      b.tri(at(i, j), at(i, j + 1), at(i + 1, j + 1));
      b.tri(at(i, j), at(i + 1, j + 1), at(i + 1, j));
    }
}

// A leaf card for marching terminals: the unit square in the XY plane facing +Z, its
// texture upright seen from +Z (u = x, v = y). One-sided geometry: the glTF material is
// double-sided, and a second face would fight the first in depth.
void buildLeaf(Builder& b) {
  const V3 n(0, 0, 1);
  for (auto [x, y] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}})
    b.vertex({x, y, 0}, n, {x, y});
  b.tri(0, 1, 2);
  b.tri(0, 2, 3);
}

void buildDisc(Builder& b, int segments) {
  const V3 n(0, 0, 1);
  const uint32_t centre = b.vertex({0, 0, 0}, n);
  for (auto [c, s] : circle(segments)) b.vertex({c, s, 0}, n);
  for (int j = 0; j < segments; ++j) b.tri(centre, 1 + j, 1 + (j + 1) % segments);
}

// Stretches the bounding box onto [0,1]^3 (flat axes snap to 0) and transforms the
// normals by the inverse transpose of that scaling.
Mesh normaliseToUnitBox(const Builder& b) {
  V3 lo = V3::Constant(INFINITY), hi = V3::Constant(-INFINITY);
  for (const V3& q : b.p) {
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  const V3 extent = b.p.empty() ? V3::Zero() : V3(hi - lo);
  const double maxExtent = extent.maxCoeff();
  bool flat[3];
  V3 normalScale;  // the inverse transpose of the position scaling diag(1 / extent)
  for (int a = 0; a < 3; ++a) {
    flat[a] = extent[a] <= kFlatRelTolerance * maxExtent;
    normalScale[a] = flat[a] ? 1.0 : extent[a];
  }
  Mesh m;
  m.positions.reserve(3 * b.p.size());
  m.normals.reserve(3 * b.p.size());
  // Texture coordinates stay as they are: they address the texture, not the box.
  if (!b.uv.empty() && b.uv.size() == b.p.size())
    for (const V2& t : b.uv) m.texcoords.insert(m.texcoords.end(), {float(t[0]), float(t[1])});
  for (size_t i = 0; i < b.p.size(); ++i) {
    V3 nn = b.n[i].cwiseProduct(normalScale);
    if (nn.norm() > 0) nn.normalize();
    for (int a = 0; a < 3; ++a) {
      // Dividing (not multiplying by 1 / extent) makes the maximum exactly 1.
      m.positions.push_back(flat[a] ? 0.0f : float((b.p[i][a] - lo[a]) / extent[a]));
      m.normals.push_back(float(nn[a]));
    }
  }
  m.indices.assign(b.idx.begin(), b.idx.end());
  return m;
}

using OMesh = OpenMesh::TriMesh_ArrayKernelT<>;

// Gives every face corner the area-weighted mean normal of the faces around its vertex
// that lie within the crease angle of the corner's own face, then merges corners of a
// vertex whose normals agree. Sharp edges stay sharp; curved surfaces stay smooth.
// `cornerUV` (parallel to `tris`, or empty) keeps texture seams: corners of a vertex merge
// only when their texture coordinates are equal too.
void creaseNormals(const std::vector<V3>& pos, const std::vector<uint32_t>& tris,
                   const std::vector<V2>& cornerUV, Builder& out) {
  const size_t faceCount = tris.size() / 3;
  std::vector<V3> area(faceCount), unit(faceCount);
  std::vector<std::vector<uint32_t>> facesOf(pos.size());
  for (size_t f = 0; f < faceCount; ++f) {
    const V3 &a = pos[tris[3 * f]], &b = pos[tris[3 * f + 1]], &c = pos[tris[3 * f + 2]];
    area[f] = (b - a).cross(c - a);
    unit[f] = area[f].norm() > 0 ? area[f].normalized() : V3::Zero();
    for (int k = 0; k < 3; ++k) facesOf[tris[3 * f + k]].push_back(uint32_t(f));
  }
  const double cosCrease = std::cos(kCreaseAngleDegrees * std::numbers::pi / 180.0);
  std::vector<std::vector<uint32_t>> copies(pos.size());  // output vertices per input vertex
  for (size_t f = 0; f < faceCount; ++f) {
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = tris[3 * f + k];
      V3 sum = V3::Zero(), all = V3::Zero();
      for (uint32_t g : facesOf[v]) {
        all += area[g];
        if (unit[g].dot(unit[f]) >= cosCrease) sum += area[g];
      }
      if (sum.norm() == 0) sum = all;
      const V3 n = sum.norm() > 0 ? V3(sum.normalized()) : V3(0, 0, 1);
      const bool withUV = !cornerUV.empty();
      uint32_t index = UINT32_MAX;
      for (uint32_t c : copies[v])
        if (out.n[c].dot(n) > 1.0 - 1e-9 && (!withUV || out.uv[c] == cornerUV[3 * f + k])) index = c;
      if (index == UINT32_MAX) {
        index = withUV ? out.vertex(pos[v], n, cornerUV[3 * f + k]) : out.vertex(pos[v], n);
        copies[v].push_back(index);
      }
      out.idx.push_back(index);
    }
  }
}

// Where a triangle of a loaded asset came from: the file's polygon (the TriMesh fans
// polygons into triangles), and the first vertex ImporterT would add when it splits the
// polygon off as non-manifold (it copies the corners, in order, from there).
struct TriangleSource {
  size_t polygon = 0, firstCopy = 0;
};

// The file's texture coordinate at the corner of the triangle's polygon that vertex `v`
// of the imported mesh stands for.
V2 cornerUVOf(const io::MeshFileContent& file, const TriangleSource& src, int v) {
  const size_t first = file.polygonStart[src.polygon], end = file.polygonStart[src.polygon + 1];
  size_t corner = first;
  if (size_t(v) >= src.firstCopy)
    corner += size_t(v) - src.firstCopy;
  else  // ImporterT refuses polygons that repeat a vertex, so the corner is unique
    while (corner + 1 < end && file.corners[corner] != v) ++corner;
  corner = std::min(corner, end - 1);
  return {file.cornerUV[corner][0], file.cornerUV[corner][1]};
}

// An OBJ asset's own material images (its .mtl's map_Kd, found beside the OBJ): the
// mesh's texture runs, triangle by triangle from the polygons they were cut from.
bool attachMaterialImages(const std::string& path, const io::MeshFileContent& file,
                          const std::vector<TriangleSource>& sourceOf, Mesh& out, std::string& error) {
  const fs::path folder = fs::path(path).parent_path();
  for (const std::string& name : file.textureFiles) {
    const fs::path image = fs::path(name).is_absolute() ? fs::path(name) : folder / name;
    std::string why;
    if (!texture::ColorTexture::probe(image.string(), why)) {
      error = "asset file '" + path + "': its material's image cannot be used: " + why;
      return false;
    }
    out.textures.push_back(image.string());
  }
  for (size_t t = 0; t < sourceOf.size(); ++t) {
    const int32_t image = file.polygonTexture[sourceOf[t].polygon];
    out.addTextureRun(t, image);
  }
  return true;
}

// `sourceBox` receives the file's bounding box (lo, then hi), which the unit box forgets.
bool loadMeshFile(const std::string& path, Mesh& out, std::string& error, std::array<double, 6>& sourceBox) {
  const std::string ext = io::lowerExtension(path);
  if (ext != ".obj" && ext != ".ply" && ext != ".off" && ext != ".stl") {
    error = "asset file '" + path + "' has an unsupported format '" + ext +
            "' (supported: .obj .ply .off .stl)";
    return false;
  }
  io::MeshFileContent file;
  if (!io::readMeshFile(path, file, error)) {
    error = "cannot read asset file: " + error;
    return false;
  }
  // Built as OpenMesh's readers would: ImporterT splits non-manifold faces off and drops
  // faces with a repeated corner; the TriMesh fan-triangulates polygons.
  OMesh om;
  OpenMesh::IO::ImporterT<OMesh> importer(om);
  std::optional<io::QuietOpenMesh> quiet(std::in_place);  // it reports each such face on omerr
  std::vector<OpenMesh::VertexHandle> handles;
  handles.reserve(file.vertices.size());
  for (const auto& p : file.vertices)
    handles.push_back(importer.add_vertex(OpenMesh::Vec3d(p[0], p[1], p[2])));
  std::vector<OpenMesh::VertexHandle> corners;
  std::vector<TriangleSource> sourceOf;  // per triangle, for its texture coordinates
  for (size_t f = 0; f < file.polygonCount(); ++f) {
    corners.clear();
    for (size_t c = file.polygonStart[f]; c < file.polygonStart[f + 1]; ++c)
      corners.push_back(handles[size_t(file.corners[c])]);
    const size_t verticesBefore = om.n_vertices();
    importer.add_face(corners);
    sourceOf.resize(om.n_faces(), TriangleSource{f, verticesBefore});
  }
  quiet.reset();
  if (om.n_faces() == 0) {
    error = "asset file '" + path + "' contains no faces";
    return false;
  }
  std::vector<V3> pos;
  pos.reserve(om.n_vertices());
  for (auto v : om.vertices()) {
    const auto& q = om.point(v);
    const V3 p(q[0], q[1], q[2]);
    if (!p.allFinite()) {
      error = "asset file '" + path + "' has a NaN or infinite vertex coordinate";
      return false;
    }
    pos.push_back(p);
  }
  V3 lo = pos[0], hi = pos[0];
  for (const V3& p : pos) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  if ((hi - lo).maxCoeff() <= 0.0) {
    error = "asset file '" + path + "' is degenerate: all its vertices coincide";
    return false;
  }
  sourceBox = {lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]};
  std::vector<uint32_t> tris;
  tris.reserve(3 * om.n_faces());
  std::vector<V2> cornerUV;
  for (auto f : om.faces())  // a TriMesh has triangulated every polygon on import
    for (auto v : f.vertices()) {
      tris.push_back(uint32_t(v.idx()));
      if (!file.cornerUV.empty()) cornerUV.push_back(cornerUVOf(file, sourceOf[size_t(f.idx())], v.idx()));
    }
  Builder b;
  creaseNormals(pos, tris, cornerUV, b);
  out = normaliseToUnitBox(b);
  return cornerUV.empty() || file.polygonTexture.empty() || attachMaterialImages(path, file, sourceOf, out, error);
}

std::string joinNames(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

}  // namespace

const std::vector<std::string>& builtinPrimitiveNames() {
  static const std::vector<std::string> names = {"cube", "cylinder", "sphere", "torus", "ico", "quad",
                                                 "disc", "bark",     "leaf",   "line",  "none"};
  return names;
}

bool makeBuiltinPrimitive(const std::string& name, Mesh& out) {
  static const std::map<std::string, std::function<void(Builder&)>> builders = {
      {"cube", buildCube},
      {"cylinder", [](Builder& b) { buildCylinder(b, 32); }},
      {"sphere", [](Builder& b) { buildSphere(b, 32, 16); }},
      {"torus", [](Builder& b) { buildTorus(b, 48, 16); }},
      {"ico", buildIcosphere},
      {"quad", buildQuad},
      {"disc", [](Builder& b) { buildDisc(b, 32); }},
      {"bark", [](Builder& b) { buildBark(b, 24, 9); }},  // 216 quads, as the paper's
      {"leaf", buildLeaf},
  };
  // CityEngine's built-in assets (a `.cga` file's i("builtin:cube")), under their names.
  if (name == "builtin:cube") return makeBuiltinPrimitive("cube", out);
  if (name == "builtin:unitQuad") return makeBuiltinPrimitive("quad", out);
  if (name == "none") {  // I("none"): CGA's way to place nothing
    out = Mesh{};
    return true;
  }
  if (name == "line") {  // one line segment on the box's Y edge (turtle segments "lines")
    out = Mesh{};
    const float positions[] = {0, 0, 0, 0, 1, 0}, normals[] = {0, 0, 1, 0, 0, 1};
    out.positions.assign(positions, positions + 6);
    out.normals.assign(normals, normals + 6);
    out.lines.resize(2);
    out.lines[0] = 0, out.lines[1] = 1;
    return true;
  }
  Builder b;
  if (const int sides = tubeSides(name)) {
    buildTube(b, sides);
    out = normaliseToUnitBox(b);
    return true;
  }
  auto it = builders.find(name);
  if (it == builders.end()) return false;
  it->second(b);
  out = normaliseToUnitBox(b);
  return true;
}

int AssetLibrary::resolve(const std::string& name, std::string& error) {
  if (auto it = byName_.find(name); it != byName_.end()) return it->second;
  Mesh mesh;
  std::array<double, 6> box{0, 0, 0, 1, 1, 1};  // a built-in's own box: the unit box
  if (!makeBuiltinPrimitive(name, mesh)) {
    std::vector<std::string> searched;
    std::string found;
    if (fs::path(name).is_absolute()) {
      searched.push_back(fs::path(name).parent_path().string());
      if (fs::is_regular_file(name)) found = name;
    } else {
      // Without search directories, names are relative to the working directory.
      std::vector<std::string> dirs = searchDirs_.empty() ? std::vector<std::string>{"."} : searchDirs_;
      for (const auto& dir : dirs) {
        searched.push_back(dir);
        const fs::path candidate = fs::path(dir) / name;
        std::error_code ec;
        if (fs::is_regular_file(candidate, ec)) {
          found = candidate.string();
          break;
        }
      }
    }
    if (found.empty()) {
      error = "asset '" + name + "' not found: not a built-in primitive (" +
              joinNames(builtinPrimitiveNames()) + ", tube3 ... tube64) and no such file in " + joinNames(searched);
      return -1;
    }
    if (!loadMeshFile(found, mesh, error, box)) return -1;
  }
  sourceBoxes_.resize(meshes_.size(), {0, 0, 0, 1, 1, 1});  // generated meshes before it
  sourceBoxes_.push_back(box);
  meshes_.push_back(std::move(mesh));
  return byName_[name] = int(meshes_.size() - 1);
}

int AssetLibrary::addGenerated(const std::string& name, const Mesh& world,
                               std::array<double, 16>& unitBoxToWorld) {
  Builder b;
  for (size_t v = 0; v < world.vertexCount(); ++v) {
    b.p.emplace_back(world.positions[3 * v], world.positions[3 * v + 1], world.positions[3 * v + 2]);
    b.n.emplace_back(world.normals[3 * v], world.normals[3 * v + 1], world.normals[3 * v + 2]);
    if (world.texcoords.size() == 2 * world.vertexCount())
      b.uv.emplace_back(world.texcoords[2 * v], world.texcoords[2 * v + 1]);
  }
  b.idx.assign(world.indices.begin(), world.indices.end());
  V3 lo = V3::Constant(INFINITY), hi = V3::Constant(-INFINITY);
  for (const V3& q : b.p) {
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  const V3 extent = b.p.empty() ? V3::Zero() : V3(hi - lo);
  unitBoxToWorld.fill(0.0);
  for (int a = 0; a < 3; ++a) {
    // A flat axis was snapped to 0 in the unit box: scale 0 puts it back at lo.
    unitBoxToWorld[5 * a] = extent[a] <= kFlatRelTolerance * extent.maxCoeff() ? 0.0 : extent[a];
    unitBoxToWorld[12 + a] = b.p.empty() ? 0.0 : lo[a];
  }
  unitBoxToWorld[15] = 1.0;
  meshes_.push_back(normaliseToUnitBox(b));
  return byName_[name] = int(meshes_.size() - 1);
}

void placeGenerated(AssetLibrary& library, InstanceList& out, const std::string& name,
                    const Mesh& world, uint32_t symbol, const std::array<float, 3>& color) {
  Instance inst;
  library.addGenerated(name, world, inst.transform);
  inst.asset = static_cast<uint32_t>(out.assets.size());
  out.assets.push_back(name);
  inst.symbol = symbol;
  inst.color = color;
  inst.firstParam = static_cast<uint32_t>(out.params.size());
  out.instances.push_back(inst);
}

}  // namespace fgsg::rt
