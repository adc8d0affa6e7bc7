// The input of model synthesis: the labels (each a model piece: an asset, its rotation and
// mirroring) and the adjacency rules between them, in one form whatever the source was
// (an example grid, a WFC-style tile set, a labelled image). The rules are kept as plain
// (b, c) pairs per axis; the solver compiles them into transition matrices and the
// independent checker reads them directly.
#pragma once

#include "runtime/synthesis/diagnostic.h"
#include "runtime/synthesis/label_grid.h"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace fgsg::rt::synthesis {

struct Piece {
  std::string name;        // the label as written in grids ("W", "road", "ff8800")
  std::string asset;       // asset placed for it; "" (written "none") places nothing
  int rotation = 0;        // quarter turns counter-clockwise about +z applied to the asset
  bool mirrored = false;   // asset mirrored in x before it is rotated
  bool hasColor = false;
  std::array<float, 3> color{0.8f, 0.8f, 0.8f};
  double weight = 1.0;     // relative probability of being chosen (example frequency)
  bool background = false; // may appear outside a mask (empty space, ground)
  bool connect = false;    // belongs to the objects the connectivity constraint keeps whole
};

// The six faces of the grid box, in the order of the direction slots (+x is slot 0 whose
// "outside" is XMax).
enum Face : int { kXMin = 0, kXMax = 1, kYMin = 2, kYMax = 3, kZMin = 4, kZMax = 5 };
const char* faceName(int face);
int faceFromName(std::string_view name);  // -1 when unknown

// Border constraints (thesis §3.3.6, "labeling the boundaries"): per face either the label
// of a virtual cell just outside the face (the face cells must be able to sit next to it:
// "the model is surrounded by empty space / stands on ground"), or a label every cell of
// the face layer is fixed to. -1 means unconstrained.
struct BorderSpec {
  std::array<int32_t, 6> outside{-1, -1, -1, -1, -1, -1};
  std::array<int32_t, 6> fixed{-1, -1, -1, -1, -1, -1};
  // Labels allowed on the face layer (empty = any). closedLikeExample() fills these with
  // the labels on the example's own faces, so objects end where the example's end.
  std::array<std::vector<int32_t>, 6> only;
  bool any() const {
    for (int f = 0; f < 6; ++f)
      if (outside[f] >= 0 || fixed[f] >= 0 || !only[f].empty()) return true;
    return false;
  }
};


struct Example {
  std::string path;           // where it was read from (for messages and asset lookup)
  std::vector<Piece> labels;  // label id = index
  // Adjacency rules (eq. 3.2): allowed[a] holds (b, c) when c may lie at +axis a of b.
  std::array<std::vector<std::pair<int32_t, int32_t>>, 3> allowed;
  int dims = 3;               // 2: a planar example (no z rules; outputs have nz = 1)
  int32_t emptyLabel = -1;    // the label of the trivial initial solution (empty space)
  // Label maps for symmetry constraints (§3.5.2): the label a piece becomes when the model
  // is mirrored in x / mirrored in y / turned 90° about z. Empty = every piece maps to itself.
  std::vector<int32_t> mirrorX, mirrorY, rot90;
  BorderSpec border;          // defaults declared by the example file
  std::optional<LabelGrid> grid;  // the example model when it was given as a grid or image

  int labelCount() const { return int(labels.size()); }
  int32_t findLabel(std::string_view name) const;  // -1 when unknown
};

// `only` per face = the labels found on that face of the example grid (a planar example
// leaves zmin/zmax alone). Without an example grid: empty/background labels.
BorderSpec closedLikeExample(const Example& ex, BorderSpec base = {});

// Fills `allowed` from ex.grid (eq. 3.2), and weights from label frequencies unless the file
// gave explicit weights (weight < 0 marks "not given" while loading).
void computeAdjacencyFromGrid(Example& ex);

// Reads an example by extension: .json tile set, .png labelled image, anything else the
// label-grid text format. Never throws; false with diagnostics on bad input.
bool loadExample(const std::string& path, Example& out, Diagnostics& diags);

// The label-grid text format (docs/synthesis.md). `fileName` is used in diagnostics.
bool parseExampleText(std::string_view text, const std::string& fileName, Example& out,
                      Diagnostics& diags);
// Writes `grid` with the label table of `ex` in the same format (readable by
// parseExampleText: a round trip gives the same grid and labels).
std::string writeLabelGridText(const LabelGrid& grid, const Example& ex);

// WFC-style tile set (JSON): tiles with symmetry classes X L T I \ F and neighbour lists.
bool parseTileSetJson(std::string_view text, const std::string& fileName, Example& out,
                      Diagnostics& diags);

// A labelled example image (PNG): each distinct colour is a label, nz = 1, rows top-down
// (image row 0 is y = ny-1). The top-left pixel's colour is the empty label.
bool loadExampleImage(const std::string& path, Example& out, Diagnostics& diags);

}  // namespace fgsg::rt::synthesis
