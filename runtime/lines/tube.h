// Meshing a linear structure (FGSG §4.4): a smooth centreline through the points of a
// line, and a closed tube swept along it.
#pragma once

#include "runtime/mesh.h"
#include "runtime/scope.h"

#include <vector>

namespace fgsg::rt {

// A centripetal Catmull–Rom spline through `points` (no cusps or loops within a segment,
// unlike the uniform one), sampled `samplesPerSegment` times per segment (at least once):
// (n - 1) * samplesPerSegment + 1 samples, and sample i * samplesPerSegment is exactly
// points[i], so the ends of joined lines stay where they joined. Fewer than two points
// give the points themselves.
std::vector<Vec3> sampleCentreline(const std::vector<Vec3>& points, int samplesPerSegment);

// A closed tube of `radius` around the centreline of `points` (as sampleCentreline): at
// each sample a ring of `sides` (at least 3) vertices, turned along by parallel transport
// so the tube does not twist, and flat caps at both ends. Side vertices carry radial
// normals; each cap has its own vertices (a copy of the end ring plus its centre) with the
// cap's flat normal, so the surface is closed by position rather than by index.
// Vertices: samples * sides + 2 * (sides + 1); triangles: 2 * sides * samples.
// Counter-clockwise seen from outside. Fewer than two points give an empty mesh.
Mesh sweepTube(const std::vector<Vec3>& points, double radius, int sides, int samplesPerSegment);

}  // namespace fgsg::rt
