// The surface as on-mesh marching sees it (Buron et al. §4-5): the mesh, its atlas and
// the indirection geometry image built from it. The engine's Marching command places a
// scope into it, marches, and reads the destination back as a surface point; texture
// contexts are sampled at texCoord(). Read-only once prepared, so seeds march from many
// threads at once.
#pragma once

#include "runtime/atlas/atlas.h"
#include "runtime/surface/surface_mesh.h"

#include <memory>
#include <string>

namespace fgsg::rt::marching {

using atlas::Vec2;
class GeometryImage;

// Where a march stands: the exact surface point, its place in the geometry image and
// the marching direction there.
struct MarchPoint {
  surface::SurfacePoint at;  // face and barycentric coordinates on the mesh
  Vec2 image = Vec2::Zero();  // position in the geometry image, in texels (x right, y up)
  int chart = -1;
  Vec2 dir = Vec2(1, 0);  // unit marching direction in the image
};

// How Marching's length is measured: along the surface (the 3D distance between
// consecutive samples; the default) or in texels of the geometry image (the paper's).
enum class LengthUnit { Surface, Image };

struct MarchingOptions {
  int resolution = 1024;      // geometry image side, texels
  std::string cacheDir;       // where prepared surfaces are kept ("" : no cache)
};

// What prepare() did, for progress lines and the benchmark.
struct PrepareStats {
  bool fromCache = false;
  bool meshUV = false;   // the mesh's own texture coordinates were used
  int charts = 0;
  double atlasSeconds = 0, imageSeconds = 0;
};

class MarchingSurface {
 public:
  // Builds the atlas (the mesh's own UVs when it has them, else a generated one) and the
  // geometry image, or reads both from options.cacheDir when the mesh and options are
  // the same. Null with a message on failure (e.g. overlapping UVs).
  static std::shared_ptr<const MarchingSurface> prepare(const surface::SurfaceMesh& mesh,
                                                        const MarchingOptions& options,
                                                        std::string& error, PrepareStats* stats = nullptr);
  ~MarchingSurface();

  // The march point at surface point p heading along dir3 (projected into the tangent
  // plane; any non-tangent vector works).
  MarchPoint place(const surface::SurfacePoint& p, const Vec3& dir3) const;
  // Marches `length` from `from` along from.dir (the four cases of §5, jumps through
  // indirection texels with the direction turned as §5.2). True when the full length
  // was marched; false when the surface's own boundary (an open mesh) stopped it first —
  // `to` then holds the last point reached. Never leaves the atlas, never loops.
  bool march(const MarchPoint& from, double length, LengthUnit unit, MarchPoint& to) const;

  Vec3 position(const MarchPoint& p) const;
  Vec3 normal(const MarchPoint& p) const;    // smooth, unit
  Vec3 direction(const MarchPoint& p) const; // p.dir as a unit 3D tangent
  // The texture coordinate textures are sampled with: the mesh's own UVs when it has
  // them, else the generated atlas's (u right, v up, in [0,1]).
  Vec2 texCoord(const surface::SurfacePoint& p) const;

  const surface::SurfaceMesh& mesh() const;
  const atlas::Atlas& atlas() const;
  const GeometryImage& image() const;

 private:
  MarchingSurface();
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fgsg::rt::marching
