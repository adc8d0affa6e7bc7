#include "runtime/output/gltf_writer.h"

#include "runtime/io/glb_container.h"
#include "runtime/io/glb_writer.h"
#include "runtime/io/float_text.h"
#include "runtime/io/mesh_attributes.h"
#include "runtime/output/base_color_opacity_image.h"
#include "runtime/output/metallic_roughness_image.h"
#include "runtime/output/start_extras.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <unordered_map>

namespace fgsg::rt::output {

namespace {

static_assert(std::endian::native == std::endian::little, "glTF buffers are little endian");

using nlohmann::json;

using namespace io::gltf;  // glTF's numeric codes, padded4, the GLB container
constexpr const char* kInstancing = "EXT_mesh_gpu_instancing";
// CityEngine's specular map: KHR_materials_specular's specularColorTexture.
constexpr const char* kSpecular = "KHR_materials_specular";
constexpr int kUnsignedShort = 5123, kShort = 5122;
// GltfEncoding::quantize: 16-bit vertex data, and the texture coordinates' steps scaled back.
constexpr const char* kQuantization = "KHR_mesh_quantization";
constexpr const char* kTextureTransform = "KHR_texture_transform";
// Quantized texture coordinates: at most 2^14 steps per tile (finer than a float's at 16
// tiles), at least 2^12 (a quarter texel of a 1024-pixel tile; uvs spanning more than
// +-8 tiles stay floats).
constexpr int kMaxUvStepBits = 14, kMinUvStepBits = 12;
// CityEngine's texture layers: uv set 5 is the normal map's.
constexpr uint32_t kNormalMapUvSet = Finish::kNormalMap;
// A triangle's vertex normals closer to its face's normal than this (the cosine of their
// angle) are flat: glTF readers compute the same normals where a primitive has none.
constexpr double kFlatCosine = 1 - 1e-5;

// Whether every triangle of `m` is shaded flat by its vertex normals (turning as its
// corners wind); degenerate triangles, which draw nothing, do not count.
bool flatShaded(const Mesh& m) {
  if (!io::hasNormals(m)) return false;
  for (size_t t = 0; t < m.triangleCount(); ++t) {
    const uint32_t* c = &m.indices[3 * t];
    const float *a = &m.positions[3 * c[0]], *b = &m.positions[3 * c[1]], *d = &m.positions[3 * c[2]];
    const double u[3] = {double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]};
    const double v[3] = {double(d[0]) - a[0], double(d[1]) - a[1], double(d[2]) - a[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0) || !std::isfinite(len)) continue;
    for (int k = 0; k < 3; ++k) {
      const float* vn = &m.normals[3 * c[k]];
      const double vlen = std::sqrt(double(vn[0]) * vn[0] + double(vn[1]) * vn[1] + double(vn[2]) * vn[2]);
      if (!(vlen > 0) || (n[0] * vn[0] + n[1] * vn[1] + n[2] * vn[2]) / (len * vlen) < kFlatCosine) return false;
    }
  }
  return true;
}

// Whether none of the n values is NaN or infinite: quantizing casts them to integers.
bool gltfValuesFinite(const float* v, size_t n) {
  return std::all_of(v, v + n, [](float x) { return std::isfinite(x); });
}

// Per vertex the tangent a normal map needs (glTF's TANGENT: xyz along +u on the surface,
// w the bitangent's side), from the triangles' uv gradients (`texcoords` as written: v
// down), made perpendicular to the vertex normal; a vertex no triangle gives a gradient
// gets any unit vector across its normal.
std::vector<float> normalMapTangents(const float* positions, const float* normals, const float* texcoords,
                                     size_t vertices, const std::vector<uint32_t>& indices) {
  using V = Eigen::Vector3d;
  std::vector<V> t(vertices, V::Zero()), b(vertices, V::Zero());
  const auto at = [](const float* p, uint32_t k) { return V(p[3 * k], p[3 * k + 1], p[3 * k + 2]); };
  for (size_t f = 0; f + 2 < indices.size(); f += 3) {
    const uint32_t i0 = indices[f], i1 = indices[f + 1], i2 = indices[f + 2];
    const V e1 = at(positions, i1) - at(positions, i0), e2 = at(positions, i2) - at(positions, i0);
    const double du1 = texcoords[2 * i1] - texcoords[2 * i0], dv1 = texcoords[2 * i1 + 1] - texcoords[2 * i0 + 1];
    const double du2 = texcoords[2 * i2] - texcoords[2 * i0], dv2 = texcoords[2 * i2 + 1] - texcoords[2 * i0 + 1];
    const double r = du1 * dv2 - du2 * dv1;
    if (!(std::abs(r) > 1e-20)) continue;
    const V tf = (e1 * dv2 - e2 * dv1) / r, bf = (e2 * du1 - e1 * du2) / r;
    for (uint32_t k : {i0, i1, i2}) t[k] += tf, b[k] += bf;
  }
  std::vector<float> out(4 * vertices);
  for (size_t v = 0; v < vertices; ++v) {
    V n = at(normals, uint32_t(v));
    if (!(n.norm() > 0)) n = V::UnitZ();
    n.normalize();
    V x = t[v] - n * n.dot(t[v]);
    if (!(x.norm() > 1e-12)) x = n.unitOrthogonal();
    x.normalize();
    const float w = n.cross(x).dot(b[v]) < 0 ? -1.0f : 1.0f;
    for (int d = 0; d < 3; ++d) out[4 * v + d] = float(x[d]);
    out[4 * v + 3] = w;
  }
  return out;
}

// A baked part's vertex attributes as written, equal vertices (in every attribute
// written, bit for bit) made one: the pieces of a facade meet at shared corners.
struct WeldedVertices {
  std::vector<float> positions, normals, texcoords, colors;
  std::vector<std::vector<float>> uvSets;  // per Mesh::uvSets entry (CGA's sets 1..9), v down
  std::vector<uint32_t> of;  // per vertex of the mesh, its welded vertex
  size_t count = 0;
};

std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const size_t n = std::min<size_t>(3, bytes.size() - i);
    uint32_t v = 0;
    for (size_t k = 0; k < 3; ++k) v = (v << 8) | (k < n ? uint8_t(bytes[i + k]) : 0u);
    for (size_t k = 0; k < 4; ++k) out += k <= n ? digits[(v >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

enum class GltfPoolKind : uint8_t { Vertices, Indices, Instances };

// An instance scale folded into a shared mesh's vertices (instancedNode); 1: none.
using GltfScale = std::array<float, 3>;
constexpr GltfScale kGltfUnitScale{1, 1, 1};

// The double nearest the shortest decimal of `x` (29.3, not 29.299999237060547): what
// the JSON writes of a float.
double gltfShortest(float x) {
  char text[io::kMaxFloatText + 1];
  *io::putShortestFloat(text, x) = '\0';
  return std::strtod(text, nullptr);
}

// Quantized positions: p = origin + step * q per axis (q 16-bit unsigned), one step on
// every axis so that normals need no other transform; the node's translation and scale.
struct GltfPositionGrid {
  std::array<double, 3> origin{0, 0, 0};
  double step = 1;
};

class Writer {
 public:
  Writer(const Scene& scene, std::vector<PlacedNode>* placed, const GltfEncoding& encoding)
      : scene_(scene), placed_(placed), encoding_(encoding) {}

  bool write(bool binary, std::string& bytes, std::string& error);

 private:
  // A buffer view over `count` values of T appended to the BIN chunk (images).
  template <class T>
  int view(const T* data, size_t count, int target) {
    bin_.resize(padded4(bin_.size()), '\0');
    json v = {{"buffer", 0}, {"byteLength", count * sizeof(T)}, {"byteOffset", bin_.size()}};
    if (target) v["target"] = target;
    bin_.append(reinterpret_cast<const char*>(data), count * sizeof(T));
    views_.push_back(std::move(v));
    return int(views_.size() - 1);
  }
  // Room for `bytes` bytes (zeroed) in the pooled view of its kind, aligned to `align`:
  // the view and the offset in it. Vertex attributes share a view per element size
  // (its byteStride), indices one, instance transforms one: a view per accessor was a
  // city's 2000 views, 128 KB of JSON. The pools follow the instances in the BIN chunk
  // (flushPools), their views' offsets and lengths set there.
  std::pair<int, size_t> pooled(GltfPoolKind kind, size_t stride, size_t bytes, size_t align) {
    auto [it, added] = pools_.try_emplace({kind, stride});
    Pool& pool = it->second;
    if (added) {
      json v = {{"buffer", 0}, {"byteLength", 0}, {"byteOffset", 0}};
      if (kind == GltfPoolKind::Vertices) v["target"] = kArrayBuffer, v["byteStride"] = stride;
      if (kind == GltfPoolKind::Indices) v["target"] = kElementArrayBuffer;
      views_.push_back(std::move(v));
      pool.view = int(views_.size() - 1);
    }
    pool.bytes.resize((pool.bytes.size() + align - 1) / align * align, '\0');
    const size_t offset = pool.bytes.size();
    pool.bytes.resize(offset + bytes, '\0');
    return {pool.view, offset};
  }
  // A float vertex attribute of `width` components (2..4) per vertex; null `data`: zeros.
  int vertexAccessor(const float* data, size_t vertices, int width) {
    const size_t stride = sizeof(float) * size_t(width);
    const auto [v, offset] = pooled(GltfPoolKind::Vertices, stride, stride * vertices, 4);
    if (data) std::memcpy(pools_[{GltfPoolKind::Vertices, stride}].bytes.data() + offset, data, stride * vertices);
    static const char* const types[] = {"", "", "VEC2", "VEC3", "VEC4"};
    return accessor(v, vertices, kFloat, types[width], offset);
  }
  // A 16-bit vertex attribute (KHR_mesh_quantization) of `width` components per vertex,
  // each element padded to 4 bytes as glTF wants.
  template <class T>
  int shortVertexAccessor(const std::vector<T>& values, size_t vertices, int width, bool normalized) {
    static_assert(sizeof(T) == 2);
    const size_t element = sizeof(T) * size_t(width), stride = (element + 3) / 4 * 4;
    const auto [v, offset] = pooled(GltfPoolKind::Vertices, stride, stride * vertices, 4);
    char* out = pools_[{GltfPoolKind::Vertices, stride}].bytes.data() + offset;
    for (size_t k = 0; k < vertices; ++k) std::memcpy(out + stride * k, &values[size_t(width) * k], element);
    static const char* const types[] = {"", "", "VEC2", "VEC3", "VEC4"};
    const int a = accessor(v, vertices, std::is_signed_v<T> ? kShort : kUnsignedShort, types[width], offset);
    if (normalized) accessors_[a]["normalized"] = true;
    quantized_ = true;
    return a;
  }
  void flushPools() {
    for (auto& [key, pool] : pools_) {
      bin_.resize(padded4(bin_.size()), '\0');
      views_[size_t(pool.view)]["byteOffset"] = bin_.size();
      views_[size_t(pool.view)]["byteLength"] = pool.bytes.size();
      bin_ += pool.bytes;
    }
    pools_.clear();
  }
  int accessor(int view, size_t count, int componentType, const char* type, size_t byteOffset = 0) {
    json a = {{"bufferView", view}, {"componentType", componentType}, {"count", count}, {"type", type}};
    if (byteOffset) a["byteOffset"] = byteOffset;
    accessors_.push_back(std::move(a));
    return int(accessors_.size() - 1);
  }
  int positions(const float* p, size_t vertices);
  int quantizedPositions(const float* p, size_t vertices, const GltfPositionGrid& grid);
  GltfPositionGrid bakedGrid(const GroupNode& g) const;
  int unitVectors(const float* v, size_t vertices, int width);
  int texcoordAccessor(const float* t, size_t vertices, int& stepBits);
  std::vector<float> unitNormals(const Mesh& m) const;
  std::vector<float> scaledNormals(const Mesh& m, const GltfScale& scale) const;
  std::vector<float> flippedTexcoords(const Mesh& m, std::array<float, 2> shift) const;
  int normals(const Mesh& m);
  int texcoords(const Mesh& m, std::array<float, 2> shift, int& stepBits);
  WeldedVertices weld(const Mesh& m, bool withNormals, bool withColors) const;
  // Indices (of `vertices` vertices) as 16-bit where they fit, into the indices' pooled
  // view: where they lie there.
  struct IndexSpan {
    int view = 0, type = 0;
    size_t offset = 0;  // in the view
    size_t size = 0;    // of an index
  };
  template <class Indices>
  IndexSpan indexView(const Indices& indices, size_t vertices);
  json sharedAttributes(uint32_t mesh, const GltfScale& scale);
  int sharedMesh(uint32_t mesh, uint32_t material, const GltfScale& scale = kGltfUnitScale);
  GltfScale foldedScale(const InstancedPart& part) const;
  int instancedNode(const InstancedPart& part);
  int instanceNode(const InstancedPart& part, size_t k);
  int bakedMesh(const GroupNode& g, const std::string& name, bool& wrote, GltfPositionGrid* grid);
  int groupNode(const GroupNode& g, json node);
  int startNode(const StartNode& s);
  json materialJson(const Material& m, uint32_t ownSets, int uvStepBits);
  void uvSetAttributes(const Mesh& m, const WeldedVertices& w, json& attributes);
  bool verticesFinite(std::string& error) const;

  const Scene& scene_;
  std::vector<PlacedNode>* placed_;  // may be null
  GltfEncoding encoding_;
  bool quantized_ = false, textureTransform_ = false;  // what the file then requires
  std::map<uint32_t, int> sharedUvStepBits_;  // per shared mesh, its TEXCOORD_0's (0: floats)
  std::string bin_;
  struct Pool {
    int view = -1;
    std::string bytes;
  };
  std::map<std::pair<GltfPoolKind, size_t>, Pool> pools_;  // (kind, byteStride) -> its view
  json views_ = json::array(), accessors_ = json::array(), meshes_ = json::array(), nodes_ = json::array();
  // Per (shared mesh, the scale folded into it: instancedNode), its vertex accessors and its
  // tangents' (normal maps); per shared mesh its indices' and texture coordinates' (which
  // the scale leaves as they are).
  std::map<std::pair<uint32_t, GltfScale>, json> sharedAttributes_;
  std::map<std::pair<uint32_t, GltfScale>, int> sharedTangents_;
  std::map<uint32_t, int> sharedIndices_, sharedTexcoords_;
  std::map<std::tuple<uint32_t, uint32_t, GltfScale>, int> sharedMeshes_;  // (mesh, material, scale) -> glTF mesh
  // (Scene::materials index, the layers sampled with their own uv set, TEXCOORD_0's step
  // bits: texcoordAccessor) -> the file's material (only those used)
  std::map<std::tuple<uint32_t, uint32_t, int>, int> materialOut_;
  json materials_ = json::array();
  // An image the file embeds: one of Scene::images (`file`); the base colour texture made
  // from a colour map and an opacity map (base_color_opacity_image.h: `opacity` set); or the
  // metallic-roughness texture packed from a roughness and a metallic map
  // (metallic_roughness_image.h). Scene::images indices, -1: none.
  struct ImageOut {
    int32_t file = -1, roughness = -1, metallic = -1, color = -1, opacity = -1;
    bool operator==(const ImageOut&) const = default;
  };
  std::vector<ImageOut> imagesOut_;  // the file's textures' images, in order (only those used)
  bool instancing_ = false;
  bool specular_ = false;  // a material has KHR_materials_specular

  // `sets`: the uv sets 1..9 the primitive has (bit n: TEXCOORD_n is set n's). Each texture
  // layer of the material samples its own set where the primitive has it (the normal map
  // only beside a colour map, as before the other layers came).
  int material(uint32_t k, uint32_t sets = 0, int uvStepBits = 0) {
    const Material& m = scene_.materials[k];
    if (m.image < 0) uvStepBits = 0;  // nothing samples TEXCOORD_0: no variant
    uint32_t own = 0;
    for (uint32_t layer = 1; layer < Finish::kLayers; ++layer)
      if ((sets >> layer & 1) && m.maps[layer] >= 0 && (layer != kNormalMapUvSet || m.image >= 0)) own |= 1u << layer;
    const auto [it, added] = materialOut_.emplace(std::make_tuple(k, own, uvStepBits), int(materials_.size()));
    if (added) materials_.push_back(materialJson(m, own, uvStepBits));
    return it->second;
  }
};

int Writer::positions(const float* p, size_t vertices) {
  const int a = vertexAccessor(p, vertices, 3);
  std::array<double, 3> lo, hi;
  lo.fill(INFINITY), hi.fill(-INFINITY);
  for (size_t v = 0; v < vertices; ++v)
    for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], double(p[3 * v + d])), hi[d] = std::max(hi[d], double(p[3 * v + d]));
  // As the floats' shortest decimals (29.3, not 29.299999237060547): a tenth of a city's JSON.
  const auto shortest = [](const std::array<double, 3>& x) {
    json out = json::array();
    for (double d : x) out.push_back(gltfShortest(float(d)));
    return out;
  };
  accessors_[a]["min"] = shortest(lo);
  accessors_[a]["max"] = shortest(hi);
  return a;
}

// 16-bit unsigned positions on `grid` (KHR_mesh_quantization: not normalized, min/max in
// the stored integers).
int Writer::quantizedPositions(const float* p, size_t vertices, const GltfPositionGrid& grid) {
  std::vector<uint16_t> q(3 * vertices);
  std::array<uint16_t, 3> lo{65535, 65535, 65535}, hi{0, 0, 0};
  for (size_t v = 0; v < vertices; ++v)
    for (int d = 0; d < 3; ++d) {
      const double x = std::round((double(p[3 * v + d]) - grid.origin[d]) / grid.step);
      const uint16_t k = uint16_t(std::clamp(x, 0.0, 65535.0));
      q[3 * v + d] = k, lo[d] = std::min(lo[d], k), hi[d] = std::max(hi[d], k);
    }
  const int a = shortVertexAccessor(q, vertices, 3, false);
  accessors_[a]["min"] = lo;
  accessors_[a]["max"] = hi;
  return a;
}

// The grid of a group's baked parts (one mesh, one node): its box's lowest corner, and its
// longest side in 65535 steps.
GltfPositionGrid Writer::bakedGrid(const GroupNode& g) const {
  std::array<double, 3> lo, hi;
  lo.fill(INFINITY), hi.fill(-INFINITY);
  for (const BakedPart& part : g.baked)
    for (size_t k = 0; k < part.mesh.positions.size(); ++k)
      lo[k % 3] = std::min(lo[k % 3], double(part.mesh.positions[k])), hi[k % 3] = std::max(hi[k % 3], double(part.mesh.positions[k]));
  // Origin and step as short decimals (the JSON's node translation and scale): the
  // floats' shortest, the step's rounded up until 65535 steps span the box.
  GltfPositionGrid grid;
  double side = 0;
  for (int d = 0; d < 3; ++d)
    if (lo[d] <= hi[d]) grid.origin[d] = gltfShortest(float(lo[d])), side = std::max(side, hi[d] - grid.origin[d]);
  if (side > 0) {
    float step = float(side / 65535);
    while (gltfShortest(step) * 65535 < side) step = std::nextafter(step, INFINITY);
    grid.step = gltfShortest(step);
  }
  return grid;
}

// Unit vectors (normals: width 3; tangents: 4, w +-1) as floats, or quantizing as
// normalized 16-bit (a unit vector to 3e-5); values that are not finite stay floats, as
// without quantizing.
int Writer::unitVectors(const float* v, size_t vertices, int width) {
  if (!encoding_.quantize || !gltfValuesFinite(v, size_t(width) * vertices)) return vertexAccessor(v, vertices, width);
  std::vector<int16_t> q(size_t(width) * vertices);
  for (size_t k = 0; k < q.size(); ++k) q[k] = int16_t(std::lround(std::clamp(v[k], -1.0f, 1.0f) * 32767.0f));
  return shortVertexAccessor(q, vertices, width, true);
}

// TEXCOORD_0 as floats (`stepBits` 0), or quantizing as 16-bit integers in steps of
// 1/2^stepBits of a tile, whole tiles taken off (the sampler repeats) so that they lie
// around 0: as many bits as their span allows. The materials sampling them scale them back
// (KHR_texture_transform). Values that are not finite stay floats, as without quantizing.
int Writer::texcoordAccessor(const float* t, size_t vertices, int& stepBits) {
  stepBits = 0;
  if (encoding_.quantize && vertices > 0 && gltfValuesFinite(t, 2 * vertices)) {
    std::array<double, 2> lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY}, shift;
    for (size_t k = 0; k < 2 * vertices; ++k) lo[k % 2] = std::min(lo[k % 2], double(t[k])), hi[k % 2] = std::max(hi[k % 2], double(t[k]));
    double half = 0;
    for (int d = 0; d < 2; ++d) shift[d] = std::round((lo[d] + hi[d]) / 2), half = std::max({half, hi[d] - shift[d], shift[d] - lo[d]});
    if (std::isfinite(half)) {
      int bits = kMaxUvStepBits;
      while (bits >= kMinUvStepBits && half * double(1 << bits) > 32767) --bits;
      if (bits >= kMinUvStepBits) {
        std::vector<int16_t> q(2 * vertices);
        for (size_t k = 0; k < q.size(); ++k) q[k] = int16_t(std::lround((double(t[k]) - shift[k % 2]) * double(1 << bits)));
        stepBits = bits;
        return shortVertexAccessor(q, vertices, 2, false);
      }
    }
  }
  return vertexAccessor(t, vertices, 2);
}

