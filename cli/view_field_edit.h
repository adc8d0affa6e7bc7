// fgsg view's field design editing (#49, item 3): a design element of the grammar's first
// field added, moved, deleted or given a new strength from the page, written back into the
// grammar's text. Only the element's own text changes — the `at` words of a moved one, the
// `strength` words, the whole item of a deleted one, a new item after the block's last —
// and every other byte of the file stays as it was, comments and layout included:
//   field F = design tensor { wedge at (-2, 0, 0) decay 1; }
//   + add trisector (2, 0, 0)  ->  { wedge at (-2, 0, 0) decay 1; trisector at (2, 0, 0); }
//   + move 0 to (-1.5, 0.25, 0)  ->  { wedge at (-1.5, 0.25, 0) decay 1; trisector ... }
// Numbers are written to a millionth of the surface's size (positions, directions) or
// 1e-4 (strengths), in plain decimals (`-1.5`, not `-1.5e+00`).
#pragma once

#include "cli/view_message.h"

#include <string>

namespace fgsg::cli {

// Where the surface lies (world space, after --surface-size): positions farther outside
// its box than its diagonal are refused, and numbers are rounded to its scale.
struct FieldEditBounds {
  double min[3] = {0, 0, 0};
  double max[3] = {0, 0, 0};
};

// Rewrites `text`, the grammar file `fileName`'s own text, for one edit of the design
// elements of its first field, which must be named `fieldName` (the one the overlay shows).
// False with a reason, and `out` untouched, when the text does not parse, its first field
// is not that design, the index is past its elements, the kind does not fit the design
// (wedge and trisector in a vector design), the position is far off the surface, or the
// edit would leave the design without an element.
bool editFieldDesignText(const std::string& fileName, const std::string& text, const std::string& fieldName,
                         const PageFieldElement& edit, const FieldEditBounds& bounds, std::string& out,
                         std::string& reason);

}  // namespace fgsg::cli
