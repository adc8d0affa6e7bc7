// A surface laid flat (Buron et al. §4, after Sander et al.'s multi-chart geometry
// images): every face belongs to one chart, and every face corner has a position in the
// unit square. Charts do not overlap, are not mirrored, and keep a band of empty space
// around them wide enough for the indirection pixels of a geometry image of
// `resolution` texels (at least one texel, `AtlasOptions::gutterTexels`).
#pragma once

#include "runtime/surface/surface_mesh.h"

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace fgsg::rt::atlas {

using Vec2 = Eigen::Vector2d;

struct Atlas {
  int chartCount = 0;
  // Per face: its chart, 0 .. chartCount-1; charts are numbered by their lowest face.
  std::vector<int> faceChart;
  std::vector<std::array<Vec2, 3>> cornerUV;  // per face corner: (u right, v up) in [0,1]^2
  int resolution = 1024;                      // the geometry image the layout was packed for
};

struct AtlasOptions {
  int resolution = 1024;   // texels per side of the geometry image the charts are packed for
  // Empty texels kept between charts and around the border (>= 1). Exactly: between the
  // texels a chart touches (any texel its triangles meet) and those of any other chart,
  // or the image's edge, lie at least this many empty texels, in x or in y.
  int gutterTexels = 2;
  // Charts grow while every face normal stays within this angle (degrees) of the chart's
  // first face normal; a larger angle means fewer, more distorted charts.
  double maxNormalDeviation = 60.0;
};

// Segments `mesh` into charts, parametrizes each (least-squares conformal maps) and packs
// them into the unit square. Every chart is a disk laid flat without folds or overlaps;
// all charts have the same texel density (UV area per surface area), which marching
// relies on to measure lengths in texels; a chart may be turned (by any angle) but never
// mirrored. Needs the mesh's topology. Deterministic: the same mesh and options give the
// same bytes, on any number of threads. False with a message when the options are out of
// range or the charts do not fit into `resolution` texels even at one texel each.
bool buildAtlas(const surface::SurfaceMesh& mesh, const AtlasOptions& options, Atlas& out, std::string& error);

// The mesh's own texture coordinates (`mesh.textureUV`) as an atlas: charts are the
// connected components of faces that share an edge with the same coordinates on both
// sides; each chart keeps its own layout (scaled and moved, never rotated or mirrored)
// and is re-packed with the gutter (one scale for all charts, so their relative densities
// stay as the file has them). False with a located message (face numbers) when
// coordinates are not finite, degenerate, mirrored (a triangle running against its chart,
// or a chart running clockwise where the faces run counter-clockwise) or overlap.
bool atlasFromTextureUV(const surface::SurfaceMesh& mesh, const AtlasOptions& options, Atlas& out,
                        std::string& error);

}  // namespace fgsg::rt::atlas
