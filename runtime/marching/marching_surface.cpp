#include "runtime/marching/marching_surface_impl.h"

#include <chrono>
#include <cmath>

namespace fgsg::rt::marching {

namespace {

// Landings closer than this fraction of the surface's size are the exit point itself.
constexpr double kLandingTolerance = 1e-9;

}  // namespace

MarchingSurface::MarchingSurface() : impl_(std::make_unique<Impl>()) {}
MarchingSurface::~MarchingSurface() = default;

std::shared_ptr<const MarchingSurface> MarchingSurface::fromAtlas(const surface::SurfaceMesh& mesh,
                                                                  const atlas::Atlas& atlas,
                                                                  const MarchingOptions& options, std::string& error,
                                                                  PrepareStats* stats) {
  const auto started = std::chrono::steady_clock::now();
  std::shared_ptr<MarchingSurface> s(new MarchingSurface());
  Impl& impl = *s->impl_;
  if (!buildImageTriangles(mesh, atlas, impl.triangles, error)) return nullptr;
  impl.mesh = mesh;
  impl.atlas = atlas;
  impl.options = options;
  impl.landingTolerance = kLandingTolerance * (mesh.boundsMax - mesh.boundsMin).norm();
  impl.image = GeometryImage::build(impl.mesh, impl.triangles, atlas.resolution);
  if (stats) {
    stats->charts = atlas.chartCount;
    stats->imageSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  }
  return s;
}

std::shared_ptr<const MarchingSurface> MarchingSurface::fromStoredImage(const surface::SurfaceMesh& mesh,
                                                                        const atlas::Atlas& atlas,
                                                                        ImageTexels&& texels,
                                                                        const MarchingOptions& options,
                                                                        std::string& error) {
  std::shared_ptr<MarchingSurface> s(new MarchingSurface());
  Impl& impl = *s->impl_;
  if (!buildImageTriangles(mesh, atlas, impl.triangles, error)) return nullptr;
  if (texels.size != atlas.resolution) {
    error = "the stored image has " + std::to_string(texels.size) + " texels per side, the atlas " +
            std::to_string(atlas.resolution);
    return nullptr;
  }
  impl.mesh = mesh;
  impl.atlas = atlas;
  impl.options = options;
  impl.landingTolerance = kLandingTolerance * (mesh.boundsMax - mesh.boundsMin).norm();
  if (!GeometryImage::restore(impl.mesh, impl.triangles, std::move(texels), impl.image, error)) return nullptr;
  return s;
}

MarchPoint MarchingSurface::place(const surface::SurfacePoint& p, const Vec3& dir3) const {
  const Impl& s = *impl_;
  MarchPoint m;
  if (p.face < 0 || p.face >= int(s.triangles.size())) return m;
  const ImageTriangle& t = s.triangles[p.face];
  const Vec3 n = s.mesh.faceNormals[p.face];
  Vec3 tangent = dir3 - dir3.dot(n) * n;
  if (!(tangent.norm() > 1e-12 * dir3.norm()) || !tangent.allFinite()) {
    const auto& v = s.mesh.faces[p.face];
    tangent = s.mesh.vertices[v[1]] - s.mesh.vertices[v[0]];
  }
  m.at.face = p.face;
  m.at.bary = tidyBary(p.bary);
  m.image = t.imagePoint(m.at.bary);
  m.chart = t.chart;
  m.dir = (t.toImage * tangent).normalized();
  return m;
}

surface::SurfacePoint MarchingSurface::texelPoint(int texel) const {
  const Impl& s = *impl_;
  surface::SurfacePoint p;
  const int n = s.image.size();
  if (texel < 0 || texel >= n * n || s.image.face(texel) < 0) return p;
  p.face = s.image.face(texel);
  p.bary = s.triangles[p.face].closestBary(Vec2(texel % n + 0.5, texel / n + 0.5));
  return p;
}

bool MarchingSurface::locate(const Vec2& image, const Vec2& dir, MarchPoint& out) const {
  const Impl& s = *impl_;
  const int n = s.image.size();
  if (!image.allFinite() || image.minCoeff() < 0 || image.maxCoeff() > n) return false;
  const surface::SurfacePoint start = texelPoint(s.image.texelAt(image));
  if (!start.valid()) return false;
  ChartPoint p{start.face, start.bary};
  const bool inside = walkTo(s.mesh, s.triangles, p, image);
  const ImageTriangle& t = s.triangles[p.face];
  out.at.face = p.face;
  out.at.bary = p.bary;
  out.image = t.imagePoint(p.bary);
  out.chart = t.chart;
  out.dir = dir.norm() > 0 && dir.allFinite() ? Vec2(dir.normalized()) : Vec2(1, 0);
  return inside;
}

Vec3 MarchingSurface::position(const MarchPoint& p) const { return p.at.position(impl_->mesh); }

Vec3 MarchingSurface::normal(const MarchPoint& p) const { return p.at.normal(impl_->mesh); }

Vec3 MarchingSurface::direction(const MarchPoint& p) const {
  return (impl_->triangles[p.at.face].toSurface * p.dir).normalized();
}

Vec2 MarchingSurface::texCoord(const surface::SurfacePoint& p) const {
  const Impl& s = *impl_;
  const auto& uv = s.mesh.textureUV.size() == s.mesh.faceCount() ? s.mesh.textureUV[p.face] : s.atlas.cornerUV[p.face];
  return p.bary[0] * uv[0] + p.bary[1] * uv[1] + p.bary[2] * uv[2];
}

const surface::SurfaceMesh& MarchingSurface::mesh() const { return impl_->mesh; }
const atlas::Atlas& MarchingSurface::atlas() const { return impl_->atlas; }
const GeometryImage& MarchingSurface::image() const { return impl_->image; }
const MarchingOptions& MarchingSurface::options() const { return impl_->options; }

}  // namespace fgsg::rt::marching
