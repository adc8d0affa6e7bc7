// The surface a grammar grows on, as fgsg view's page needs it to click seeds and paint
// textures on it (#49): the mesh in world space (after --surface-size), each corner
// carrying the texture coordinate texture contexts are sampled with
// (MarchingSurface::texCoord: the mesh's own UVs, else the generated atlas's), so a brush
// laid on the page's mesh lands on the texels the derivation reads.
#pragma once

#include "ir/ir.h"
#include "runtime/derivation.h"
#include "runtime/marching/marching_surface.h"

#include <memory>
#include <string>
#include <vector>

namespace fgsg::backend {
class SurfaceGeometry;
class SurfaceGeometryCache;
}  // namespace fgsg::backend

namespace fgsg::cli {

struct ViewSurface {
  // Laid out for texture lookups; null when the grammar declares no texture.
  std::shared_ptr<const rt::marching::MarchingSurface> marching;
  std::string glb;     // the mesh, three vertices per triangle, UVs when `marching` is set
  size_t triangles = 0;
  // What it was built from (#49): a compile of the grammar on the same geometry with the
  // same layout takes it as it is (a field edit recompiles, the surface stays).
  std::shared_ptr<const backend::SurfaceGeometry> geometry;
  bool textured = false;
  int atlasResolution = 0;
  std::string atlasCacheDir;
};

// Builds the surface of `module` (its own or options.surfaceOverride) as a derivation
// would. False with a message; a grammar without a surface gives true and an empty glb.
// `geometries`: the mesh taken from there when it is the same (null: loaded here);
// `previous`: the last result, taken again when built from the same.
bool buildViewSurface(const ir::Module& module, const rt::DeriveOptions& options,
                      const std::vector<std::string>& searchDirs, ViewSurface& out, std::string& error,
                      backend::SurfaceGeometryCache* geometries = nullptr, const ViewSurface* previous = nullptr);

}  // namespace fgsg::cli
