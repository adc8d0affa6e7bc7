// Constraints beyond adjacency (§3.3.6 borders, §3.5.2 symmetry, §3.5.3 per-position
// probabilities and large-scale masks, §4.6.2 connectivity), as plain values the solver
// and the independent checker both read.
#pragma once

#include "runtime/synthesis/example.h"

#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::rt::synthesis {

// M(σ(p)) = f(M(p)) for every cell p (σ(p) inside the grid), f taken from the example's
// label maps. Mirror planes and rotation centres are the middle of the grid.
struct SymmetrySpec {
  enum Kind { kMirrorX, kMirrorY, kRotate90, kRotate180, kTranslateX, kTranslateY } kind;
  int offset = 0;  // translation distance in cells (Translate*)
};
const char* symmetryName(SymmetrySpec::Kind k);
constexpr int kMaxTranslation = 1 << 20;  // N of translate-x:N / translate-y:N
bool parseSymmetry(const std::string& text, SymmetrySpec& out);  // "mirror-x", "translate-x:8", ...

// σ(p) for one cell; -1 when σ(p) leaves the grid (translations) or the grid does not
// admit the symmetry (rotate-90 needs nx == ny).
int64_t symmetryImage(const SymmetrySpec& s, const GridSize& size, int64_t cell);
// f as a vector (identity when the example declares no map).
std::vector<int32_t> symmetryLabelMap(const SymmetrySpec& s, const Example& ex);

// Per-position label probabilities (§3.5.3) in a compact form: each cell belongs to a
// region, each region scales the label weights; a factor of 0 removes the label there.
// An empty `region` puts every cell in region 0.
struct PositionWeights {
  std::vector<uint16_t> region;                // per cell
  std::vector<std::vector<double>> factor;     // [region][label]
  bool empty() const { return factor.empty(); }
  double at(int64_t cell, int label) const {
    if (factor.empty()) return 1.0;
    const auto& f = factor[region.empty() ? 0 : region[size_t(cell)]];
    return f[size_t(label)];
  }
};

// Whether the cells of `region` may hold background labels only (a mask's outside, where
// no object stands). A face's `only` labels (--closed) do not bind there: no object
// crosses the face where none may stand, and the example's face labels need not be
// background (the city's streets along its sides), which would leave such cells no label.
bool backgroundOnlyRegion(const PositionWeights& w, size_t region, const Example& ex);

// A large-scale mask from an image (a letter, a symbol): dark pixels are "inside". The image
// is stretched over the grid's x-y extent (all layers alike; image row 0 is y = ny-1).
// Outside, only background labels may appear; inside, non-background labels are weighted
// by `insideBoost`.
bool maskFromImage(const std::string& path, const GridSize& size, const Example& ex,
                   double insideBoost, PositionWeights& out, std::string& error);
// The same from a boolean inside-grid (nx*ny, row-major, y = 0 first).
PositionWeights maskFromCells(const std::vector<uint8_t>& inside, const GridSize& size,
                              const Example& ex, double insideBoost);

// Connectivity (§4.6.2): the cells carrying `connect` labels grow from `seeds` seed cells,
// so they form at most `seeds` 6-connected groups.
struct ConnectivitySpec {
  bool enabled = false;
  int seeds = 1;
  std::vector<uint8_t> labels;  // per label; empty: the example's `connect` flags
};

}  // namespace fgsg::rt::synthesis
