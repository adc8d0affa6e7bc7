// CityEngine's footprint-shaping and scope operations as fgsg commands (issue #44):
// AlignScopeToAxes, AlignScopeToGeometry, RotateScope, MirrorScope, Mirror, Setback, ShapeL,
// ShapeU, ShapeO, InnerRectangle, DeleteHoles, ReverseNormals, ResetGeometry,
// CleanupGeometry, the Primitive* shapes and Scatter. They share one command id and one op kind
// (ir::OpKind::ShapeOperation, named by op.str); this table says which words their string
// arguments may be (each becomes a number the runtime reads) and which labels their body
// parts may carry. Semantic analysis and lowering both read it, so they agree.
#pragma once

#include <string>

namespace fgsg::frontend {

// Argument `k` of `command` written as the word `word`: the number it stands for (true), or
// false with the words allowed there in `allowed` (empty: a string is not allowed there).
bool shapeOperationWord(const std::string& command, size_t k, const std::string& word, double& value,
                        std::string& allowed);

// Whether a body part of `command` may be labelled `label` (false: `allowed` lists the labels).
// Setback's edge selectors may end in '=' (CGA's `all = A`: the selected edges' setbacks merged).
bool shapeOperationLabel(const std::string& command, const std::string& label, std::string& allowed);

// Whether `command`'s one body part is written without a label (Scatter's `{ Tree }`).
bool shapeOperationPlainBody(const std::string& command);

// Whether `command` has a form with `count` arguments (the primitives skip some counts
// between their least and most: PrimitiveCylinder takes 0, 1 or 3); false: `forms` says which.
bool shapeOperationArity(const std::string& command, size_t count, std::string& forms);

}  // namespace fgsg::frontend
