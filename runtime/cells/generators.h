// Pattern generators (Legakis et al. 2001, §4–5): each places cells on one feature of
// the base mesh, reading and filling the occupancy maps (cellular_texture.h). A pattern
// tree (in a grammar: rules over features, docs/cells.md) picks which generator each
// feature gets. All of them return the number of cells they placed.
//
//   bricks       corners: a block where three faces meet square; vertical edges: one
//                brick per course, running along the left and the right face in turn
//                (the corner bond; `flip` starts with the right one); other edges: a
//                row of stretchers along the edge; faces: courses shared by every wall,
//                in the size's bond (below).
//   headers      edges: a row of blocks along the edge on its more vertical face (a
//                header row under a window); corners and faces: nothing.
//   archBricks   arc edges: voussoirs radial to the arc, as wide as a course at the
//                intrados; other features: as bricks.
//   shingles     faces: rows of tiles from the face's lowest edge (the eaves) up, joints
//                on a grid of the tile width across the face, odd rows shifted by half a
//                tile (runs start with a cut tile); non-vertical edges (ridges, hips): a
//                row of ridge tiles along the edge; corners and vertical edges: nothing.
//   stones       corners: a block; vertical edges: stones of random height and length
//                along the left and right face in turn; other edges: random lengths;
//                faces: grid squares merged at random into rectangles no larger than the
//                maximum size (§5 "Random").
#pragma once

#include "runtime/cells/cellular_texture.h"
#include "runtime/random.h"

namespace fgsg::rt::cells {

// How a face's courses are laid (§4's bonds). A stretcher shows the brick's side
// (`length`), a header its end (as wide as the brick's `depth`); a closer is the cut
// brick that starts an odd course at a free end so that the joints do not line up.
//   Running   stretchers; odd courses start with a half brick.
//   English   stretcher and header courses in turn; header courses start with a quarter
//             brick (half a header), so headers sit over stretchers' middles and joints.
//   Flemish   stretcher, header, stretcher ... in every course; odd courses start with a
//             closer of (length - depth) / 2 and a header, so each header sits on the
//             middle of a stretcher.
//   Header    headers; odd courses start with half a header.
enum class Bond { Running, English, Flemish, Header };

struct BrickSize {
  double length = 0.215, height = 0.075, depth = 0.1025;
  bool flip = false;  // the paper's stored bit: which face a corner's first course runs along
  Bond bond = Bond::Running;
};

struct TileSize {
  double width = 0.3, exposure = 0.2, thickness = 0.03;  // a row shows `exposure` of each tile
};

struct StoneSize {
  double grid = 0.1, maxWidth = 0.4, maxHeight = 0.3, depth = 0.12;
};

int layBricks(CellularTexture& tex, FeatureRef on, const BrickSize& size);
int layHeaders(CellularTexture& tex, FeatureRef on, const BrickSize& size);
int layArchBricks(CellularTexture& tex, FeatureRef on, const BrickSize& size);
int layStones(CellularTexture& tex, FeatureRef on, const StoneSize& size, RandomStream& rng);
int layShingles(CellularTexture& tex, FeatureRef on, const TileSize& size);

// Throws std::invalid_argument naming the first size that is not a positive finite
// number (or a stone maximum below the grid).
void checkSize(const BrickSize& size);
void checkSize(const StoneSize& size);
void checkSize(const TileSize& size);

}  // namespace fgsg::rt::cells
