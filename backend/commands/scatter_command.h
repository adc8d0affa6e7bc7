// CityEngine's scatter as fgsg's Scatter(domain, n, distribution[, mean, stddev, "relative"])
// { operations } (an ir::OpKind::ShapeOperation named "Scatter"): n points drawn on the
// shape's surface, in its solid or in its scope (runtime/cga/scatter.h), the body run on
// each as a shape of its own with a scope of size zero. The points come from a stream of
// their own, keyed by the shape's stream (which gives up one number for it), so they are
// the same in every engine and whatever the body draws.
#pragma once

#include "backend/commands/command_family.h"

namespace fgsg::backend {

class Derivation;

// a: domain (0 surface, 1 volume, 2 scope), n, distribution (0 uniform, 1 gaussian), then
// optionally the mean (frontend/shape_operations.cpp's codes), the deviation and whether
// it is relative (1; the default when the deviation is not given).
void applyScatter(Derivation& d, const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex, Frame& f);

}  // namespace fgsg::backend