// Unit normals (glTF requires them): a vanished one as the flattened output writes it.
std::vector<float> Writer::unitNormals(const Mesh& m) const {
  std::vector<float> n(m.normals.begin(), m.normals.end());
  for (size_t v = 0; v < n.size(); v += 3) {
    const double len = std::sqrt(double(n[v]) * n[v] + double(n[v + 1]) * n[v + 1] + double(n[v + 2]) * n[v + 2]);
    if (!(len > 0) || !std::isfinite(len))
      n[v] = 0, n[v + 1] = 0, n[v + 2] = 1;
    else if (std::abs(len - 1) > 1e-6)
      for (int d = 0; d < 3; ++d) n[v + d] = float(n[v + d] / len);
  }
  return n;
}

// v flipped (glTF's runs down); whole tiles taken off.
std::vector<float> Writer::flippedTexcoords(const Mesh& m, std::array<float, 2> shift) const {
  std::vector<float> t(m.texcoords.size());
  for (size_t k = 0; k < t.size(); ++k) {
    const float x = m.texcoords[k] - shift[k % 2];
    t[k] = k % 2 ? 1.0f - x : x;
  }
  return t;
}

// A uv set 1..9 as written: v flipped, no tiles taken off (each set's own frame).
std::vector<float> flippedUvSet(const MeshArray<float>& coords) {
  std::vector<float> t(coords.size());
  for (size_t k = 0; k < t.size(); ++k) t[k] = k % 2 ? 1.0f - coords[k] : coords[k];
  return t;
}

