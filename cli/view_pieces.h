// A model of seeds derived apart, sent to fgsg view's pages a piece per seed (#49, item 5):
// each seed's plant is a scene of its own (.glb, as view_scene.h builds it), and what no
// seed placed (the surface, lines) one more piece after them. A seed dragged or a texture
// painted changes some plants only; a piece whose instances, reports and start are the
// same as the last derivation's is taken from it (not assembled nor encoded again), and a
// page is sent only the pieces it does not have.
#pragma once

#include "ir/ir.h"
#include "runtime/assets.h"
#include "runtime/derivation.h"

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace fgsg::cli {

struct ViewPiece {
  rt::InstanceList list;  // its instances, with their own params, curves and finishes
  std::vector<rt::Report> reports;  // its start shape's, `start` 0
  std::string glb;                  // the piece as .glb
  // Per node that places shared meshes: its index in the piece's nodes and its count;
  // `ids` their numbers in the piece's instances (the derivation's minus `base`).
  std::vector<std::pair<int, uint32_t>> placing;
  std::vector<uint32_t> ids;
  size_t triangles = 0;
};

struct ViewPieces {
  std::vector<std::shared_ptr<const ViewPiece>> pieces;  // a seed's each, then the rest
  std::vector<uint32_t> bases;  // per piece, the derivation's number of its first instance
  size_t triangles = 0;
  size_t built = 0;  // pieces assembled and encoded by this call (the others were the last's)
};

// True when `result` is a model of seeds derived apart (more than one start shape, as
// many as options.seeds) that fgsg view sends as pieces.
bool viewByPieces(const rt::DeriveOptions& options, const rt::DeriveResult& result);

// True when a piece of `pieces` embeds an image whose file is named as one of `files`
// (by file name: a texture's path may be spelt relative to the grammar). Its .glb holds
// the image's bytes as they were, which a paint stroke changes without a recompile.
bool viewPiecesEmbedAny(const ViewPieces& pieces, const std::vector<std::string>& files);

// The pieces of `result` (its assets resolved: meshOf); a piece equal to `last`'s at the
// same place (instances, params, curves, finishes, origins, reports: byte for byte) is
// taken from there. `last` must come from the same grammar, values and seed. False with a
// message as buildViewScene.
bool buildViewPieces(const ir::Module& module, const rt::DeriveOptions& options, const rt::DeriveResult& result,
                     const rt::AssetLibrary& assets, const std::vector<int>& meshOf, const ViewPieces& last,
                     ViewPieces& out, std::string& error);

}  // namespace fgsg::cli
