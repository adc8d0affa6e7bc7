// Cells(...){ Feature } and its pattern generators: feature-based cellular texturing
// (Legakis et al. 2001, runtime/cells/). Cells builds the base mesh — an annotated OBJ
// file (its groups label the features; Z up, turned to fgsg's Y up) placed at the
// shape's position, the pieces a base part { Base | Feature } splits the shape into
// (labelled by their symbols), or the shape's own box (open at the bottom) — and derives
// its feature tree once per feature, corners first, then edges, then faces (§4), each
// on the spot, so that a feature's cells are placed before the next feature reads the
// occupancy maps. Inside, `Feature.edge`, `Feature.label("window")` ...
// (feature()) let rules pick a pattern per feature, the way the paper's pattern trees do,
// and BrickBond (English-, Flemish-, HeaderBond) / HeaderRow / ArchBricks / RandomStones
// / Shingles place cells on the current feature: each cell a shape of the generator's
// body symbol (its scope the cell, shrunk by the mortar joint), or a box when there is
// no body. A mortar surface (the base mesh grown by `mortar`) fills the joints.
#pragma once

#include "backend/commands/command_family.h"
#include "runtime/cells/base_mesh_file.h"
#include "runtime/cells/base_mesh_pieces.h"
#include "runtime/cells/cellular_texture.h"
#include "runtime/random.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace fgsg::backend {

class Derivation;

class CellsCommand final : public CommandFamily {
 public:
  explicit CellsCommand(Derivation& derivation) : d_(derivation) {}

  std::vector<ir::OpKind> kinds() const override { return {ir::OpKind::Cells, ir::OpKind::CellPattern}; }
  void apply(const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex, Frame& f) override;
  // Feature.member of the feature being textured (R026 outside Cells).
  double feature(const std::string& member, const std::string& arg, ir::Loc at) const;

 private:
  struct Active {
    rt::cells::CellularTexture* texture;
    rt::cells::FeatureRef feature;
    double joint;
    rt::RandomStream* rng;
    std::vector<int> facesLaid;  // faces a generator ran on: their coverage is counted
  };
  void texture(const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex, Frame& f);
  void pattern(const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex, Frame& f);
  rt::cells::LabelledMesh baseMesh(const ir::Op& op, State& st, Exec& ex, Frame& f);
  rt::cells::LabelledMesh basePart(const ir::Op& op, State& st, Exec& ex, Frame& f);
  rt::Scope featureScope(const rt::cells::CellularTexture& tex, rt::cells::FeatureRef ref) const;
  uint32_t cellAsset();
  // Places one output cell (shrunk) as the generator's body shape or, without a body, as
  // the cell asset; a clipped cell's cube is drawn as its prism.
  void placeCell(const rt::cells::Cell& cell, const ir::Op& op, State& st, Exec& ex, Frame& f);

  Derivation& d_;
  std::vector<Active> active_;  // Cells inside Cells nest
  std::map<std::string, std::shared_ptr<const rt::cells::LabelledMesh>> files_;
  uint32_t cellAsset_ = UINT32_MAX;
  int mortars_ = 0;
};

}  // namespace fgsg::backend
