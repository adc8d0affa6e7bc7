#include "runtime/output/time_budget.h"

#include "runtime/assemble.h"

namespace fgsg::rt::output {

namespace {

// The mesh an instance draws, or nullptr when its asset is not bound (drawing nothing).
const Mesh* budgetedMesh(const Instance& inst, const InstanceList& list, const AssetLibrary& library,
                         const std::vector<int>& meshOf) {
  if (inst.geometry != UINT32_MAX) return inst.geometry < list.geometries.size() ? &list.geometries[inst.geometry] : nullptr;
  if (inst.asset >= meshOf.size() || meshOf[inst.asset] < 0) return nullptr;
  return &library.mesh(meshOf[inst.asset]);
}

}  // namespace

size_t instancesWithinTime(const InstanceList& list, const AssetLibrary& library, const std::vector<int>& meshOf,
                           const Deadline& deadline, double writeSecondsPerTriangle) {
  const size_t n = list.instances.size();
  if (!deadline.limited()) return n;
  size_t begin = 0, triangles = 0;
  // The assembly's test before each block (runtime/assemble.cpp), on the triangles taken.
  const auto timeLeft = [&] {
    if (deadline.passed()) return false;
    return !(writeSecondsPerTriangle > 0) || deadline.remainingSeconds() > writeSecondsPerTriangle * double(triangles);
  };
  while (begin < n && timeLeft()) {
    size_t work = 0;
    while (begin < n && work < kAssemblyBlockTriangles) {  // the assembly's blocks
      const Mesh* m = budgetedMesh(list.instances[begin++], list, library, meshOf);
      work += 1 + (m ? m->triangleCount() + m->lineCount() : 0);
      triangles += m ? m->triangleCount() : 0;
    }
  }
  return begin;
}

}  // namespace fgsg::rt::output
