#include "runtime/output/time_budget.h"

#include "runtime/assemble.h"

namespace fgsg::rt::output {

size_t instancesWithinTime(const InstanceList& list, const AssetLibrary& library, const std::vector<int>& meshOf,
                           const Deadline& deadline, double writeSecondsPerTriangle) {
  const size_t n = list.instances.size();
  if (!deadline.limited()) return n;
  size_t begin = 0, triangles = 0;
  // The assembly's test before each block, on the triangles taken.
  while (begin < n && assemblyBlockMayStart(deadline, writeSecondsPerTriangle, triangles)) {
    size_t work = 0;
    while (begin < n && work < kAssemblyBlockTriangles) {  // the assembly's blocks
      const Mesh* m = instanceMesh(list.instances[begin++], list, library, meshOf);
      work += 1 + (m ? m->triangleCount() + m->lineCount() : 0);
      triangles += m ? m->triangleCount() : 0;
    }
  }
  return begin;
}

}  // namespace fgsg::rt::output
