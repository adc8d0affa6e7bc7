// What names each start shape of a derivation's scene (runtime/output/scene.h) and what
// it carries, for fgsg run, Python and the C API alike: a lot is named after its GeoJSON
// feature id (else "feature N", "face N"; " polygon K" after a MultiPolygon's later
// polygons) with its properties; a seed derived apart "seed N"; else the one "axiom".
// Each has the grammar attrs' values it derived with (defaults, --set, the lot's
// properties of their names, as the derivation set them) and its report collections.
#pragma once

#include "ir/ir.h"
#include "runtime/derivation.h"
#include "runtime/output/scene.h"

#include <vector>

namespace fgsg::backend {

// One per start shape of result.instances.startBounds (one when it has none).
std::vector<rt::output::StartInfo> sceneStarts(const ir::Module& m, const rt::DeriveOptions& options,
                                               const rt::DeriveResult& result);

}  // namespace fgsg::backend
