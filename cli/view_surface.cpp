#include "cli/view_surface.h"

#include "backend/commands/surface_geometry.h"
#include "backend/interp/eval.h"
#include "runtime/surface/surface_mesh.h"
#include "runtime/io/write_mesh.h"

namespace fgsg::cli {

bool buildViewSurface(const ir::Module& module, const rt::DeriveOptions& options,
                      const std::vector<std::string>& searchDirs, ViewSurface& out, std::string& error,
                      backend::SurfaceGeometryCache* geometries, const ViewSurface* previous) {
  out = ViewSurface{};
  if (!module.surface.present && options.surfaceOverride.empty()) return true;
  // Only the mesh is shown: the fields are not built.
  std::shared_ptr<const backend::SurfaceGeometry> geometry;
  try {
    geometry = geometries ? geometries->obtain(module.surface, options, searchDirs)
                          : backend::SurfaceGeometry::build(module.surface, options, searchDirs);
  } catch (const backend::DeriveError& e) {
    error = e.message;
    return false;
  }
  const rt::surface::SurfaceMesh& mesh = geometry->mesh();
  bool textured = false;
  for (const ir::EnvDecl& env : module.environment) textured = textured || env.kind == "texture";
  if (previous && previous->geometry == geometry && previous->textured == textured &&
      previous->atlasResolution == options.atlasResolution && previous->atlasCacheDir == options.atlasCacheDir) {
    out = *previous;
    return true;
  }
  out.geometry = geometry;
  out.textured = textured;
  out.atlasResolution = options.atlasResolution;
  out.atlasCacheDir = options.atlasCacheDir;
  if (textured) {
    rt::marching::MarchingOptions layout;
    layout.resolution = options.atlasResolution;
    layout.cacheDir = options.atlasCacheDir;
    out.marching = rt::marching::MarchingSurface::prepare(mesh, layout, error);
    if (!out.marching) return false;
  }
  // Corners unshared, so that each keeps its own chart's UV across seams.
  rt::Mesh m;
  const size_t n = mesh.faceCount();
  m.positions.resize(9 * n);
  m.normals.resize(9 * n);
  m.indices.resize(3 * n);
  if (out.marching) m.texcoords.resize(6 * n);
  for (size_t f = 0; f < n; ++f)
    for (int k = 0; k < 3; ++k) {
      const size_t c = 3 * f + k;
      const int v = mesh.faces[f][k];
      for (int a = 0; a < 3; ++a) {
        m.positions[3 * c + a] = static_cast<float>(mesh.vertices[v][a]);
        m.normals[3 * c + a] = static_cast<float>(mesh.vertexNormals[v][a]);
      }
      m.indices[c] = static_cast<uint32_t>(c);
      if (out.marching) {
        rt::Vec3 corner = rt::Vec3::Zero();
        corner[k] = 1;
        const auto uv = out.marching->texCoord({static_cast<int>(f), corner});
        m.texcoords[2 * c] = static_cast<float>(uv.x());
        m.texcoords[2 * c + 1] = static_cast<float>(uv.y());
      }
    }
  out.triangles = n;
  return rt::io::encodeMesh(m, ".glb", out.glb, error);
}

}  // namespace fgsg::cli
