// Continuous model synthesis (Merrell, "Model Synthesis", ch. 4, §4.5-4.6): from a closed
// polygonal example, a new solid in a box whose every point has a neighbourhood that
// occurs in the example (the continuous adjacency constraint, eq. 4.1), with every face
// on a set of parallel planes per example normal.
//
//   ExampleSolid ex;  std::string err;
//   if (!loadExampleSolid("houses.obj", ex, err)) ...;
//   ContinuousOptions o;  o.size = {40, 40, 12};  o.spacing = 1;  o.seed = 7;
//   ContinuousResult r = synthesizeContinuous(ex, o);
//   if (!r.ok) print(r.error);   else writeMesh(r.mesh, "village.glb", err);
//
// The labels are the example's vertex figures (labels.h), one per vertex of the plane
// arrangement (arrangement.h); neighbouring vertices must agree along their edge. They
// are assigned by the discrete solver's catalog (catalog.h: the same bitset domains,
// AC-3 propagation and transition rows, the arrangement's edges as its links), in
// overlapping blocks that start from the empty model (always consistent) and are
// reverted when they fail (§4.5.6, Fig. 4.23). The output is the boundary between inside
// and outside cells: a closed 2-manifold triangle mesh.
#pragma once

#include "runtime/deadline.h"
#include "runtime/mesh.h"
#include "runtime/synthesis/continuous/example_solid.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::rt::synthesis::continuous {

// A dimensional constraint (§4.6.1): objects are exactly `planes` plane spacings wide
// along the direction `normal` (one of the example's face directions): its planes are
// that far apart and no label may cross one.
struct FixedWidth {
  IVec3 normal{};
  int planes = 1;
};

struct ContinuousOptions {
  std::array<double, 3> size{20, 20, 10};  // the output box, world units, from the origin
  double spacing = 1.0;                    // lattice unit: the planes' spacing along the axes
  uint64_t seed = 1;
  // Block edge in lattice units (Fig. 4.23); 0 = the whole box at once; -1 = the whole
  // box, and blocks of 8 if that meets a contradiction.
  int block = -1;
  int blockRetries = 6;      // tries of a block before it is left as it was
  int passes = 2;            // sweeps over all blocks
  std::vector<FixedWidth> fixedWidth;
  // Coarser planes (§4.5.8, spacing the planes): along `normal` only every `planes`-th
  // plane, without fixing any width — fewer vertices where a steep slope's planes crowd
  // (a 2:1 slope's planes lie 1/sqrt(5) apart), faces of that slope at fewer places.
  std::vector<FixedWidth> planeStep;
  // Every solid stands on the box's floor (y = 0), as the example on its lowest level:
  // floor vertices may carry solid above them; above the floor a face looks down only in
  // a figure the example has above its own ground plane (a bridge's soffit, an arch), so
  // a pier's foot or a box's bottom corner never floats.
  bool onGround = false;
  double fill = 0.5;         // chance weight of labels with solid in them against empty space
  // Connectivity (§4.6.2): > 0 grows the solid from this many seeds, a vertex taking
  // solid only where the solid already placed reaches it, so each seed is one connected
  // part (the whole box at once; blocks are not used).
  int growSeeds = 0;
  // A large-scale constraint (§4.6.3): a map over the box's floor (x along the rows, z
  // down them), 0..1; no solid touches a place where it is below one half. Empty: none.
  int maskWidth = 0, maskHeight = 0;
  std::vector<float> mask;   // row-major, 0..1
  // Symmetry: the output is its own mirror image across the middle of the box along each
  // axis listed (0 x, 2 z). The whole box at once (no blocks).
  std::vector<int> mirrorAxes;
  // §4.8's post-process: each part moved by up to this much (world units) along x and z,
  // at random, never into another part's box; 0 = off.
  double perturb = 0;
  size_t maxVertices = 8'000'000;
  double timeLimitSeconds = 120;
  Deadline* deadline = nullptr;
};

struct ContinuousStats {
  int exampleFaces = 0, directions = 0, labels = 0, relations = 0;
  size_t vertices = 0, edges = 0;
  size_t outputPolygons = 0;  // whole faces (touching arrangement faces of a plane merged)
  size_t arrangementFaces = 0, triangles = 0, parts = 0;
  int blocks = 0, blocksFailed = 0;
  uint64_t assignments = 0;
  double seconds = 0;
  // Where the time went: the arrangement and labels, the assignment, the surface.
  double compileSeconds = 0, assignSeconds = 0, surfaceSeconds = 0;
};

struct ContinuousResult {
  bool ok = false;
  std::string error;
  Mesh mesh;                       // world units; no normals (faceted)
  // The surface as whole faces (world units, counter-clockwise from outside) and, per
  // face, which connected part of the solid it bounds (0 .. stats.parts - 1).
  std::vector<std::vector<std::array<double, 3>>> faces;
  std::vector<uint32_t> facePart;
  ContinuousStats stats;
};

ContinuousResult synthesizeContinuous(const ExampleSolid& example, const ContinuousOptions& options) noexcept;

}  // namespace fgsg::rt::synthesis::continuous