int Writer::normals(const Mesh& m) {
  const std::vector<float> n = unitNormals(m);
  return unitVectors(n.data(), m.vertexCount(), 3);
}

int Writer::texcoords(const Mesh& m, std::array<float, 2> shift, int& stepBits) {
  const std::vector<float> t = flippedTexcoords(m, shift);
  return texcoordAccessor(t.data(), m.vertexCount(), stepBits);
}

WeldedVertices Writer::weld(const Mesh& m, bool withNormals, bool withColors) const {
  const size_t n = m.vertexCount();
  const std::vector<float> normals = withNormals ? unitNormals(m) : std::vector<float>();
  const std::vector<float> texcoords = m.hasTexcoords() ? flippedTexcoords(m, {0, 0}) : std::vector<float>();
  std::vector<float> colors;
  if (withColors) {
    colors.assign(m.colors.begin(), m.colors.end());
    for (float& x : colors) x = io::clamp01(x);
  }
  std::vector<std::vector<float>> uvSets;
  for (const MeshUvSet& set : m.uvSets) uvSets.push_back(flippedUvSet(set.coords));
  // Each vertex's attributes side by side, compared as bytes.
  const size_t stride =
      3 + (withNormals ? 3 : 0) + (texcoords.empty() ? 0 : 2) + (withColors ? 3 : 0) + 2 * uvSets.size();
  std::vector<float> records(stride * n);
  for (size_t v = 0; v < n; ++v) {
    float* r = &records[stride * v];
    r = std::copy_n(&m.positions[3 * v], 3, r);
    if (withNormals) r = std::copy_n(&normals[3 * v], 3, r);
    if (!texcoords.empty()) r = std::copy_n(&texcoords[2 * v], 2, r);
    if (withColors) r = std::copy_n(&colors[3 * v], 3, r);
    for (const std::vector<float>& set : uvSets) r = std::copy_n(&set[2 * v], 2, r);
  }
  WeldedVertices w;
  w.uvSets.resize(uvSets.size());
  w.of.resize(n);
  std::unordered_map<std::string_view, uint32_t> first;
  first.reserve(n);
  const char* bytes = reinterpret_cast<const char*>(records.data());
  for (size_t v = 0; v < n; ++v) {
    const auto [it, added] = first.emplace(std::string_view(bytes + 4 * stride * v, 4 * stride), uint32_t(w.count));
    w.of[v] = it->second;
    if (!added) continue;
    ++w.count;
    w.positions.insert(w.positions.end(), &m.positions[3 * v], &m.positions[3 * v] + 3);
    if (withNormals) w.normals.insert(w.normals.end(), &normals[3 * v], &normals[3 * v] + 3);
    if (!texcoords.empty()) w.texcoords.insert(w.texcoords.end(), &texcoords[2 * v], &texcoords[2 * v] + 2);
    if (withColors) w.colors.insert(w.colors.end(), &colors[3 * v], &colors[3 * v] + 3);
    for (size_t k = 0; k < uvSets.size(); ++k) w.uvSets[k].insert(w.uvSets[k].end(), &uvSets[k][2 * v], &uvSets[k][2 * v] + 2);
  }
  return w;
}

