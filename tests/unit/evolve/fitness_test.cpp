// The measures of Chan & Hui 2013 §4.1.3 (f_H Eq. 3, f_Com Eq. 4, f_Con Eq. 5, Eq. 6)
// and the p4 measure of §6.1, on small arrays computed by hand.
#include "runtime/evolve/fitness.h"

#include <catch2/catch.hpp>

using namespace fgsg::rt::evolve;

namespace {

// H: a horizontal line through the middle, (0, .5)-(1, .5). D: the diagonal (0, 0)-(1, 1).
// A: a quarter arc (.5, 0)-(1, .5) (exampleTileSet's A).
TileSet lineTiles() {
  TileSet ts;
  ts.loci.push_back({"H", {Curve::Kind::kPolyline, {{0, 0.5}, {1, 0.5}}}});
  ts.loci.push_back({"D", {Curve::Kind::kPolyline, {{0, 0}, {1, 1}}}});
  ts.loci.push_back({"A", {Curve::Kind::kCubic, {{0.5, 0}, {0.5, 0.3}, {0.7, 0.5}, {1, 0.5}}}});
  ts.sections.push_back({"C", {Curve::Kind::kPolyline, {{-1, 0}, {0, 1}, {1, 0}}}});
  ts.tiles = {Tile{'H', 0, 0}, Tile{'D', 1, 0}, Tile{'A', 2, 0}};
  validateTileSet(ts);
  return ts;
}

AlleleGrid grid(const std::string& text) { return parseLSystem("{H.D.A." + text + "}", "HDA").axiom; }

}  // namespace

TEST_CASE("f_H: the six symmetries, compared by loci end points", "[evolve][fitness]") {
  const PatternMeasure m(lineTiles());
  // Horizontal lines everywhere: symmetric under the half turn and both mirror lines.
  const AlleleGrid h = grid("HHHH");
  CHECK_FALSE(m.symmetric(h, Symmetry::kRotate90));
  CHECK(m.symmetric(h, Symmetry::kRotate180));
  CHECK(m.symmetric(h, Symmetry::kMirrorX));
  CHECK(m.symmetric(h, Symmetry::kMirrorY));
  CHECK_FALSE(m.symmetric(h, Symmetry::kDiagonal));
  CHECK_FALSE(m.symmetric(h, Symmetry::kAntiDiagonal));
  CHECK(m.symmetryCount(h) == 3);
  CHECK(m.symmetry(h) == 0.5);
  // Diagonals (0,0)-(1,1): the half turn and both diagonals.
  const AlleleGrid d = grid("DDDD");
  CHECK(m.symmetric(d, Symmetry::kRotate180));
  CHECK(m.symmetric(d, Symmetry::kDiagonal));
  CHECK(m.symmetric(d, Symmetry::kAntiDiagonal));
  CHECK(m.symmetryCount(d) == 3);
  // In the manner of Fig. 5: D H90 / H90 D is not symmetric about the diagonal that swaps
  // the top-right and bottom-left cells (a vertical line mirrors to a horizontal one),
  // D H180 / H90 D is (H180 has the end points of H0).
  CHECK_FALSE(m.symmetric(grid("DH90H90D"), Symmetry::kAntiDiagonal));
  CHECK(m.symmetric(grid("DH180H90D"), Symmetry::kAntiDiagonal));
  CHECK(m.symmetryCount(grid("DH180H90D")) == 1);
  // The symmetry is of the arrangement too: H D / H H has none.
  CHECK(m.symmetryCount(grid("HDHH")) == 0);
  // A single cell: the cell's own symmetries.
  CHECK(m.symmetryCount(grid("H")) == 3);
  // The arc (.5,0)-(1,.5) is mirrored onto itself by the (-x, y) axis alone.
  CHECK(m.symmetryCount(grid("A")) == 1);
  CHECK(m.symmetric(grid("A"), Symmetry::kAntiDiagonal));
}

TEST_CASE("f_Com (Eq. 4): differing neighbours over R(C-1) + C(R-1)", "[evolve][fitness]") {
  const PatternMeasure m(lineTiles());
  CHECK(m.complexity(grid("HHHH")) == 0);
  CHECK(m.complexity(grid("H")) == 0);  // no pairs
  // H D / H H: K_R = 1 (H|D), K_C = 1 (D over H); 2 / (2*1 + 2*1).
  CHECK(m.complexity(grid("HDHH")) == 0.5);
  // H H90 H / H H H90 / D D D:
  //   rows: 2 + 1 + 0 = 3; columns: 1 + 2 + 2 = 5; 8 / (3*2 + 3*2) = 2/3.
  CHECK(m.complexity(grid("HH90H" "HHH90" "DDD")) == Approx(2.0 / 3.0).epsilon(1e-15));
  // H180 looks like H (same end points): the same value.
  CHECK(m.complexity(grid("HH90H" "H180HH90" "DDD")) == m.complexity(grid("HH90H" "HHH90" "DDD")));
}

