// Built-in surfaces, generated in code (no files): the defaults a grammar can grow on and
// the fixtures tests measure against. Every one is manifold, consistently oriented with
// counter-clockwise faces seen from outside, and meshed with well-shaped triangles of
// about equal size; the returned meshes have their topology built.
#pragma once

#include "runtime/surface/surface_mesh.h"

#include <string>
#include <vector>

namespace fgsg::rt::surface {

// Default resolutions: segments around the smallest circle, or subdivision levels. The
// torus and sphere defaults keep the area within 0.5% of the smooth surface's.
constexpr int kDefaultTorusSegments = 32;      // around the tube
constexpr int kDefaultCylinderSegments = 48;   // around the axis
constexpr int kDefaultPlaneSegments = 32;      // along the longer side
constexpr int kDefaultSphereSubdivisions = 4;  // of an icosahedron: 5120 faces
constexpr int kDefaultGenus2Levels = 3;        // Catmull-Clark steps: 8448 faces
// No procedural surface may have more faces than this (a typo in a resolution argument
// should not exhaust memory).
constexpr size_t kMaxProceduralFaces = 4'000'000;

// A torus around the Z axis: major radius R, tube radius r (R > r > 0); `segments`
// around the tube, as many around the axis as keep the triangles near square halves.
SurfaceMesh torus(double R = 1.0, double r = 0.4, int segments = kDefaultTorusSegments);
// A sphere of radius r about the origin: a subdivided icosahedron (near-equilateral
// triangles everywhere, no poles).
SurfaceMesh sphere(double r = 1.0, int subdivisions = kDefaultSphereSubdivisions);
// A flat w x h grid in the XY plane centred at the origin, normal +Z (open: all boundary).
// `segments` along the longer side; square cells, each split into two triangles.
SurfaceMesh plane(double w = 2.0, double h = 2.0, int segments = kDefaultPlaneSegments);
// An OPEN cylinder (no caps: two boundary circles) of radius r around the Z axis, from
// z = -h/2 to h/2, normals pointing away from the axis; `segments` around the axis.
SurfaceMesh cylinder(double r = 1.0, double h = 2.0, int segments = kDefaultCylinderSegments);
// A closed genus-2 surface (a double torus) in the XY plane, centred at the origin: two
// handles whose holes are centred at x = -R and x = R, bars about r thick (the
// Catmull-Clark limit of a polycube cage with bars 2r wide, so the tube is a little
// thinner than r). Euler characteristic -2.
SurfaceMesh genus2(double R = 1.0, double r = 0.4, int levels = kDefaultGenus2Levels);
// FGSG Fig. 17's genus-7 surface: the union of three tori (major radius R, tube radius r,
// R > 2r so the six junctions stay apart) about the Z, X and Y axes, remeshed to about
// the torus's edge length (three_tori.cpp). Euler characteristic -12.
SurfaceMesh threeTori(double R = 1.0, double r = 0.3, int segments = kDefaultTorusSegments);

// Builds the surface named `name` from `args` (missing trailing ones take the defaults
// above). False with a message for an unknown name, too many arguments or a bad value
// ("torus(R, r) needs R > r > 0"); `out` is then left empty.
bool makeProceduralSurface(const std::string& name, const std::vector<double>& args,
                           SurfaceMesh& out, std::string& error);

// The names makeProceduralSurface() knows, in a stable order: torus sphere plane genus2
// cylinder tori3.
const std::vector<std::string>& proceduralSurfaceNames();
// The signature of a procedural surface for messages, e.g.
// "torus(R = 1, r = 0.4, segments = 32)"; "" for an unknown name.
std::string proceduralSurfaceSignature(const std::string& name);

}  // namespace fgsg::rt::surface
