#include "runtime/render/preview.h"

#include "runtime/io/png_encode.h"
#include "runtime/texture/color_texture.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <memory>
#include <new>


namespace fgsg::rt::render {

namespace {

using Eigen::Vector3d;
using Eigen::Vector3f;

constexpr double kPi = 3.14159265358979323846;
constexpr double kFramingMargin = 1.08;  // the fitted view leaves a little room around the mesh
constexpr double kFieldOfViewDegrees = 40.0;  // vertical, perspective view
const Vector3d kViewFrom(0.9, 0.7, 1.2);  // the 3/4 view direction (towards the camera)
const Vector3f kDefaultColor(0.8f, 0.8f, 0.8f);

struct Camera {
  bool orthographic = false;
  Vector3d eye, forward, right, up;
  double halfWidth = 1, halfHeight = 1;  // ortho: world units; perspective: tan(fov/2)

  // The ray through image point (x, y) in [0,1]^2, y downwards.
  void ray(double x, double y, Vector3d& org, Vector3d& dir) const {
    const double sx = (2 * x - 1) * halfWidth, sy = (1 - 2 * y) * halfHeight;
    if (orthographic) {
      org = eye + sx * right + sy * up;
      dir = forward;
    } else {
      org = eye;
      dir = (forward + sx * right + sy * up).normalized();
    }
  }
};

// A perspective camera looking at `centre` along -towardsEye, `right` square to it and
// horizontal, at `distance`, or when that is 0 backed off until all eight box corners
// are inside the view (tighter than framing the bounding sphere when the scene is long
// and thin).
Camera perspectiveCamera(const Vector3d& mn, const Vector3d& mx, const Vector3d& towardsEye, const Vector3d& right,
                         double distance, double aspect) {
  const Vector3d centre = 0.5 * (mn + mx);
  Camera cam;
  cam.halfHeight = std::tan(0.5 * kFieldOfViewDegrees * kPi / 180.0);
  cam.halfWidth = cam.halfHeight * aspect;
  cam.forward = -towardsEye;
  cam.right = right;
  cam.up = cam.right.cross(cam.forward);
  if (distance <= 0) {
    for (int corner = 0; corner < 8; ++corner) {
      const Vector3d p((corner & 1) ? mx.x() : mn.x(), (corner & 2) ? mx.y() : mn.y(),
                       (corner & 4) ? mx.z() : mn.z());
      const Vector3d d = p - centre;
      const double depth = d.dot(towardsEye);  // towards the camera
      distance = std::max({distance, depth + kFramingMargin * std::abs(d.dot(cam.right)) / cam.halfWidth,
                           depth + kFramingMargin * std::abs(d.dot(cam.up)) / cam.halfHeight});
    }
    distance = std::max(distance, 1e-9);
  }
  cam.eye = centre + distance * towardsEye;
  return cam;
}

Camera fitCamera(const Mesh& mesh, double aspect) {
  const auto lo = mesh.boundsMin(), hi = mesh.boundsMax();
  const Vector3d mn(lo[0], lo[1], lo[2]), mx(hi[0], hi[1], hi[2]);
  const Vector3d centre = 0.5 * (mn + mx), extent = mx - mn;
  const double maxExtent = std::max(extent.maxCoeff(), 1e-9);  // a lone point still gets a view
  Camera cam;
  if (extent.z() < kFlatPreviewRatio * maxExtent) {
    // Straight down -Z: a planar pattern reads best as a plan.
    cam.orthographic = true;
    cam.forward = Vector3d(0, 0, -1);
    cam.right = Vector3d(1, 0, 0);
    cam.up = Vector3d(0, 1, 0);
    cam.eye = Vector3d(centre.x(), centre.y(), mx.z() + maxExtent);
    cam.halfWidth = std::max(0.5 * extent.x(), 1e-3 * maxExtent) * kFramingMargin;
    cam.halfHeight = std::max(0.5 * extent.y(), 1e-3 * maxExtent) * kFramingMargin;
    if (cam.halfWidth < cam.halfHeight * aspect)
      cam.halfWidth = cam.halfHeight * aspect;
    else
      cam.halfHeight = cam.halfWidth / aspect;
    return cam;
  }
  const Vector3d towardsEye = kViewFrom.normalized();
  return perspectiveCamera(mn, mx, towardsEye, (-towardsEye).cross(Vector3d(0, 1, 0)).normalized(), 0, aspect);
}

// PreviewCamera's orbit. `right` comes from the azimuth alone, so it stays defined
// looking straight down or up.
Camera orbitCamera(const Mesh& mesh, const PreviewCamera& orbit, double aspect) {
  const auto lo = mesh.boundsMin(), hi = mesh.boundsMax();
  const Vector3d mn(lo[0], lo[1], lo[2]), mx(hi[0], hi[1], hi[2]);
  const double az = orbit.azimuthDegrees * kPi / 180.0, el = orbit.elevationDegrees * kPi / 180.0;
  const Vector3d towardsEye(std::cos(el) * std::cos(az), std::sin(el), std::cos(el) * std::sin(az));
  return perspectiveCamera(mn, mx, towardsEye, Vector3d(std::sin(az), 0, -std::cos(az)), orbit.distance, aspect);
}

Vector3f background(double y) {  // y in [0,1] from the top
  const Vector3f top(0.80f, 0.84f, 0.90f), bottom(0.55f, 0.58f, 0.63f);
  return top + float(y) * (bottom - top);
}

// One Embree scene holding the mesh; released with the object.
class RayScene {
 public:
  explicit RayScene(const Mesh& mesh) {
    device_ = rtcNewDevice(nullptr);
    scene_ = rtcNewScene(device_);
    // Robust traversal: no rays slipping through the shared edges of adjacent triangles.
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    // Embree-allocated buffers carry the padding its SIMD loads need past the last vertex.
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), mesh.vertexCount()));
    std::memcpy(v, mesh.positions.data(), mesh.positions.size() * sizeof(float));
    auto* i = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                             3 * sizeof(uint32_t), mesh.triangleCount()));
    std::memcpy(i, mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t));
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene_, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(scene_);
  }
  ~RayScene() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  bool intersect(const Vector3d& org, const Vector3d& dir, RTCHit& hit) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRayHit rh{};
    rh.ray.org_x = float(org.x()), rh.ray.org_y = float(org.y()), rh.ray.org_z = float(org.z());
    rh.ray.dir_x = float(dir.x()), rh.ray.dir_y = float(dir.y()), rh.ray.dir_z = float(dir.z());
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = INFINITY;
    rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &ctx, &rh);
    hit = rh.hit;
    return rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
  }

 private:
  RTCDevice device_;
  RTCScene scene_;
};

