// On-mesh marching (Buron et al. 2015): `Marching(length, angle, cond[, smoothness]){ Top, Extruded }`
// walks the scope along the surface through its indirection geometry image (§5), tries
// other directions on the half circle ahead when `cond` fails at the destination (§8),
// and derives Top at the destination before Extruded on the segment (§6's depth-first
// order); `Branch(n){ A, B }` splits a march into n. Texture contexts
// (`context.mask(texCoord)`, §4) are sampled here too: they share the surface's texture
// coordinates. Every march point and segment is kept as a graph, from which the smooth
// terminals' Bezier curves are built once the derivation ends (§6).
#pragma once

#include "backend/commands/command_family.h"
#include "backend/commands/march_tally.h"
#include "runtime/instances.h"
#include "runtime/marching/march_graph.h"
#include "runtime/scope.h"

#include <memory>
#include <string>
#include <vector>

namespace fgsg::rt::marching {
class MarchingSurface;
}
namespace fgsg::rt::texture {
class TextureMap;
}

namespace fgsg::backend {

class Derivation;

class MarchingCommands final : public CommandFamily {
 public:
  explicit MarchingCommands(Derivation& derivation);
  ~MarchingCommands() override;

  std::vector<ir::OpKind> kinds() const override;
  void apply(const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex, Frame& f) override;

  // Before deriving: loads the grammar's textures (a missing or unreadable one is an
  // error at its declaration).
  void loadTextures();
  // Lays the surface out for marching now rather than at the first march (an error is
  // kept and thrown where a march or texture query first needs the surface).
  void prepareSurface();
  // Uses `other`'s textures and prepared surface (a seed plant's derivation shares its
  // parent's; both are only read once prepared).
  void shareFrom(const MarchingCommands& other);
  // `count` surface points drawn with a density proportional to texture `name` (a
  // declared texture; R022/R023 otherwise) times the area, from `key`: --seed-density.
  std::vector<rt::Vec3> densitySeeds(const std::string& name, uint32_t count, uint64_t key);
  // context.NAME(texCoord) at the scope's surface point.
  double sampleTexture(const rt::Scope& scope, uint32_t env, ir::Loc at);
  // The texels a derivation read, by tiles of kTextureTile x kTextureTile texels: a kept
  // seed plant (seed_plants.cpp) is taken again only while those texels are unchanged.
  static constexpr int kTextureTile = 8;
  struct TextureTiles {
    int columns = 0, rows = 0;  // tiles across and down
    std::vector<uint64_t> bits;  // tile (c, r) at bit r * columns + c
  };
  void recordTextureReads() { recordReads_ = true; }
  const std::vector<TextureTiles>& textureReads() const { return reads_; }  // by environment index
  const std::vector<std::shared_ptr<const rt::texture::TextureMap>>& textures() const { return textures_; }
  // After deriving: the Bezier path of every march segment, indexed as the instances'
  // `curve` (runtime/instances.h).
  std::vector<rt::CurveSegment> curves() const;
  uint64_t marches() const { return tally_.marches; }
  uint64_t marchesStopped() const { return tally_.marches - tally_.steps; }
  // How the marches ended (a seed plant's join its parent's): for the R030 warning.
  const MarchTally& tally() const { return tally_; }
  void addTally(const MarchTally& plant) { tally_.add(plant); }

 private:
  const rt::marching::MarchingSurface& surface(ir::Loc at);
  void march(const ir::Op& op, const double* a, State& st, Exec& ex, Frame& f);
  void branch(const ir::Op& op, const double* a, State& st, Exec& ex, Frame& f);
  int32_t nodeAt(const rt::Scope& scope);
  static rt::Scope chord(const rt::Scope& from, const rt::Scope& to, int32_t segment);

  Derivation& d_;
  std::shared_ptr<const rt::marching::MarchingSurface> surface_;
  bool prepared_ = false;           // surface_ set, or why not in the two below
  std::string unpreparedCode_, unpreparedWhy_;
  std::vector<std::shared_ptr<const rt::texture::TextureMap>> textures_;  // by environment index
  std::vector<rt::marching::MarchNode> nodes_;
  std::vector<rt::marching::MarchSegment> segments_;
  bool condition_ = false;  // what the last MarchCondition said
  bool recordReads_ = false;
  std::vector<TextureTiles> reads_;
  void noteTextureRead(uint32_t env, double u, double v);
  MarchTally tally_;
};

}  // namespace fgsg::backend
