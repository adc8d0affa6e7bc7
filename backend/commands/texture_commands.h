// Texture("brick.png", w, h): CGA's materials. The command sets up a projection in the
// scope it runs in (runtime/cga/uv_projection.h) that the shapes derived from it inherit;
// each leaf output below it gets texture coordinates from that projection and draws the
// image. The image files are found and checked before anything is derived, so a missing
// or unreadable one is reported at its Texture(). Texture("none") takes the image away.
#pragma once

#include "backend/commands/command_family.h"
#include "runtime/cga/uv_projection.h"

#include <string>
#include <vector>

namespace fgsg::backend {

// Texture("none"): the leaves from here on are drawn untextured again (a door in a brick wall).
inline constexpr const char* kNoTexture = "none";

class TextureCommands final : public CommandFamily {
 public:
  std::vector<ir::OpKind> kinds() const override { return {ir::OpKind::Texture}; }
  void apply(const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex, Frame& f) override;

  // Finds every image the module's Texture commands name in `dirs` and checks it is a PNG
  // or JPEG; throws DeriveError (R003) at the first Texture whose image is not.
  void prepare(const ir::Module& m, const std::vector<std::string>& dirs);
  // A seed plant's derivation uses its parent's images (their paths and numbering).
  void shareFrom(const TextureCommands& parent) { paths_ = parent.paths_, textureOf_ = parent.textureOf_; }

  // The images' paths, numbered as Instance::texture counts them.
  const std::vector<std::string>& paths() const { return paths_; }
  // The projection a scope's `projection` (non-zero) names.
  const rt::cga::UvProjection& projection(uint32_t scopeProjection) const {
    return projections_[scopeProjection - 1];
  }

 private:
  std::vector<std::string> paths_;
  std::vector<uint32_t> textureOf_;  // per module string id: its index in paths_ (Texture's file)
  std::vector<rt::cga::UvProjection> projections_;
};

}  // namespace fgsg::backend
