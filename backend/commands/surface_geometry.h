// The part of a grammar's surface that no field depends on (#49): the mesh as loaded or
// generated (and fitted by --surface-size), its closest-point locator, its tangent frames
// and, built on first use, the heat method's factorised operators that field design
// solves with. It depends only on the surface's source and the load options, so fgsg view
// keeps it across recompiles (SurfaceGeometryCache): a design element dragged in the page
// redesigns the field on the same geometry instead of loading and factorising the mesh
// again (about a second for a 26 K-vertex mesh). Read-only once built; its members may be
// used from several threads.
#pragma once

#include "ir/ir.h"
#include "runtime/deadline.h"
#include "runtime/derivation.h"

#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace fgsg::rt::field {
class HeatGeodesics;
class TangentFrames;
}  // namespace fgsg::rt::field
namespace fgsg::rt::surface {
struct SurfaceMesh;
class SurfaceLocator;
}  // namespace fgsg::rt::surface

namespace fgsg::backend {

class SurfaceGeometry {
 public:
  // The module's surface (`spec`) or --surface's, files looked up in `searchDirs`;
  // `deadline` bounds a procedural generator. Throws DeriveError at the declaration.
  static std::shared_ptr<const SurfaceGeometry> build(const ir::SurfaceSpec& spec, const rt::DeriveOptions& options,
                                                      const std::vector<std::string>& searchDirs,
                                                      rt::Deadline* deadline = nullptr);
  ~SurfaceGeometry();
  SurfaceGeometry(const SurfaceGeometry&) = delete;
  SurfaceGeometry& operator=(const SurfaceGeometry&) = delete;

  const rt::surface::SurfaceMesh& mesh() const { return *mesh_; }
  const rt::surface::SurfaceLocator& locator() const { return *locator_; }
  const std::shared_ptr<const rt::field::TangentFrames>& frames() const { return frames_; }
  // The heat method's operators on this mesh, factorised by the first caller (once,
  // whichever thread asks first); check ok() on them.
  std::shared_ptr<const rt::field::HeatGeodesics> heatGeodesics() const;

 private:
  SurfaceGeometry() = default;
  std::unique_ptr<rt::surface::SurfaceMesh> mesh_;
  std::unique_ptr<rt::surface::SurfaceLocator> locator_;
  std::shared_ptr<const rt::field::TangentFrames> frames_;
  mutable std::once_flag heatBuilt_;
  mutable std::shared_ptr<const rt::field::HeatGeodesics> heat_;
};

// fgsg view's geometries, kept across recompiles. A geometry is taken again only when
// everything it was built from is the same: a mesh file's absolute path, size,
// modification time and content (hashed), or a procedural surface's generator and
// arguments, and the options that change the mesh (--surface-size, --repair-surface,
// --max-memory). A .gltf (whose buffers are other files) is always loaded afresh.
class SurfaceGeometryCache {
 public:
  std::shared_ptr<const SurfaceGeometry> obtain(const ir::SurfaceSpec& spec, const rt::DeriveOptions& options,
                                                const std::vector<std::string>& searchDirs,
                                                rt::Deadline* deadline = nullptr);
  // How many geometries were built (not taken from the cache) so far.
  size_t builds() const;

 private:
  static constexpr size_t kKept = 4;  // the most recently used ones
  mutable std::mutex mutex_;
  std::vector<std::pair<std::string, std::shared_ptr<const SurfaceGeometry>>> kept_;  // last: newest
  size_t builds_ = 0;
};

}  // namespace fgsg::backend
