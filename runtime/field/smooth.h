// Component-wise discrete Laplacian smoothing of a field (FGSG §4.2's editing stage,
// Zhang et al. 2007 §4.2): every iteration moves each vertex's value part of the way
// toward the mean of its edge neighbours' values, each transported into the vertex's
// frame first (so a field that is parallel on a flat patch stays as it is). Jacobi
// iterations, uniform weights. Smoothing removes unwanted singularities: they merge and
// cancel as the field gets smoother.
#pragma once

#include "runtime/deadline.h"
#include "runtime/field/tangent_field.h"

#include <cstdint>
#include <vector>

namespace fgsg::rt::field {

struct SmoothOptions {
  // The fraction of the way to the neighbours' mean per iteration. The averaging has
  // eigenvalues in [-1, 1]; with one half every mode is multiplied by a factor in [0, 1]
  // per iteration, so none oscillates (with 1 the roughest ones would flip sign).
  double step = 0.5;
  // Vertices marked non-zero keep their values (design elements the user placed).
  const std::vector<uint8_t>* locked = nullptr;
  // --max-seconds: asked for every block of vertices; smoothing throws TimeLimitReached
  // when it expires (the field is then left as it was).
  Deadline* deadline = nullptr;
};

void smooth(TangentField& field, int iterations, const SmoothOptions& options = {});

}  // namespace fgsg::rt::field
