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
struct ImageTexels;

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

// How a march ended: the first arrives (true), the others return false.
enum class MarchEnd {
  Arrived,
  Boundary,     // the surface's own boundary (an open mesh)
  PathTooLong,  // a surface length the path did not reach within 8 x its length
  NoProgress,   // 4096 crossings in a row without moving
  FaceLimit,    // 2^22 faces crossed
  Refused,      // an invalid start, a zero direction or a non-finite length
};

// What one march did (tests and benchmarks look; the engine passes none).
struct MarchTrace {
  MarchEnd end = MarchEnd::Arrived;
  int pieces = 0;          // straight pieces, one per face crossed
  int pointerJumps = 0;    // chart changes through an indirection pointer (§5)
  // Chart changes where no pointer around the exit landed on the exit point and the
  // mesh's own neighbour across the seam was taken instead (0 on a sound atlas).
  int adjacencyJumps = 0;
  bool coarse = false;     // an image-length march settled on the coarse levels at once
};

class MarchingSurface {
 public:
  // Builds the atlas (the mesh's own UVs when it has them, else a generated one) and the
  // geometry image, or reads both from options.cacheDir when the mesh and options are
  // the same. Null with a message on failure (e.g. overlapping UVs).
  static std::shared_ptr<const MarchingSurface> prepare(const surface::SurfaceMesh& mesh,
                                                        const MarchingOptions& options,
                                                        std::string& error, PrepareStats* stats = nullptr);
  // The surface over an atlas already built for `mesh` (its topology built): the
  // geometry image is rasterized at atlas.resolution texels per side (the gutters were
  // packed for it; options.resolution is not consulted). Keeps its own copies of the
  // mesh and the atlas. Null with a message when the atlas does not fit the mesh.
  // `stats`, when given, receives imageSeconds and charts.
  static std::shared_ptr<const MarchingSurface> fromAtlas(const surface::SurfaceMesh& mesh,
                                                          const atlas::Atlas& atlas,
                                                          const MarchingOptions& options, std::string& error,
                                                          PrepareStats* stats = nullptr);
  // The surface over an atlas and a geometry image read back from the disk cache
  // (image_cache.h): null with a message unless both are consistent with the mesh.
  static std::shared_ptr<const MarchingSurface> fromStoredImage(const surface::SurfaceMesh& mesh,
                                                                const atlas::Atlas& atlas, ImageTexels&& texels,
                                                                const MarchingOptions& options,
                                                                std::string& error);
  ~MarchingSurface();

  // The march point at surface point p heading along dir3 (projected into the face's
  // plane; any non-tangent vector works; one along the normal heads along the face's
  // first edge).
  MarchPoint place(const surface::SurfacePoint& p, const Vec3& dir3) const;
  // Marches `length` from `from` along from.dir (the four cases of §5, jumps through
  // indirection texels with the direction turned as §5.2). True when the full length
  // was marched; false when the surface's own boundary (an open mesh) stopped it first —
  // `to` then holds the last point reached. Never leaves the atlas, never loops.
  //
  // The march is a straight line in each chart's image (as the paper's), followed face
  // by face, so every point is exact: `to.at` is on the mesh up to rounding, whatever
  // the resolution. Where the line leaves its chart, the indirection pointers around
  // the exit (best first by §5.1's criterion) say where it continues; the landing is
  // the exact seam point in the target chart (searched from the pointer's texel), and
  // the direction keeps its angle with the seam edge, unfolded about it (§5.2, with the
  // mesh's exact edge as the tangent). `from.at` and `from.dir` define the start;
  // from.image and from.chart are recomputed from them.
  //
  // LengthUnit::Surface: `to` is the first point along the path whose straight 3D
  // distance from the start is `length` (to rounding, about 1e-16 of the coordinates).
  // False also when the path grows 8 x `length` long without getting that far (a
  // length larger than the surface allows). LengthUnit::Image: `length` texels of image
  // path (jumps cost nothing). A length <= 0 stays at `from` (true); a non-finite one, an
  // invalid start or a zero direction is refused (false, `to` = `from`). Every march
  // ends within 2^22 faces crossed (false past that) and never spins on the spot: 4096
  // crossings without progress end it (false).
  bool march(const MarchPoint& from, double length, LengthUnit unit, MarchPoint& to) const;
  bool march(const MarchPoint& from, double length, LengthUnit unit, MarchPoint& to, MarchTrace* trace) const;

  // The march point at image position `image` (texels) heading along image direction
  // `dir`: the exact surface point there, found from the covering texel's face by a walk
  // in its chart. False when no chart covers the position (a background or indirection
  // texel, or a conservative texel's part outside its chart: `out` is then the chart's
  // border point on the way, or left as it was when there is no chart at all).
  bool locate(const Vec2& image, const Vec2& dir, MarchPoint& out) const;
  // The surface point of an inner texel (the closest point of its face to the texel's
  // centre); invalid (face -1) for other texels.
  surface::SurfacePoint texelPoint(int texel) const;

  Vec3 position(const MarchPoint& p) const;
  Vec3 normal(const MarchPoint& p) const;    // smooth, unit
  Vec3 direction(const MarchPoint& p) const; // p.dir as a unit 3D tangent
  // The texture coordinate textures are sampled with: the mesh's own UVs when it has
  // them, else the generated atlas's (u right, v up, in [0,1]).
  Vec2 texCoord(const surface::SurfacePoint& p) const;

  const surface::SurfaceMesh& mesh() const;
  const atlas::Atlas& atlas() const;
  const GeometryImage& image() const;
  const MarchingOptions& options() const;

  struct Impl;  // marching_surface_impl.h, for this folder's files only

 private:
  MarchingSurface();
  std::unique_ptr<Impl> impl_;
};

}  // namespace fgsg::rt::marching