TEST_CASE("f_Con (Eq. 5): end points meeting one in a neighbouring cell", "[evolve][fitness]") {
  const PatternMeasure m(lineTiles());
  // 2x2 horizontal lines: each cell's inner end point meets its neighbour's: 4 of 8.
  CHECK(m.connectedEndpoints(grid("HHHH")) == 4);
  CHECK(m.connectivity(grid("HHHH")) == 0.5);
  // 2x2 diagonals: only the bottom-left's (1,1) meets the top-right's (0,0), at the
  // centre, through a corner neighbour: 2 of 8.
  CHECK(m.connectedEndpoints(grid("DDDD")) == 2);
  CHECK(m.connectivity(grid("DDDD")) == 0.25);
  // H H90 H / H H H90 / D D D: only the two middle-row H meet: 2 of 18.
  CHECK(m.connectedEndpoints(grid("HH90H" "HHH90" "DDD")) == 2);
  CHECK(m.connectivity(grid("HH90H" "HHH90" "DDD")) == 2.0 / 18.0);
  // A circle of four arcs: every end point meets one.
  CHECK(m.connectivity(grid("AA270A90A180")) == 1);
  // A single cell has no neighbours.
  CHECK(m.connectivity(grid("H")) == 0);
}

TEST_CASE("Eq. 6 combines the measures with weights a, b, c", "[evolve][fitness]") {
  const PatternMeasure m(lineTiles());
  FitnessWeights w;
  w.symmetry = 2, w.connectivity = 1, w.complexity = 1;
  // HHHH: f_H = 1/2, f_Con = 1/2, f_Com = 0: (2 * 0.5 + 0.5 + 0) / 4.
  const FitnessTerms t = m.evaluate(grid("HHHH"), w, false);
  CHECK(t.symmetries == 3);
  CHECK(t.fH == 0.5);
  CHECK(t.fCon == 0.5);
  CHECK(t.fCom == 0);
  CHECK(t.fitness == 0.375);
  CHECK(combineFitness(0.5, 0.5, 0, w) == 0.375);
  // The circle of arcs: every symmetry, every end point connected, every neighbour
  // different: fitness 1 whatever the weights.
  const FitnessTerms c = m.evaluate(grid("AA270A90A180"), w, false);
  CHECK(c.symmetries == 6);
  CHECK(c.fCon == 1);
  CHECK(c.fCom == 1);
  CHECK(c.fitness == 1);
  // With the p4 term (d): (a fH + b fCon + c fCom + d fP4) / (a + b + c + d).
  w.p4 = 4;
  const FitnessTerms p = m.evaluate(grid("HHHH"), w, true);
  CHECK(p.fP4 == 0);  // H turned is vertical: no cell matches (see the p4 test)
  CHECK(p.fitness == (2 * 0.5 + 0.5 + 0 + 4 * 0) / 8);
  FitnessWeights bad;
  bad.complexity = -1;
  CHECK_THROWS_AS(combineFitness(0, 0, 0, bad), std::invalid_argument);
  CHECK_THROWS_AS(combineFitness(0, 0, 0, FitnessWeights{0, 0, 0, 1}), std::invalid_argument);
}

TEST_CASE("p4 (§6.1): corner sub-tiles that turn into each other", "[evolve][fitness]") {
  const PatternMeasure m(lineTiles());
  // 2x2: the corner sub-tiles are the cells. A quarter turn maps cell (r, c) to
  // (n-1-c, r). The circle of arcs turns into itself; H turned is a vertical line, so
  // HHHH matches nowhere...
  CHECK(m.p4(grid("AA270A90A180")) == 1);
  CHECK(m.p4(grid("HHHH")) == 0);
  CHECK(m.p4(grid("AAAA")) == 0);
  // ... H H90 / H90 H: every cell's quarter turn lands on a cell of the other
  // orientation: all match (H270 looks like H90).
  CHECK(m.p4(grid("HH90H90H")) == 1);
  CHECK(m.p4(grid("HH90H90H90")) == 0.5);  // the bottom-right cell spoils two comparisons
  // 3x3: the middle row and column are left out; the four corners must chain.
  CHECK(m.p4(grid("DHD90" "HHH" "D270HD180")) == 1);
  CHECK(m.p4(grid("DHD" "HHH" "D270HD180")) == 0.5);
  CHECK(m.p4(grid("H")) == 1);  // no corner sub-tiles
}
