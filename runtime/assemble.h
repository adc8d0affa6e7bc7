// Turns a derivation's instance list into one world-space mesh: every instance's asset
// mesh (in the unit box) mapped through the instance transform and coloured with the
// instance colour. Deterministic: the same list gives the same bytes on any thread count.
#pragma once

#include "runtime/assets.h"
#include "runtime/deadline.h"
#include "runtime/instances.h"
#include "runtime/mesh.h"

#include <string>
#include <vector>

namespace fgsg::rt {

// Triangles whose world-space area is below this are dropped (the sides of a box that a
// zero scale flattened).
constexpr double kMinTriangleArea = 1e-12;

// With a deadline, instances are assembled in blocks of about this many triangles (and
// line segments, and one per instance): a millisecond or so of work, so that the
// deadline is noticed in time. A scene-only run cuts its list by the same blocks
// (runtime/output/time_budget.h).
constexpr size_t kAssemblyBlockTriangles = 32768;

// Whether the next block may start: the deadline has not passed and writing the
// `trianglesTaken` so far (at `writeSecondsPerTriangle`, 0: not counted) fits in the time
// left. The assembly and a scene-only run's cut (runtime/output/time_budget.h) both ask it.
bool assemblyBlockMayStart(const Deadline& deadline, double writeSecondsPerTriangle, size_t trianglesTaken);

// The mesh an instance draws (its own geometry, or its asset), or nullptr when the
// binding is missing.
const Mesh* instanceMesh(const Instance& inst, const InstanceList& list, const AssetLibrary& library,
                         const std::vector<int>& meshOf);

// Resolves every name in `list.assets` in `library` (loading files on first use) and
// fills `meshOf[i]` with the library index of `list.assets[i]`. False and a message in
// `error` for the first name that cannot be resolved.
bool resolveAssets(const InstanceList& list, AssetLibrary& library, std::vector<int>& meshOf,
                   std::string& error);

// The assembled mesh: positions by the instance transform, normals by its cofactor matrix
// (correct even when one scale is zero), vertex colours from Instance::color, texture
// coordinates as the asset has them, degenerate triangles and the vertices only they used
// left out. Instances are emitted in list order. The mesh has texture coordinates when any
// instance's asset has them; vertices of assets without them then get (0, 0). When any
// instance is textured (Instance::texture), the mesh lists list.textures and a texture
// run wherever the image changes.
// A smooth terminal (Instance::curve set) is then bent along list.curves[curve]
// (runtime/marching/curve_bend.h); a curve index past list.curves throws
// std::out_of_range, here and in countTriangles.
// With a `deadline`, the instances are assembled in blocks of a few thousand triangles
// and no block starts once it has passed: the mesh holds the first `*assembled`
// instances (all of them when it did not pass). `writeSecondsPerTriangle` > 0 keeps
// time for what comes after, within the deadline: no block starts once the time left
// is less than writing the triangles assembled so far would take at that rate.
Mesh assembleInstances(const InstanceList& list, const AssetLibrary& library,
                       const std::vector<int>& meshOf, const Deadline* deadline = nullptr,
                       size_t* assembled = nullptr, double writeSecondsPerTriangle = 0);
// The same into `out`, whose content it replaces but whose arrays' capacity it keeps: a
// host regenerating a model assembles into the previous mesh without faulting in fresh
// memory again (hundreds of megabytes for on-mesh marching). The arrays end up exactly
// as a fresh mesh's would; only their capacity may be larger.
void assembleInstances(const InstanceList& list, const AssetLibrary& library,
                       const std::vector<int>& meshOf, Mesh& out, const Deadline* deadline = nullptr,
                       size_t* assembled = nullptr, double writeSecondsPerTriangle = 0);

// The instances `which` of `list` (indices into list.instances, in the order given)
// assembled into `out` as assembleInstances assembles a list that holds only them (their
// geometries, curves and the list's textures alike): the same bytes, without copying
// them into a list of their own. An index past the list throws std::out_of_range.
void assembleSelected(const InstanceList& list, const std::vector<uint32_t>& which, const AssetLibrary& library,
                      const std::vector<int>& meshOf, Mesh& out);

// The number of triangles assembleInstances would produce, without building the mesh.
size_t countTriangles(const InstanceList& list, const AssetLibrary& library,
                      const std::vector<int>& meshOf);

}  // namespace fgsg::rt