template <class Indices>
Writer::IndexSpan Writer::indexView(const Indices& indices, size_t vertices) {
  // 65535 is no index of a 16-bit accessor (primitive restart).
  const bool narrow = vertices < 65535;
  const size_t size = narrow ? 2 : 4;
  const auto [v, offset] = pooled(GltfPoolKind::Indices, 0, size * indices.size(), size);
  char* out = pools_[{GltfPoolKind::Indices, 0}].bytes.data() + offset;
  for (const auto index : indices) {
    if (narrow) {
      const uint16_t i16 = uint16_t(index);
      std::memcpy(out, &i16, 2);
    } else {
      const uint32_t i32 = uint32_t(index);
      std::memcpy(out, &i32, 4);
    }
    out += size;
  }
  return {v, narrow ? kUnsignedShort : kUnsignedInt, offset, size};
}

// A shared mesh's positions scaled by `scale` (as floats, as a reader's instance matrix
// would), and its unit normals as that scale turns them (by its inverse).
std::vector<float> gltfScaledPositions(const Mesh& m, const GltfScale& scale) {
  std::vector<float> p(m.positions.begin(), m.positions.end());
  for (size_t k = 0; k < p.size(); ++k) p[k] = float(double(p[k]) * scale[k % 3]);
  return p;
}

std::vector<float> Writer::scaledNormals(const Mesh& m, const GltfScale& scale) const {
  std::vector<float> n = unitNormals(m);
  if (scale == kGltfUnitScale) return n;
  for (size_t v = 0; v < n.size(); v += 3) {
    const double x = n[v] / double(scale[0]), y = n[v + 1] / double(scale[1]), z = n[v + 2] / double(scale[2]);
    const double len = std::sqrt(x * x + y * y + z * z);
    if (len > 0) n[v] = float(x / len), n[v + 1] = float(y / len), n[v + 2] = float(z / len);
  }
  return n;
}

