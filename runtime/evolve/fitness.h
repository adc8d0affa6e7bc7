// The aesthetic measures of Chan & Hui 2013 (§4.1.3, Eqs. 3-6) and the p4 constraint
// (§6.1), on an expanded pattern (an AlleleGrid, lsystem2d.h).
//
// How two cells are compared (our reading of §4.1.3.1 and Fig. 5, "comparing end points
// of the loci that contain the same letters"): two alleles *look alike* when they have
// the same symbol (so the same locus and cross-section) and the same set of locus end
// points in the tile, orientation applied; the order of the two end points does not
// matter. So B0 and B180 look alike when B's locus is a straight line through the
// centre. The whole pattern is the unit of comparison (the paper: "the whole 2D array is
// considered"); measures are exact, with a 1e-9 tolerance on end point coordinates.
//
//  f_H   (Eq. 3) = H / 6, H the number of the six symmetries below the pattern has. A
//        symmetry T holds when every cell c holds an allele that, transformed by T (end
//        points mapped by T inside the tile), looks like the allele in cell T(c):
//          I   rotation by 90 (and so by -90) degrees about the centre
//          II  rotation by 180 degrees
//          III the x axis (the horizontal midline): y -> -y
//          IV  the y axis (the vertical midline): x -> -x
//          V   the (x, y) axis: the diagonal y = x (through the bottom-left corner)
//          VI  the (-x, y) axis: the diagonal y = -x (through the top-left corner)
//  f_Com (Eq. 4) = (K_R + K_C) / (R(C-1) + C(R-1)): K_R counts horizontally adjacent
//        pairs of cells that do not look alike, K_C vertically adjacent ones. 0 for a
//        1x1 pattern (no pairs).
//  f_Con (Eq. 5) = C / (N K): K = 2 end points per cell (every locus has a start and an
//        end), N cells, C the end points that coincide with an end point of a locus in
//        one of the 8 neighbouring cells (edge and corner neighbours: loci may meet at a
//        tile corner). Cells beyond the pattern's border are not neighbours.
//  fitness (Eq. 6) = (a f_H + b f_Con + c f_Com) / (a + b + c).
//  f_p4  (§6.1): the pattern is meant to be repeated by translation, and the p4
//        signature asks for four-fold rotation centres at its centre and its corners and
//        two-fold ones at the middles of its edges. Following the paper we divide an n x n
//        pattern into four corner sub-tiles of floor(n/2) x floor(n/2) cells (for odd n
//        the middle row and column are left out) and compare each sub-tile with the next
//        one turned by 90 degrees. For a tile repeated by translation, the quarter turn
//        about a corner maps the corner sub-tiles onto each other exactly as the quarter
//        turn about the centre does, cell (r, c) to (n-1-c, r), and two of them make the
//        half turn about an edge middle: so one comparison checks all three criteria.
//        f_p4 is the fraction of the 4 floor(n/2)^2 corner cells whose allele, turned by
//        90 degrees, looks like the allele at the image cell; the pattern has the p4
//        signature when f_p4 = 1. A 1x1 pattern has no corner sub-tiles: f_p4 = 1.
//        With the p4 constraint on, the fitness becomes
//          (a f_H + b f_Con + c f_Com + d f_p4) / (a + b + c + d)
//        and a pattern is accepted only when f_p4 = 1 (genetic.h).
#pragma once

#include "runtime/evolve/lsystem2d.h"
#include "runtime/evolve/tiles.h"

#include <array>
#include <cstdint>
#include <vector>

namespace fgsg::rt::evolve {

// The six symmetries of §4.1.3.1, in the paper's order.
enum class Symmetry { kRotate90, kRotate180, kMirrorX, kMirrorY, kDiagonal, kAntiDiagonal };
constexpr int kSymmetryCount = 6;

// Where cell (r, c) of an n x n pattern goes under a symmetry (row 0 at the top).
std::array<int, 2> mapCell(Symmetry s, int n, int r, int c);
// Where a point of a tile's unit square goes under a symmetry (about the tile centre).
Point2 mapPoint(Symmetry s, Point2 p);

// Weights of Eq. 6 (a, b, c) and of the p4 term (d). Defaults: a = b = c = 1, d = 3
// (the paper gives no values; d = 3 lets the p4 constraint lead the search: on the
// paper's 8 alleles with 3x3 rules the GA then finds a p4 pattern in about 10
// generations, bench/evolve.cpp).
struct FitnessWeights {
  double symmetry = 1;      // a
  double connectivity = 1;  // b
  double complexity = 1;    // c
  double p4 = 3;            // d, used when the p4 constraint is on
};

struct FitnessTerms {
  int symmetries = 0;       // H
  double fH = 0, fCon = 0, fCom = 0;
  double fP4 = 1;           // 1 when not measured
  double fitness = 0;       // Eq. 6 (with the p4 term when asked for)
};

// Eq. 6: (a fH + b fCon + c fCom) / (a + b + c). Throws std::invalid_argument when a
// weight is negative or not finite, or all are 0.
double combineFitness(double fH, double fCon, double fCom, const FitnessWeights& w);
// With the p4 term: (a fH + b fCon + c fCom + d fP4) / (a + b + c + d).
double combineFitness(double fH, double fCon, double fCom, double fP4, const FitnessWeights& w);

// The measures for one tile set. Construction tabulates, for every allele (all four
// orientations of every symbol), its look, the look of its image under each symmetry and
// which of its end points meet which of every other allele's in each neighbour
// direction; the measures are then table look-ups. Immutable once built: one object
// may serve many threads.
class PatternMeasure {
 public:
  explicit PatternMeasure(const TileSet& tiles);

  // Whether a and b look alike (same symbol, same end point set).
  bool lookAlike(Allele a, Allele b) const { return look_[size_t(a.index())] == look_[size_t(b.index())]; }

  bool symmetric(const AlleleGrid& g, Symmetry s) const;
  int symmetryCount(const AlleleGrid& g) const;                     // H
  double symmetry(const AlleleGrid& g) const;                       // f_H, Eq. 3
  double complexity(const AlleleGrid& g) const;                     // f_Com, Eq. 4
  int connectedEndpoints(const AlleleGrid& g) const;                // C of Eq. 5
  double connectivity(const AlleleGrid& g) const;                   // f_Con, Eq. 5
  double p4(const AlleleGrid& g) const;                             // f_p4, §6.1
  FitnessTerms evaluate(const AlleleGrid& g, const FitnessWeights& w, bool withP4) const;

  int symbolCount() const { return symbols_; }

 private:
  // A pattern checked (square, symbols in range) and tabulated once for all measures:
  // each cell's allele index and look.
  struct Cells {
    int n = 0;
    std::vector<uint8_t> index, look;
  };
  Cells prepare(const AlleleGrid& g) const;
  bool symmetricImpl(const Cells& v, Symmetry s) const;
  int symmetryCountImpl(const Cells& v) const;
  double complexityImpl(const Cells& v) const;
  int connectedImpl(const Cells& v) const;
  double p4Impl(const Cells& v) const;

  int symbols_ = 0;
  std::vector<uint8_t> look_;                                 // [allele] -> look id
  std::array<std::vector<uint8_t>, kSymmetryCount> image_;    // [sym][allele] -> look id of the image, 255: none
  // [direction][a * alleles + b], b the neighbour of a in kForward direction d: bits 0-1,
  // a's end points (start, end) meeting one of b's; bits 2-3, b's meeting one of a's.
  std::array<std::vector<uint8_t>, 4> meet_;
};

}  // namespace fgsg::rt::evolve
