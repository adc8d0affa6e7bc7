// Tidying a segmentation before charts are flattened. Region growing leaves ragged
// boundaries (a face between two charts sticking into one), holes where a single noisy
// face fell outside the normal cone, and slivers no chart would take. Each of these costs
// a split later (a hole makes a chart an annulus; a ragged boundary touching itself makes
// a pinch, where the flat layout overlaps itself), or a tiny chart that marching must
// jump over.
#pragma once

#include "runtime/atlas/chart_segmentation.h"

namespace fgsg::rt::atlas {

// Moves every face most of whose neighbours (two or three) lie in one other chart into
// that chart, over a few passes until nothing moves; fills one-face holes and files down
// one-face teeth. Then merges charts smaller than `kSliverFraction` of the mean chart area
// into the neighbour they share the longest boundary with, smallest first (the normal cone
// is not asked: a sliver is what the cone left over). Finally charts are split into their
// connected pieces and renumbered by their lowest face. Deterministic.
void cleanUpCharts(const surface::SurfaceMesh& mesh, Segmentation& segmentation);

// A chart covering less than this fraction of the mean chart area is a sliver.
constexpr double kSliverFraction = 0.05;

}  // namespace fgsg::rt::atlas
