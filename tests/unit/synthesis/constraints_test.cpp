// The constraint maps of constraints.h, cell by cell on small non-square grids: where each
// symmetry sends a cell, which mask region holds background labels only, and how a mask
// image is read (dark is inside, image row 0 is the grid's top row). Each check kills a
// mutation of tests/mutations/synthesis_constraints.txt that the solver tests let through
// (issue #51, docs/testing.md); its comment says which and the value under it.
#include "tests/unit/runtime/scratch_files.h"
#include "test_helpers.h"

#include "runtime/synthesis/constraints.h"

#include <fstream>

using namespace synth_test;

namespace {

// Cell index of (x, y, z), x fastest (symmetryImage's order).
int64_t at(const GridSize& n, int x, int y, int z = 0) { return x + int64_t(n.nx) * (y + int64_t(n.ny) * z); }

int64_t image(SymmetrySpec::Kind kind, const GridSize& n, int64_t cell, int offset = 0) {
  return symmetryImage(SymmetrySpec{kind, offset}, n, cell);
}

}  // namespace

TEST_CASE("symmetry images of single cells on non-square grids", "[synthesis][constraints][symmetry]") {
  SymmetrySpec s{SymmetrySpec::kRotate90, 0};
  REQUIRE(parseSymmetry("mirror-x", s));
  CHECK(s.kind == SymmetrySpec::kMirrorX);  // issue #51: mirror-x parsed as mirror-y passed
  REQUIRE(parseSymmetry("mirror-y", s));
  CHECK(s.kind == SymmetrySpec::kMirrorY);

  const GridSize g{4, 6, 2};
  // Mirror x: (0, 2, 0) -> (3, 2, 0); the off-by-one nx - x gives x = 4, off the grid.
  CHECK(image(SymmetrySpec::kMirrorX, g, at(g, 0, 2)) == at(g, 3, 2));
  // Mirror y: (1, 0, 1) -> (1, 5, 1) = 45. Kills "Y = n.nx - 1 - y" (nx for ny): on this
  // 4 x 6 grid that gives Y = 3, cell 37.
  CHECK(image(SymmetrySpec::kMirrorY, g, at(g, 1, 0, 1)) == 45);
  CHECK(at(g, 1, 5, 1) == 45);
  // Rotate 180 about the centre: (1, 0) -> (2, 5); both coordinates turn.
  CHECK(image(SymmetrySpec::kRotate180, g, at(g, 1, 0)) == at(g, 2, 5));
  // Rotate 90 (counter-clockwise) needs a square grid: (0, 1) -> (3 - 1 - 1, 0) = (1, 0).
  const GridSize sq{3, 3, 1};
  CHECK(image(SymmetrySpec::kRotate90, sq, at(sq, 0, 1)) == at(sq, 1, 0));
  CHECK(image(SymmetrySpec::kRotate90, g, at(g, 0, 1)) == -1);

  // Translate x by 2 on a 5 x 3 grid: (1, 1) -> (3, 1) = 8, and (3, 1) -> x = 5, off the
  // grid. Kills "X = x - s.offset" (the wrong way): (1, 1) -> x = -1, off the grid (-1),
  // and (3, 1) -> (1, 1) = 6.
  const GridSize t{5, 3, 1};
  CHECK(image(SymmetrySpec::kTranslateX, t, at(t, 1, 1), 2) == 8);
  CHECK(image(SymmetrySpec::kTranslateX, t, at(t, 3, 1), 2) == -1);
  CHECK(image(SymmetrySpec::kTranslateY, t, at(t, 1, 1), 1) == at(t, 1, 2));
  CHECK(image(SymmetrySpec::kTranslateY, t, at(t, 1, 2), 1) == -1);
}