json Writer::sharedAttributes(uint32_t mesh, const GltfScale& scale) {
  auto it = sharedAttributes_.find({mesh, scale});
  if (it != sharedAttributes_.end()) return it->second;
  const SharedMesh& s = scene_.meshes[mesh];
  const Mesh& m = *s.mesh;
  json attributes;
  if (scale == kGltfUnitScale) {
    attributes["POSITION"] = positions(m.positions.data(), m.vertexCount());
  } else {
    const std::vector<float> p = gltfScaledPositions(m, scale);
    attributes["POSITION"] = positions(p.data(), m.vertexCount());
  }
  if (io::hasNormals(m)) {
    const std::vector<float> n = scaledNormals(m, scale);
    attributes["NORMAL"] = unitVectors(n.data(), m.vertexCount(), 3);
  }
  if (m.hasTexcoords()) {
    if (!sharedTexcoords_.count(mesh)) sharedTexcoords_[mesh] = texcoords(m, s.uvShift, sharedUvStepBits_[mesh]);
    attributes["TEXCOORD_0"] = sharedTexcoords_[mesh];
  }
  if (!sharedIndices_.count(mesh)) {
    const IndexSpan indices = indexView(m.indices, m.vertexCount());
    sharedIndices_[mesh] = accessor(indices.view, m.indices.size(), indices.type, "SCALAR", indices.offset);
  }
  return sharedAttributes_[{mesh, scale}] = attributes;
}

int Writer::sharedMesh(uint32_t mesh, uint32_t material, const GltfScale& scale) {
  const auto at = sharedMeshes_.find({mesh, material, scale});
  if (at != sharedMeshes_.end()) return at->second;
  json attributes = sharedAttributes(mesh, scale);
  const Material& look = scene_.materials[material];
  const Mesh& m = *scene_.meshes[mesh].mesh;
  if (look.image >= 0 && look.normalImage() >= 0 && m.hasTexcoords() && io::hasNormals(m)) {
    // The tangents of a normal-mapped shared mesh, once per mesh (and scale).
    auto [it, added] = sharedTangents_.emplace(std::make_pair(mesh, scale), -1);
    if (added) {
      const std::vector<float> n = scaledNormals(m, scale), t = flippedTexcoords(m, scene_.meshes[mesh].uvShift);
      const std::vector<float> p = gltfScaledPositions(m, scale);
      const std::vector<uint32_t> indices(m.indices.begin(), m.indices.end());
      const std::vector<float> tangents = normalMapTangents(p.data(), n.data(), t.data(), m.vertexCount(), indices);
      it->second = unitVectors(tangents.data(), m.vertexCount(), 4);
    }
    attributes["TANGENT"] = it->second;
  }
  json primitive = {{"attributes", attributes},
                    {"indices", sharedIndices_[mesh]},
                    {"material", this->material(material, 0, sharedUvStepBits_[mesh])},
                    {"mode", kTriangles}};
  meshes_.push_back({{"name", scene_.meshes[mesh].name}, {"primitives", json::array({primitive})}});
  return sharedMeshes_[{mesh, material, scale}] = int(meshes_.size() - 1);
}

// The one scale every instance of `part` has (a facade's windows: the window's size),
// which instancedNode folds into the mesh and leaves SCALE out: where that mesh is
// written anyway, or its copy costs less than the SCALE it saves (12 bytes an instance).
// kGltfUnitScale where the scales differ (SCALE written), or are all 1 (left out).
GltfScale Writer::foldedScale(const InstancedPart& part) const {
  if (part.trs.empty()) return kGltfUnitScale;
  const auto asFloats = [](const Trs& t) { return GltfScale{float(t.scale[0]), float(t.scale[1]), float(t.scale[2])}; };
  const GltfScale scale = asFloats(part.trs.front());
  for (const Trs& t : part.trs)
    if (asFloats(t) != scale) return kGltfUnitScale;
  for (float x : scale)
    if (!(x > 0) || !std::isfinite(x)) return kGltfUnitScale;
  const Mesh& m = *scene_.meshes[part.mesh].mesh;
  const size_t copy = m.vertexCount() * (io::hasNormals(m) ? 24 : 12) + 300;  // its vertices and JSON
  const bool written = sharedAttributes_.count({part.mesh, scale}) > 0;
  return written || 12 * part.trs.size() > copy ? scale : kGltfUnitScale;
}

int Writer::instancedNode(const InstancedPart& part) {
  const size_t n = part.instances.size();
  // The colours only where they vary: else the material has the part's one colour.
  const bool colored = scene_.materials[part.material].vertexColors;
  // The part's block of the instances' pooled view: translations, rotations, scales,
  // colours, one after another, written in place (a million instances are 40 MB).
  // Rotations are floats but quantizing: as normalized 16-bit components (which the
  // extension allows) the city's wall pieces under --instancing on moved by up to 0.35 mm.
  const bool shortRotations = encoding_.quantize;
  const size_t rotationBytes = shortRotations ? 8 : 16;
  // SCALE only where the instances' scales differ: else it is in the mesh, or 1.
  const GltfScale folded = foldedScale(part);
  bool scaled = false;
  for (const Trs& t : part.trs)
    for (int d = 0; d < 3; ++d) scaled |= float(t.scale[d]) != folded[d];
  const size_t bytes = ((colored ? 3 : 0) * sizeof(float) + (scaled ? 12 : 0) + 12 + rotationBytes) * n;
  const auto [v, offset] = pooled(GltfPoolKind::Instances, 0, bytes, 4);
  char* data = pools_[{GltfPoolKind::Instances, 0}].bytes.data() + offset;
  const auto put = [&](auto x) { std::memcpy(data, &x, sizeof x), data += sizeof x; };
  for (const Trs& t : part.trs)
    for (double x : t.translation) put(float(x));
  for (const Trs& t : part.trs) {
    // Rounded to floats, renormalised there so that the quaternion stays a unit one.
    std::array<float, 4> q;
    double len = 0;
    for (int k = 0; k < 4; ++k) q[k] = float(t.rotation[k]), len += double(q[k]) * q[k];
    len = std::sqrt(len);
    for (float x : q)
      if (shortRotations)
        put(int16_t(std::lround(std::clamp(double(x) / len, -1.0, 1.0) * 32767)));
      else
        put(float(x / len));
  }
  if (scaled)
    for (const Trs& t : part.trs)
      for (double x : t.scale) put(float(x));
  if (colored)
    for (const auto& c : part.colors)
      for (float x : c) put(io::clamp01(x));
  const size_t scales = offset + (12 + rotationBytes) * n, colors = scales + (scaled ? 12 * n : 0);
  json attributes = {{"TRANSLATION", accessor(v, n, kFloat, "VEC3", offset)},
                     {"ROTATION", accessor(v, n, shortRotations ? kShort : kFloat, "VEC4", offset + 12 * n)}};
  if (shortRotations) accessors_[int(attributes["ROTATION"])]["normalized"] = true;
  if (scaled) attributes["SCALE"] = accessor(v, n, kFloat, "VEC3", scales);
  if (colored) attributes["_COLOR_0"] = accessor(v, n, kFloat, "VEC3", colors);
  instancing_ = true;
  nodes_.push_back({{"name", scene_.meshes[part.mesh].name},
                    {"mesh", sharedMesh(part.mesh, part.material, folded)},
                    {"extensions", {{kInstancing, {{"attributes", attributes}}}}},
                    {"extras", {{"asset", scene_.meshes[part.mesh].asset}, {"instances", n}}}});
  if (placed_) placed_->push_back({int(nodes_.size() - 1), part.instances.data(), n});
  return int(nodes_.size() - 1);
}