using texture::ColorTexture;

// Mesh::textures loaded, one per entry; one that failed to load stays empty, and its
// triangles show their vertex colours alone. Each failure's message is added to `warning`.
std::vector<ColorTexture> loadTextures(const Mesh& mesh, std::string* warning) {
  std::vector<ColorTexture> textures(mesh.empty() ? 0 : mesh.textures.size());
  for (size_t t = 0; t < textures.size(); ++t) {
    std::string error;
    if (textures[t].load(mesh.textures[t], error) || !warning) continue;
    if (!warning->empty()) *warning += "; ";
    *warning += "a texture cannot be loaded, so the preview shows its triangles in their vertex colours: " +
                error;
  }
  return textures;
}

// The loaded texture triangle `primID` is painted with, or nullptr when none (untextured,
// no texture coordinates, or an image that failed to load).
const ColorTexture* textureOf(const Mesh& mesh, const std::vector<ColorTexture>& textures, uint32_t primID) {
  if (!mesh.textured() || !mesh.hasTexcoords()) return nullptr;
  const auto& runs = mesh.textureRuns;
  const auto startsAfter = [](uint32_t triangle, const TextureRun& r) { return triangle < r.firstTriangle; };
  const auto run = std::upper_bound(runs.begin(), runs.end(), primID, startsAfter);
  if (run == runs.begin()) return nullptr;  // before the first run: only a malformed mesh
  const int32_t t = std::prev(run)->texture;
  return t >= 0 && size_t(t) < textures.size() && !textures[t].empty() ? &textures[t] : nullptr;
}

