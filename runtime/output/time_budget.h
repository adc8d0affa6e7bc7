// --max-seconds for a run that writes only scenes (runtime/output/scene.h) and so
// assembles no flattened mesh: the instances are kept by the rule the flattened assembly
// applies (runtime/assemble.h), on what they draw. In list order, block by block of the
// assembly's size, no block is taken once the deadline has passed or once the time left
// is less than writing the triangles taken so far would take at the flattened writer's
// rate. Counting each instance's asset in full (as the scene's shared meshes draw it)
// bounds both the scene's baking (the same assembly, on its baked parts) and its
// encoding (never more than the flattened file's bytes per triangle), so that a scene
// too large for the time left is cut where the flattened output would be, and the R004
// of a cut assembly fires for it alike.
#pragma once

#include "runtime/assets.h"
#include "runtime/deadline.h"
#include "runtime/instances.h"

#include <cstddef>
#include <vector>

namespace fgsg::rt::output {

// How many of the list's first instances a scene keeps within `deadline`
// (list.instances.size() when all of them).
size_t instancesWithinTime(const InstanceList& list, const AssetLibrary& library, const std::vector<int>& meshOf,
                           const Deadline& deadline, double writeSecondsPerTriangle);

}  // namespace fgsg::rt::output
