#include "backend/commands/texture_commands.h"

#include "runtime/io/find_file.h"
#include "runtime/texture/color_texture.h"

#include <cmath>
#include <functional>
#include <limits>

namespace fgsg::backend {

void TextureCommands::prepare(const ir::Module& m, const std::vector<std::string>& dirs) {
  textureOf_.assign(m.strings.size(), std::numeric_limits<uint32_t>::max());
  std::function<void(const ir::Block&)> visit = [&](const ir::Block& b) {
    for (const ir::Op& op : b) {
      if (op.kind == ir::OpKind::Texture && textureOf_[op.str] == std::numeric_limits<uint32_t>::max() &&
          m.strings[op.str] != kNoTexture) {
        const std::string path = rt::io::findFile(m.strings[op.str], dirs);
        std::string error;
        if (!rt::texture::ColorTexture::probe(path, error)) throw DeriveError{op.loc, "R003", "Texture: " + error};
        textureOf_[op.str] = static_cast<uint32_t>(paths_.size());
        paths_.push_back(path);
      }
      for (const ir::Block& body : op.bodies) visit(body);
    }
  };
  visit(m.axiom);
  for (const ir::Rule& r : m.rules)
    for (const ir::Alternative& alt : r.alternatives) visit(alt.ops);
}

void TextureCommands::apply(const ir::Op& op, const double* a, uint32_t n, State& st, Exec&, Frame&) {
  if (textureOf_.at(op.str) == std::numeric_limits<uint32_t>::max()) {  // Texture("none")
    st.scope.projection = 0;
    return;
  }
  const double width = n >= 2 ? a[0] : 0, height = n >= 2 ? a[1] : 0;
  for (double size : {width, height})
    if (!std::isfinite(size) || size < 0 || (n >= 2 && size == 0))
      throw DeriveError{op.loc, "R027",
                        "Texture: a tile size must be a positive number of metres, not " + std::to_string(size)};
  projections_.push_back(rt::cga::projectionAt(st.scope, width, height, textureOf_.at(op.str)));
  st.scope.projection = static_cast<uint32_t>(projections_.size());
}

}  // namespace fgsg::backend
