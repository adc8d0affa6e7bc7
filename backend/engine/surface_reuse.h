// A surface kept from one derivation for the next (#49): fgsg view derives the same
// compiled grammar with the same values again whenever a page moves a seed or paints a
// texture, and loading the surface, designing its fields and laying it out for marching
// took most of each such derivation (a second for the bunny). While a SurfaceReuseScope
// is alive on a thread, the derivations begun there take the surface from its
// SurfaceReuse (built and left there by the first). The caller starts a fresh one whenever
// anything the surface depends on may have changed: the grammar, its attributes, its seed.
// Seeds derived apart (seed_plants.cpp) are kept here too: a plant whose seed, random key
// and texels read are unchanged is taken as it was rather than derived again (#49, item 5).
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace fgsg::rt::marching {
class MarchingSurface;
}

namespace fgsg::backend {

class SurfaceWorld;
class SurfaceGeometryCache;
struct SeedPlantCache;  // seed_plants.cpp

struct SurfaceReuse {
  std::mutex mutex;
  std::shared_ptr<const SurfaceWorld> world;
  std::shared_ptr<const rt::marching::MarchingSurface> marching;
  // Outlives this reuse (fgsg view keeps it across recompiles): a world built afresh takes
  // its mesh, frames and factorisation from here when they are the same (surface_geometry.h).
  SurfaceGeometryCache* geometries = nullptr;
  // The last derivation's seed plants, with what each read (made by the first derivation
  // that grows seeds apart), and per seed of the last derivation whether its plant was
  // taken from here (1) or derived (0).
  std::shared_ptr<SeedPlantCache> plants;
  std::vector<uint8_t> plantsReused;
};

class SurfaceReuseScope {
 public:
  explicit SurfaceReuseScope(SurfaceReuse& reuse);
  ~SurfaceReuseScope();
  SurfaceReuseScope(const SurfaceReuseScope&) = delete;
  SurfaceReuseScope& operator=(const SurfaceReuseScope&) = delete;
  // The reuse in effect on this thread, or null.
  static SurfaceReuse* current();

 private:
  SurfaceReuse* previous_;
};

}  // namespace fgsg::backend
