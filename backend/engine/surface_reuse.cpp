#include "backend/engine/surface_reuse.h"

namespace fgsg::backend {

namespace {
thread_local SurfaceReuse* currentReuse = nullptr;
}

SurfaceReuseScope::SurfaceReuseScope(SurfaceReuse& reuse) : previous_(currentReuse) { currentReuse = &reuse; }
SurfaceReuseScope::~SurfaceReuseScope() { currentReuse = previous_; }
SurfaceReuse* SurfaceReuseScope::current() { return currentReuse; }

}  // namespace fgsg::backend