// Lambert with ambient: a headlight so nothing the camera sees is black, and a key light
// from the upper left so faces of different orientation read apart. A textured triangle's
// albedo is the image times the vertex colours, as glTF's baseColorTexture x COLOR_0.
Vector3f shade(const Mesh& mesh, const std::vector<ColorTexture>& textures, const Camera& cam,
               const RTCHit& hit, const Vector3d& dir) {
  const uint32_t* tri = &mesh.indices[3 * size_t(hit.primID)];
  const double w[3] = {1.0 - hit.u - hit.v, hit.u, hit.v};
  Vector3d n = Vector3d::Zero();
  Vector3f albedo = Vector3f::Zero();
  const bool colored = mesh.colors.size() == mesh.positions.size();
  const bool smooth = mesh.normals.size() == mesh.positions.size();
  for (int k = 0; k < 3; ++k) {
    const size_t v = 3 * size_t(tri[k]);
    if (smooth) n += w[k] * Vector3d(mesh.normals[v], mesh.normals[v + 1], mesh.normals[v + 2]);
    albedo += float(w[k]) * (colored ? Vector3f(mesh.colors[v], mesh.colors[v + 1], mesh.colors[v + 2])
                                     : kDefaultColor);
  }
  if (const ColorTexture* image = textureOf(mesh, textures, hit.primID)) {
    double u = 0, v = 0;
    for (int k = 0; k < 3; ++k) {
      u += w[k] * mesh.texcoords[2 * size_t(tri[k])];
      v += w[k] * mesh.texcoords[2 * size_t(tri[k]) + 1];
    }
    const auto texel = image->sample(u, v);
    albedo = albedo.cwiseProduct(Vector3f(texel[0], texel[1], texel[2]));
  }
  if (!(n.norm() > 1e-12)) n = Vector3d(hit.Ng_x, hit.Ng_y, hit.Ng_z);
  n.normalize();
  if (n.dot(dir) > 0) n = -n;  // two-sided: light the face the camera sees
  const Vector3d key = (-0.45 * cam.right + 0.75 * cam.up - 0.5 * cam.forward).normalized();
  const double light = 0.22 + 0.38 * std::max(0.0, -n.dot(dir)) + 0.5 * std::max(0.0, n.dot(key));
  return (albedo.cwiseMax(0.0f).cwiseMin(1.0f) * float(light)).cwiseMin(1.0f);
}

uint8_t toByte(float c) { return uint8_t(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f)); }

// renderImage with the mesh's textures loaded already, so stagePreview can report those
// that fail.
// Where the camera sees world point p, in pixels (x right, y down); false behind it.
bool project(const Camera& cam, const Vector3d& p, const Image& img, double& x, double& y) {
  const Vector3d d = p - cam.eye;
  const double depth = cam.orthographic ? 1.0 : d.dot(cam.forward);
  if (!(depth > 1e-9)) return false;
  const double sx = d.dot(cam.right) / (depth * cam.halfWidth), sy = d.dot(cam.up) / (depth * cam.halfHeight);
  x = 0.5 * (sx + 1) * img.width;
  y = 0.5 * (1 - sy) * img.height;
  return std::isfinite(x) && std::isfinite(y);
}

// The mesh's line segments, one pixel wide in their first vertex's colour, over the
// rendered triangles (rays cannot hit a line).
void drawLines(const Mesh& mesh, const Camera& cam, Image& img) {
  const auto vertex = [&](uint32_t v) {
    return Vector3d(mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]);
  };
  for (size_t l = 0; l < mesh.lineCount(); ++l) {
    const uint32_t a = mesh.lines[2 * l], b = mesh.lines[2 * l + 1];
    double x0, y0, x1, y1;
    if (!project(cam, vertex(a), img, x0, y0) || !project(cam, vertex(b), img, x1, y1)) continue;
    uint8_t rgb[3] = {60, 60, 60};
    if (mesh.colors.size() == mesh.positions.size())
      for (int c = 0; c < 3; ++c) rgb[c] = toByte(mesh.colors[3 * a + c]);
    // Steps of at most a pixel, clipped to the image (a few thousand pixels at most).
    const double span = std::min(std::max(std::abs(x1 - x0), std::abs(y1 - y0)), 4.0 * (img.width + img.height));
    const int steps = std::max(1, int(std::ceil(span)));
    for (int k = 0; k <= steps; ++k) {
      const double t = double(k) / steps;
      const int px = int(std::floor(x0 + t * (x1 - x0))), py = int(std::floor(y0 + t * (y1 - y0)));
      if (px < 0 || py < 0 || px >= img.width || py >= img.height) continue;
      std::copy(rgb, rgb + 3, &img.rgb[3 * (size_t(py) * img.width + px)]);
    }
  }
}

