// fgsg view's field overlay (#49, item 3): what `fgsg field` shows of a grammar's field —
// its streamlines traced from seeds spread over the surface and its singularities with
// their indices (runtime/field/field_sketch.h) — as one message for the page's Field
// toggle, bounded whatever the surface:
//   {"type":"field", "name":"F", "tensor":true, "lines":[[x,y,z, x,y,z, ...], ...],
//    "singularities":[{"kind":"wedge", "index":0.5, "position":[x,y,z]}, ...],
//    "elements":[{"kind":"wedge", "position":[x,y,z], "strength":1, "decay":1}, ...],
//    "truncated":false}                    (the grammar's first field, major lines)
// "elements" (a design field only) lists its design elements in the order the grammar
// writes them, each where it is put (`at vertex N`: that vertex), the page's handles for
// editing them (view_field_edit.h).
//   {"type":"field", "error":"why there is none"}   (no surface, no field, a bad design)
#pragma once

#include "cli/view_field_edit.h"
#include "ir/ir.h"
#include "runtime/derivation.h"

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace fgsg::backend {
class SurfaceGeometryCache;
class SurfaceWorld;
}  // namespace fgsg::backend

namespace fgsg::cli {

// At most this many streamline points and singularities travel; the rest is left out
// and "truncated" says so.
constexpr size_t kMaxFieldOverlayPoints = 60000;
constexpr size_t kMaxFieldOverlaySingularities = 1000;

// `name` and `bounds` (when not null) get the field's name and the surface's box, which
// edits of its elements are checked against; they are left alone when there is an error.
// `world`, when not null: on entry the surface and fields a derivation of `module` with
// `options` built already (fgsg view's SurfaceReuse), not built a second time (null: built
// here, on a mesh from `geometries` when that has it); on return the world the overlay
// shows (null after an error), for the derivation that follows.
std::string fieldOverlayJson(const ir::Module& module, const rt::DeriveOptions& options,
                             const std::vector<std::string>& dataDirs, std::string* name = nullptr,
                             FieldEditBounds* bounds = nullptr,
                             std::shared_ptr<const backend::SurfaceWorld>* world = nullptr,
                             backend::SurfaceGeometryCache* geometries = nullptr);

}  // namespace fgsg::cli
