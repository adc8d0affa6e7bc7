// fgsg view's field overlay (#49, item 3): what `fgsg field` shows of a grammar's field —
// its streamlines traced from seeds spread over the surface and its singularities with
// their indices (runtime/field/field_sketch.h) — as one message for the page's Field
// toggle, bounded whatever the surface:
//   {"type":"field", "name":"F", "tensor":true, "lines":[[x,y,z, x,y,z, ...], ...],
//    "singularities":[{"kind":"wedge", "index":0.5, "position":[x,y,z]}, ...],
//    "truncated":false}                    (the grammar's first field, major lines)
//   {"type":"field", "error":"why there is none"}   (no surface, no field, a bad design)
#pragma once

#include "ir/ir.h"
#include "runtime/derivation.h"

#include <cstddef>
#include <string>
#include <vector>

namespace fgsg::cli {

// At most this many streamline points and singularities travel; the rest is left out
// and "truncated" says so.
constexpr size_t kMaxFieldOverlayPoints = 60000;
constexpr size_t kMaxFieldOverlaySingularities = 1000;

std::string fieldOverlayJson(const ir::Module& module, const rt::DeriveOptions& options,
                             const std::vector<std::string>& dataDirs);

}  // namespace fgsg::cli