TEST_CASE("symmetry label maps: each symmetry its own map, rotate-180 the quarter turn twice",
          "[synthesis][constraints][symmetry]") {
  // Roads' tiles come in rotated variants (corner, tee, line ...), so the x and y mirrors
  // and the quarter turn map labels differently.
  const Example ex = load("roads.json");
  const int k = ex.labelCount();
  REQUIRE(int(ex.mirrorX.size()) == k);
  REQUIRE(ex.mirrorX != ex.mirrorY);
  CHECK(symmetryLabelMap({SymmetrySpec::kMirrorX, 0}, ex) == ex.mirrorX);
  CHECK(symmetryLabelMap({SymmetrySpec::kMirrorY, 0}, ex) == ex.mirrorY);
  CHECK(symmetryLabelMap({SymmetrySpec::kRotate90, 0}, ex) == ex.rot90);
  const std::vector<int32_t> half = symmetryLabelMap({SymmetrySpec::kRotate180, 0}, ex);
  int turnedOnce = 0;  // labels a quarter turn and a half turn map differently
  for (int l = 0; l < k; ++l) {
    CHECK(half[size_t(l)] == ex.rot90[size_t(ex.rot90[size_t(l)])]);
    turnedOnce += half[size_t(l)] != ex.rot90[size_t(l)];
  }
  CHECK(turnedOnce > 0);  // so a map turned once, not twice, fails the check above
  std::vector<int32_t> identity(static_cast<size_t>(k));
  for (int l = 0; l < k; ++l) identity[size_t(l)] = l;
  CHECK(symmetryLabelMap({SymmetrySpec::kTranslateX, 3}, ex) == identity);
}

TEST_CASE("a mask's outside holds background labels only, its inside every label", "[synthesis][constraints][mask]") {
  const Example ex = load("roads.json");  // "empty" is the one background label
  const GridSize n{3, 2, 1};
  const PositionWeights w = maskFromCells({1, 0, 0, 0, 0, 1}, n, ex, 4.0);
  REQUIRE(w.factor.size() == 2);
  CHECK(w.region == std::vector<uint16_t>{1, 0, 0, 0, 0, 1});
  const int empty = ex.findLabel("empty"), line = ex.findLabel("line");
  REQUIRE(ex.labels[size_t(empty)].background);
  REQUIRE_FALSE(ex.labels[size_t(line)].background);
  CHECK(w.at(1, empty) == 1.0);
  CHECK(w.at(1, line) == 0.0);
  CHECK(w.at(0, empty) == 1.0);
  CHECK(w.at(0, line) == 4.0);
  // Region 0 (outside) keeps only "empty" (factor 1 > 0, a background label): background-
  // only. Kills "if (w.factor[region][l] > 0) return false" (no region background-only):
  // the background label's factor 1 alone then makes it false.
  CHECK(backgroundOnlyRegion(w, 0, ex));
  CHECK_FALSE(backgroundOnlyRegion(w, 1, ex));
  CHECK_FALSE(backgroundOnlyRegion(w, 2, ex));               // no such region
  CHECK_FALSE(backgroundOnlyRegion(PositionWeights{}, 0, ex));  // no mask at all
}

TEST_CASE("a mask image: dark pixels inside, image row 0 at the top of the grid", "[synthesis][constraints][mask]") {
  // A 2 x 4 plain PGM whose only dark pixel is the top-left one, on a 2 x 4 x 2 grid: one
  // pixel a cell, pixel (px, py) for cell (x, y) is (x, 3 - y), so only cells (0, 3, z)
  // are inside: indices 6 and 14.
  // Kills "lum > 128.0" (the mask inverted): every other cell inside, those two outside;
  // and "int((y + 0.5) * img.height / size.ny)" (read upside down): py = y, so the dark
  // pixel lands on cells (0, 0, z), indices 0 and 8.
  const auto dir = fgsg::test::scratchDir("synthesis", "mask-image");
  const std::string path = (dir / "corner.pgm").string();
  std::ofstream(path) << "P2\n2 4\n255\n0 255\n255 255\n255 255\n255 255\n";
  const Example ex = load("roads.json");
  const GridSize n{2, 4, 2};
  PositionWeights w;
  std::string error;
  REQUIRE(maskFromImage(path, n, ex, 4.0, w, error));
  std::vector<uint16_t> expected(16, 0);
  expected[6] = expected[14] = 1;
  CHECK(at(n, 0, 3, 0) == 6);
  CHECK(at(n, 0, 3, 1) == 14);
  CHECK(w.region == expected);
  // Stretched over a larger grid: 4 x 8 cells on the same 2 x 4 pixels, pixel
  // (int((x + 0.5) / 2), int((7 - y + 0.5) / 2)): the dark pixel covers x < 2, y >= 6.
  const GridSize big{4, 8, 1};
  REQUIRE(maskFromImage(path, big, ex, 4.0, w, error));
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 4; ++x) {
      INFO("cell " << x << ", " << y);
      CHECK(w.region[size_t(at(big, x, y))] == ((x < 2 && y >= 6) ? 1 : 0));
    }
}