int Writer::instanceNode(const InstancedPart& part, size_t k) {
  const Trs& t = part.trs[k];
  nodes_.push_back({{"name", scene_.meshes[part.mesh].name},
                    {"mesh", sharedMesh(part.mesh, part.material)},
                    {"extras", {{"asset", scene_.meshes[part.mesh].asset}}},
                    {"translation", t.translation},
                    {"rotation", t.rotation},
                    {"scale", t.scale}});
  if (placed_) placed_->push_back({int(nodes_.size() - 1), part.instances.data() + k, 1});
  return int(nodes_.size() - 1);
}

// The group's baked parts as one glTF mesh: per part its own vertices (equal ones
// welded; no normals where the part is shaded flat, as readers then shade it), a
// primitive per image (untextured last) and one for its line segments. Quantizing, its
// positions lie on `grid` (the node that holds the mesh maps them back).
int Writer::bakedMesh(const GroupNode& g, const std::string& name, bool& wrote, GltfPositionGrid* grid) {
  json primitives = json::array();
  if (grid) *grid = bakedGrid(g);
  for (const BakedPart& part : g.baked) {
    const Mesh& m = part.mesh;
    const Material& untextured = scene_.materials[part.materials.back()];
    const bool colored = untextured.vertexColors && io::hasColors(m);
    // A normal map needs normals and tangents (glTF ignores tangents without normals).
    // CityEngine samples the normal map with uv set 5, or set 0 where the shape has no set 5.
    const uint32_t normalSet = m.uvSet(kNormalMapUvSet) ? kNormalMapUvSet : 0;
    uint32_t sets = 0;  // the uv sets 1..9 the part has, for its materials' layers
    for (const MeshUvSet& u : m.uvSets) sets |= 1u << u.set;
    bool normalMapped = false;
    for (uint32_t k : part.materials) normalMapped |= scene_.materials[k].image >= 0 && scene_.materials[k].normalImage() >= 0;
    normalMapped = normalMapped && (normalSet || m.hasTexcoords()) && io::hasNormals(m);
    const WeldedVertices w = weld(m, io::hasNormals(m) && (normalMapped || !flatShaded(m)), colored);
    json attributes = {{"POSITION", grid ? quantizedPositions(w.positions.data(), w.count, *grid)
                                         : positions(w.positions.data(), w.count)}};
    if (!w.normals.empty())
      attributes["NORMAL"] = unitVectors(w.normals.data(), w.count, 3);
    int uvStepBits = 0;
    if (!w.texcoords.empty())
      attributes["TEXCOORD_0"] = texcoordAccessor(w.texcoords.data(), w.count, uvStepBits);
    uvSetAttributes(m, w, attributes);
    if (colored)
      attributes["COLOR_0"] = vertexAccessor(w.colors.data(), w.count, 3);
    // The triangles grouped by image, as runs say; untextured ones (-1) last.
    std::vector<uint32_t> indices;
    indices.reserve(m.indices.size());
    std::vector<std::pair<uint32_t, size_t>> groups;  // (material, index count)
    const auto put = [&](auto begin, auto end) {
      for (auto it = begin; it != end; ++it) indices.push_back(w.of[*it]);
    };
    const auto add = [&](int32_t image) {
      const size_t before = indices.size();
      if (!m.textured()) {
        if (image < 0) put(m.indices.begin(), m.indices.end());
      } else {
        for (size_t r = 0; r < m.textureRuns.size(); ++r)
          if (m.textureRuns[r].texture == image)
            put(m.indices.begin() + 3 * m.textureRuns[r].firstTriangle, m.indices.begin() + 3 * m.runEnd(r));
      }
      if (indices.size() > before)
        groups.push_back({part.materials[image < 0 ? part.materials.size() - 1 : size_t(image)], indices.size() - before});
    };
    for (int32_t t = 0; t < int32_t(m.textures.size()); ++t) add(t);
    add(-1);
    if (normalMapped && !indices.empty()) {
      const float* normalUv = w.texcoords.data();
      for (size_t k = 0; k < m.uvSets.size(); ++k)
        if (m.uvSets[k].set == normalSet) normalUv = w.uvSets[k].data();
      const std::vector<float> tangents = normalMapTangents(w.positions.data(), w.normals.data(), normalUv, w.count, indices);
      attributes["TANGENT"] = unitVectors(tangents.data(), w.count, 4);
    }
    if (!indices.empty()) {
      const IndexSpan span = indexView(indices, w.count);
      size_t first = 0;
      for (const auto& [material, count] : groups) {
        primitives.push_back({{"attributes", attributes},
                              {"indices", accessor(span.view, count, span.type, "SCALAR", span.offset + span.size * first)},
                              {"material", this->material(material, sets, uvStepBits)},
                              {"mode", kTriangles}});
        first += count;
      }
    }
    if (!m.lines.empty()) {
      std::vector<uint32_t> lines;
      lines.reserve(m.lines.size());
      for (uint32_t k : m.lines) lines.push_back(w.of[k]);
      const IndexSpan span = indexView(lines, w.count);
      primitives.push_back({{"attributes", attributes},
                            {"indices", accessor(span.view, lines.size(), span.type, "SCALAR", span.offset)},
                            {"material", material(part.materials.back(), 0, uvStepBits)},
                            {"mode", kLines}});
    }
  }
  wrote = !primitives.empty();
  if (!wrote) return -1;
  meshes_.push_back({{"name", name}, {"primitives", std::move(primitives)}});
  return int(meshes_.size() - 1);
}