Image render(const Mesh& mesh, const std::vector<ColorTexture>& textures, const PreviewOptions& options) {
  Image img;
  img.width = std::max(options.width, 1);
  img.height = std::max(options.height, 1);
  img.rgb.resize(size_t(img.width) * img.height * 3);
  const int spa = std::max(options.samplesPerAxis, 1);
  const double aspect = double(img.width) / img.height;
  const Camera cam = options.camera.fit ? fitCamera(mesh, aspect) : orbitCamera(mesh, options.camera, aspect);
  std::unique_ptr<RayScene> scene;
  if (mesh.triangleCount() > 0) scene = std::make_unique<RayScene>(mesh);
  // Every pixel depends only on its own rays, so rows can be rendered in any order.
  tbb::parallel_for(tbb::blocked_range<int>(0, img.height), [&](const tbb::blocked_range<int>& rows) {
    for (int py = rows.begin(); py != rows.end(); ++py) {
      for (int px = 0; px < img.width; ++px) {
        Vector3f sum = Vector3f::Zero();
        for (int sy = 0; sy < spa; ++sy) {
          for (int sx = 0; sx < spa; ++sx) {
            const double x = (px + (sx + 0.5) / spa) / img.width;
            const double y = (py + (sy + 0.5) / spa) / img.height;
            Vector3d org, dir;
            cam.ray(x, y, org, dir);
            RTCHit hit;
            sum += scene && scene->intersect(org, dir, hit) ? shade(mesh, textures, cam, hit, dir)
                                                            : background(y);
          }
        }
        sum /= float(spa * spa);
        uint8_t* out = &img.rgb[3 * (size_t(py) * img.width + px)];
        for (int c = 0; c < 3; ++c) out[c] = toByte(sum[c]);
      }
    }
  });
  drawLines(mesh, cam, img);
  return img;
}

}  // namespace

bool checkPreviewCamera(const PreviewCamera& camera, std::string& error) {
  if (camera.fit) return true;
  const auto text = [](double v) {
    char number[32];
    std::snprintf(number, sizeof number, "%.10g", v);
    return std::isfinite(v) ? std::string(number) : std::string(std::isnan(v) ? "not a number" : "infinite");
  };
  if (!std::isfinite(camera.azimuthDegrees)) {
    error = "the camera's azimuth is " + text(camera.azimuthDegrees) + ", not a finite angle";
    return false;
  }
  if (!(camera.elevationDegrees >= -90 && camera.elevationDegrees <= 90)) {
    error = "the camera's elevation is " + text(camera.elevationDegrees) + ", not between -90 and 90 degrees";
    return false;
  }
  if (!(camera.distance >= 0 && std::isfinite(camera.distance))) {
    error = "the camera's distance is " + text(camera.distance) + ", not a positive number of scene units";
    return false;
  }
  return true;
}

Image renderImage(const Mesh& mesh, const PreviewOptions& options) {
  return render(mesh, loadTextures(mesh, nullptr), options);
}

bool renderPreview(const Mesh& mesh, const PreviewOptions& options, const std::string& pngPath,
                   std::string& error, std::string* warning) {
  io::OutputTransaction one;
  return stagePreview(mesh, options, pngPath, one, error, warning) && one.commit(error);
}

bool stagePreview(const Mesh& mesh, const PreviewOptions& options, const std::string& pngPath,
                  io::OutputTransaction& outputs, std::string& error, std::string* warning) {
  if (options.width <= 0 || options.height <= 0 || options.width > 16384 || options.height > 16384) {
    error = "preview size " + std::to_string(options.width) + "x" + std::to_string(options.height) +
            " is out of range (1..16384)";
    return false;
  }
  if (std::string why; !checkPreviewCamera(options.camera, why)) {
    error = "cannot write '" + pngPath + "': " + why;
    return false;
  }
  if (mesh.empty() && warning) *warning = "the mesh is empty: the preview shows only the background";
  std::string png;
  try {
    const Image img = render(mesh, loadTextures(mesh, warning), options);
    if (!io::encodePng(img.width, img.height, 3, img.rgb.data(), png)) {
      error = "cannot write '" + pngPath + "': cannot encode the preview as PNG";
      return false;
    }
  } catch (const std::bad_alloc&) {
    error = "cannot write '" + pngPath + "': out of memory while rendering the preview";
    return false;
  }
  return outputs.stage(pngPath, png, error);
}

}  // namespace fgsg::rt::render
