// Texture("brick.png", w, h): CGA's materials. The command sets up a projection in the
// scope it runs in (runtime/cga/uv_projection.h) that the shapes derived from it inherit;
// each leaf output below it gets texture coordinates from that projection and draws the
// image. The image files are found and checked before anything is derived, so a missing
// or unreadable one is reported at its Texture(). Texture("none") takes the image away.
//
// The same family applies CGA's material attributes (Material: roughness, metallic,
// opacity, the colour's and emissive colour's components, the texture layers' images; the
// scope's `finish`)
// and its uv operations (Uv: setupProjection, scaleUV, translateUV, rotateUV, tileUV,
// normalizeUV, each a new projection made from the scope's) on CityEngine's uv sets 0..9:
// the shapes carry a projection per set; the leaves are textured by set 0's.
#pragma once

#include "backend/commands/command_family.h"
#include "runtime/cga/uv_projection.h"
#include "runtime/instances.h"

#include <array>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace fgsg::backend {

// Texture("none"): the leaves from here on are drawn untextured again (a door in a brick wall).
inline constexpr const char* kNoTexture = "none";

class TextureCommands final : public CommandFamily {
 public:
  std::vector<ir::OpKind> kinds() const override { return {ir::OpKind::Texture, ir::OpKind::Material, ir::OpKind::Uv}; }
  void apply(const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex, Frame& f) override;

  // Finds every image the module's Texture and Material commands name in `dirs` and checks
  // it is a PNG or JPEG; throws DeriveError (R003) at the first command whose image is not.
  void prepare(const ir::Module& m, const std::vector<std::string>& dirs);
  // A seed plant's derivation uses its parent's images (their paths and numbering).
  void shareFrom(const TextureCommands& parent) {
    paths_ = parent.paths_, textureOf_ = parent.textureOf_, strings_ = parent.strings_;
  }

  // The images' paths, numbered as Instance::texture counts them.
  const std::vector<std::string>& paths() const { return paths_; }
  // The projection of uv set `set` (0..9) a scope's `projection` names; null: the set has none.
  const rt::cga::UvProjection* projection(uint32_t scopeProjection, uint32_t set = 0) const {
    const uint32_t p = projectionIndex(scopeProjection, set);
    return p ? &projections_[p - 1] : nullptr;
  }
  // The finishes a scope's `finish` (1 + index) names, and the one for `f` (0: the default).
  const std::vector<rt::Finish>& finishes() const { return finishes_; }
  const rt::Finish& finish(uint32_t scopeFinish) const { return scopeFinish ? finishes_[scopeFinish - 1] : kDefault_; }
  uint32_t internFinish(const rt::Finish& f);
  // How many projections the Texture, Material and Uv commands have made so far, and
  // `grow(list)` called on the lists they fill (the projections and their layouts, a
  // push per Texture: --lots reserves room for the rest of the lots, reserveForLots).
  size_t projectionCount() const { return projections_.size(); }
  template <class Grow>
  void reserveLists(Grow&& grow) {
    grow(projections_);
    grow(layouts_);
  }

 private:
  void material(const ir::Op& op, const double* a, State& st);
  void uv(const ir::Op& op, const double* a, State& st);
  uint32_t addProjection(const rt::cga::UvProjection& p);
  // A scope's `projection` is 1 + the index of its uv sets' layout (0: no set has one);
  // a layout holds, per uv set, 1 + the index of its projection (0: none).
  using UvLayout = std::array<uint32_t, ir::kUvSets>;
  uint32_t projectionIndex(uint32_t scopeProjection, uint32_t set) const {
    return scopeProjection ? layouts_[scopeProjection - 1][set] : 0;
  }
  // The scope's `projection` with set `set`'s projection (1 + index; 0: none) replaced.
  uint32_t withProjection(uint32_t scopeProjection, uint32_t set, uint32_t projection);

  std::vector<std::string> paths_;
  std::vector<uint32_t> textureOf_;  // per module string id: its index in paths_ (Texture's file)
  const std::vector<std::string>* strings_ = nullptr;  // the module's (Uv's axes and modes)
  std::vector<rt::cga::UvProjection> projections_;
  std::vector<UvLayout> layouts_;
  std::vector<rt::Finish> finishes_;
  std::map<rt::Finish, uint32_t> finishIndex_;
  static inline const rt::Finish kDefault_{};
};

}  // namespace fgsg::backend