// The group's node (`node` holds its name and extras): its baked mesh, and a child per
// instanced part and per mirrored instance.
int Writer::groupNode(const GroupNode& g, json node) {
  json children = json::array();
  for (const InstancedPart& p : g.instanced)
    if (scene_.instancing == Instancing::Nodes)
      for (size_t k = 0; k < p.instances.size(); ++k) children.push_back(instanceNode(p, k));
    else
      children.push_back(instancedNode(p));
  for (const InstancedPart& p : g.mirrored)
    for (size_t k = 0; k < p.instances.size(); ++k) children.push_back(instanceNode(p, k));
  bool baked = false;
  GltfPositionGrid grid;
  const std::string name = node.value("name", std::string("baked"));
  const int mesh = bakedMesh(g, name, baked, encoding_.quantize ? &grid : nullptr);
  if (baked && !encoding_.quantize) {
    node["mesh"] = mesh;
  } else if (baked) {
    // The grid's transform, on the node itself where it has no children (which it would
    // scale too), else on a child of its own.
    json holder = {{"mesh", mesh}, {"translation", grid.origin}, {"scale", {grid.step, grid.step, grid.step}}};
    if (children.empty()) {
      node.update(holder);
    } else {
      holder["name"] = name + " (quantized)";
      nodes_.push_back(std::move(holder));
      children.push_back(int(nodes_.size() - 1));
    }
  }
  if (!g.bakedAssets.empty()) {
    json counts = json::object();
    for (const auto& [asset, count] : g.bakedAssets) counts[asset] = count;
    node["extras"]["baked"] = std::move(counts);
  }
  if (!children.empty()) node["children"] = std::move(children);
  nodes_.push_back(std::move(node));
  return int(nodes_.size() - 1);
}

int Writer::startNode(const StartNode& s) {
  json node = {{"name", s.info.name}, {"extras", startExtras(s)}};
  if (scene_.groupBy == GroupBy::None) {
    // No group level: the one group's contents are the start node's own.
    if (s.groups.empty()) {
      nodes_.push_back(std::move(node));
      return int(nodes_.size() - 1);
    }
    return groupNode(s.groups.front(), std::move(node));
  }
  json children = json::array();
  for (const GroupNode& g : s.groups)
    children.push_back(groupNode(g, {{"name", g.name}, {"extras", {{"instances", g.instanceCount}}}}));
  if (!children.empty()) node["children"] = std::move(children);
  nodes_.push_back(std::move(node));
  return int(nodes_.size() - 1);
}

json Writer::materialJson(const Material& m, uint32_t ownSets, int uvStepBits) {
  // The defaults (roughness 0.8, metallic 0) as the numbers every material had before.
  // Others as their shortest decimal (0.3, not the float's 0.30000001192092896).
  const auto factor = [](float x) {
    if (x == 0.8f) return json(0.8);
    char text[io::kMaxFloatText + 1];
    *io::putShortestFloat(text, io::clamp01(x)) = '\0';
    return json(std::strtod(text, nullptr));
  };
  json pbr = {{"metallicFactor", factor(m.metallic)}, {"roughnessFactor", factor(m.roughness)}};
  const float alpha = io::clamp01(m.opacity);
  if ((!m.vertexColors && m.color != std::array<float, 3>{1, 1, 1}) || alpha < 1) {
    const std::array<float, 3> c = m.vertexColors ? std::array<float, 3>{1, 1, 1} : m.color;
    pbr["baseColorFactor"] = {io::clamp01(c[0]), io::clamp01(c[1]), io::clamp01(c[2]), alpha};
  }
  const auto texture = [&](ImageOut image) {
    const auto at = std::find(imagesOut_.begin(), imagesOut_.end(), image);
    if (at == imagesOut_.end()) imagesOut_.push_back(image);
    json t = {{"index", std::find(imagesOut_.begin(), imagesOut_.end(), image) - imagesOut_.begin()}};
    // Quantized TEXCOORD_0 (texcoordAccessor) scaled back to tiles.
    if (uvStepBits > 0) {
      const double step = std::ldexp(1.0, -uvStepBits);
      t["extensions"][kTextureTransform] = {{"scale", {step, step}}};
      textureTransform_ = true;
    }
    return t;
  };
  // The uv set a texture layer samples: its own where the primitive has it, else the base
  // colour image's (set 0, glTF's default: no texCoord written); -1 where there is neither.
  const auto setOf = [&](uint32_t layer) { return (ownSets >> layer & 1) ? int(layer) : m.image >= 0 ? 0 : -1; };
  const auto layerTexture = [&](ImageOut image, int set) {
    json t = texture(image);
    if (set > 0) t["texCoord"] = set, t.erase("extensions");  // its own set: floats
    return t;
  };
  // CityEngine's opacity map as the base colour texture's alpha (glTF has no texture of its
  // own for it): beside the colour map, on its coordinates; without one, a white image on
  // the opacity map's own set.
  const int32_t opacityMap = m.maps[Finish::kOpacityMap];
  if (m.image >= 0 && opacityMap >= 0) pbr["baseColorTexture"] = texture({-1, -1, -1, m.image, opacityMap});
  else if (m.image >= 0) pbr["baseColorTexture"] = texture({m.image});
  else if (opacityMap >= 0 && setOf(Finish::kOpacityMap) > 0)
    pbr["baseColorTexture"] = layerTexture({-1, -1, -1, -1, opacityMap}, setOf(Finish::kOpacityMap));
  const bool opacityMapped = pbr.contains("baseColorTexture") && opacityMap >= 0;
  // CityEngine's roughness and metallic maps, packed into one image (green, blue) sampled
  // with the roughness map's set, else the metallic map's.
  const int32_t roughnessMap = m.maps[Finish::kRoughnessMap], metallicMap = m.maps[Finish::kMetallicMap];
  const int packedSet = roughnessMap >= 0 && setOf(Finish::kRoughnessMap) >= 0 ? setOf(Finish::kRoughnessMap)
                        : metallicMap >= 0                                     ? setOf(Finish::kMetallicMap)
                                                                               : -1;
  if (packedSet >= 0) pbr["metallicRoughnessTexture"] = layerTexture({-1, roughnessMap, metallicMap}, packedSet);
  // The same material with a layer on its own uv set is another one, named apart
  // ("_uv5": the normal map on set 5).
  std::string name = m.name;
  if (ownSets) {
    name += "_uv";
    for (uint32_t layer = 1; layer < Finish::kLayers; ++layer)
      if (ownSets >> layer & 1) name += char('0' + layer);
  }
  json out = {{"doubleSided", true}, {"name", name}, {"pbrMetallicRoughness", std::move(pbr)}};
  // CGA's material.opacity: blended where below 1. The normal map only where there is a
  // base colour image, on uv set 5's coordinates (TEXCOORD_5) where the primitive has them,
  // else on the base colour's (TEXCOORD_0).
  if (alpha < 1 || opacityMapped) out["alphaMode"] = "BLEND";
  if (m.image >= 0 && m.normalImage() >= 0) out["normalTexture"] = layerTexture({m.normalImage()}, setOf(kNormalMapUvSet));
  // The occlusion map (glTF reads its red channel, as CityEngine does).
  const int32_t occlusionMap = m.maps[Finish::kOcclusionMap];
  if (occlusionMap >= 0 && setOf(Finish::kOcclusionMap) >= 0)
    out["occlusionTexture"] = layerTexture({occlusionMap}, setOf(Finish::kOcclusionMap));
  // The emissive colour, and the emissive map times it; a map with the colour left black
  // (CityEngine's default) shows as it is (factor white) rather than not at all.
  const int32_t emissiveMap = m.maps[Finish::kEmissiveMap];
  const bool emissiveMapped = emissiveMap >= 0 && setOf(Finish::kEmissiveMap) >= 0;
  if (emissiveMapped) out["emissiveTexture"] = layerTexture({emissiveMap}, setOf(Finish::kEmissiveMap));
  if (m.emissive != std::array<float, 3>{0, 0, 0})
    out["emissiveFactor"] = {factor(m.emissive[0]), factor(m.emissive[1]), factor(m.emissive[2])};
  else if (emissiveMapped)
    out["emissiveFactor"] = {1.0, 1.0, 1.0};
  // The specular map (a colour): KHR_materials_specular's specular colour texture, times
  // its default factors (1).
  const int32_t specularMap = m.maps[Finish::kSpecularMap];
  if (specularMap >= 0 && setOf(Finish::kSpecularMap) >= 0) {
    out["extensions"][kSpecular] = {{"specularColorTexture", layerTexture({specularMap}, setOf(Finish::kSpecularMap))}};
    specular_ = true;
  }
  return out;
}

// CGA's uv sets 1..9 as TEXCOORD_1..9 (TEXCOORD_n is always set n). glTF numbers a
// primitive's TEXCOORD_n from 0 without gaps, so the sets below the highest one the part
// has that it lacks (set 0 included) are written as zeros, one accessor shared by them.
void Writer::uvSetAttributes(const Mesh& m, const WeldedVertices& w, json& attributes) {
  if (m.uvSets.empty()) return;
  int zeros = -1;
  const auto zeroAccessor = [&] {
    if (zeros < 0) zeros = vertexAccessor(nullptr, w.count, 2);
    return zeros;
  };
  if (w.texcoords.empty()) attributes["TEXCOORD_0"] = zeroAccessor();
  uint32_t next = 1;
  for (size_t k = 0; k < m.uvSets.size(); ++k) {
    for (; next < m.uvSets[k].set; ++next) attributes["TEXCOORD_" + std::to_string(next)] = zeroAccessor();
    attributes["TEXCOORD_" + std::to_string(next++)] = vertexAccessor(w.uvSets[k].data(), w.count, 2);
  }
}

bool Writer::verticesFinite(std::string& error) const {
  const auto finite = [](const Mesh& m) {
    return std::all_of(m.positions.begin(), m.positions.end(), [](float x) { return std::isfinite(x); });
  };
  for (const SharedMesh& s : scene_.meshes)
    if (!finite(*s.mesh)) return error = "the mesh '" + s.name + "' has a vertex that is not finite", false;
  for (const StartNode& s : scene_.starts)
    for (const GroupNode& g : s.groups)
      for (const BakedPart& p : g.baked)
        if (!finite(p.mesh)) return error = "a vertex of '" + s.info.name + "' is not finite", false;
  return true;
}

bool Writer::write(bool binary, std::string& bytes, std::string& error) {
  if (!verticesFinite(error)) return false;
  json j;
  j["asset"] = {{"generator", "fgsg"}, {"version", "2.0"}};
  j["scene"] = 0;
  json roots = json::array();
  for (const StartNode& s : scene_.starts) roots.push_back(startNode(s));
  flushPools();
  // The images after the geometry, each whole.
  if (!imagesOut_.empty()) {
    std::vector<io::EmbeddedImage> images;
    for (const ImageOut& out : imagesOut_) {
      if (out.file >= 0) {
        Mesh holder;  // io::readImages reads a mesh's images
        holder.textures.push_back(scene_.images[size_t(out.file)]);
        holder.textureRuns.push_back({0, 0});
        std::vector<io::EmbeddedImage> one;
        if (!io::readImages(holder, one, error)) return false;
        images.push_back(std::move(one.front()));
      } else {
        const auto path = [&](int32_t k) { return k >= 0 ? &scene_.images[size_t(k)] : nullptr; };
        io::EmbeddedImage packed;
        packed.mimeType = "image/png";
        if (out.opacity >= 0 ? !packBaseColorOpacity(path(out.color), *path(out.opacity), packed.bytes, error)
                             : !packMetallicRoughness(path(out.roughness), path(out.metallic), packed.bytes, error))
          return false;
        images.push_back(std::move(packed));
      }
    }
    json jsonImages = json::array(), textures = json::array();
    for (size_t t = 0; t < images.size(); ++t) {
      jsonImages.push_back({{"bufferView", view(images[t].bytes.data(), images[t].bytes.size(), 0)},
                            {"mimeType", images[t].mimeType}});
      textures.push_back({{"sampler", 0}, {"source", int(t)}});
    }
    j["images"] = std::move(jsonImages);
    j["textures"] = std::move(textures);
    j["samplers"] = json::array({json{{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 10497}, {"wrapT", 10497}}});
  }
  bin_.resize(padded4(bin_.size()), '\0');
  if (!accessors_.empty()) j["accessors"] = std::move(accessors_);
  if (!views_.empty()) j["bufferViews"] = std::move(views_);
  if (!bin_.empty()) {
    json buffer = {{"byteLength", bin_.size()}};
    if (!binary) buffer["uri"] = "data:application/octet-stream;base64," + base64(bin_);
    j["buffers"] = json::array({std::move(buffer)});
  }
  if (!materials_.empty()) j["materials"] = std::move(materials_);
  if (!meshes_.empty()) j["meshes"] = std::move(meshes_);
  if (!nodes_.empty()) j["nodes"] = std::move(nodes_);
  json scene = {{"name", "fgsg"}};
  if (!roots.empty()) scene["nodes"] = std::move(roots);
  j["scenes"] = json::array({std::move(scene)});
  json used = json::array(), required = json::array();
  if (instancing_) used.push_back(kInstancing);
  if (specular_) used.push_back(kSpecular);
  // Readers without these would read the 16-bit data as something else.
  if (quantized_) used.push_back(kQuantization), required.push_back(kQuantization);
  if (textureTransform_) used.push_back(kTextureTransform), required.push_back(kTextureTransform);
  if (!used.empty()) j["extensionsUsed"] = std::move(used);
  if (!required.empty()) j["extensionsRequired"] = std::move(required);
  std::string text = j.dump();
  if (!binary) {
    bytes = std::move(text);
    bytes += '\n';
    return true;
  }
  if (!glbPrefix(text, bin_.size(), bytes, error)) return false;
  bytes.reserve(bytes.size() + bin_.size());
  bytes += bin_;
  return true;
}

}  // namespace

bool encodeGltf(const Scene& scene, bool binary, std::string& bytes, std::string& error,
                std::vector<PlacedNode>* placed, const GltfEncoding& encoding) {
  if (placed) placed->clear();
  Writer w(scene, placed, encoding);
  return w.write(binary, bytes, error);
}

bool stageGltf(const Scene& scene, const std::string& path, io::OutputTransaction& outputs, std::string& error,
               const GltfEncoding& encoding) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".glb" && ext != ".gltf") {
    error = path + ": a scene is written as glTF (.glb or .gltf)";
    return false;
  }
  std::string bytes;
  if (!encodeGltf(scene, ext == ".glb", bytes, error, nullptr, encoding)) {
    error = path + ": " + error;
    return false;
  }
  return outputs.stage(path, bytes, error);
}

}  // namespace fgsg::rt::output
