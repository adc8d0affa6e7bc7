// Painting a grammar's texture contexts from fgsg view's page (#49): brush strokes laid
// on the surface move texels toward a grey value, and the texture's file is written
// (8-bit grey PNG, atomically) so the next derivation — and any later run — reads it.
//
// Only the grammar's own declared textures can be painted, named by their grammar name,
// and only when the file they resolve to is a PNG inside the grammar's folder (its
// canonical path, so no '..' or symlink leads out) and not itself a symlink: the page
// never names a path. Undo and redo step through whole strokes.
#pragma once

#include "cli/view_message.h"
#include "ir/ir.h"
#include "runtime/marching/marching_surface.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace fgsg::cli {

// Undo keeps at most this many strokes, and at most this many bytes of images.
constexpr size_t kMaxUndoStrokes = 64;
constexpr size_t kMaxUndoBytes = size_t(256) << 20;

class ViewPaint {
 public:
  struct Texture {
    std::string name;   // as the grammar declares it
    std::string file;   // where it is read and written
    std::string why;    // empty: paintable; else why not
    int width = 0, height = 0;
    std::vector<uint8_t> grey, original;  // rows top to bottom; `original` as loaded (erase)
    std::vector<uint8_t> covered;          // 1 where a texel's centre lies in a face's UVs
  };

  // The textures `module` declares, looked up in `dataDirs` as a derivation does, loaded
  // when paintable. `surface` may be null (nothing is paintable then). Undo and redo
  // keep the strokes of each texture whose file is unchanged since it was last painted.
  void reset(const ir::Module& module, const std::string& grammarPath, const std::vector<std::string>& dataDirs,
             std::shared_ptr<const rt::marching::MarchingSurface> surface);
  // Applies a piece of a stroke and writes the texture's file. False with a reason and
  // nothing changed (an unknown or unpaintable texture, a file that cannot be written).
  bool paint(const PagePaint& stroke, std::string& writtenFile, std::string& reason);
  // The last stroke undone / redone, its file written. False when there is none.
  bool undo(std::string& writtenFile, std::string& reason);
  bool redo(std::string& writtenFile, std::string& reason);

  const std::vector<Texture>& textures() const { return textures_; }

 private:
  struct Step {
    size_t texture;
    std::vector<uint8_t> grey;  // the texels before (undo) or after (redo) the stroke
  };
  bool write(Texture& t, std::string& reason);
  void keepHistory(const std::vector<Texture>& before);  // reset(): strokes of unchanged textures
  bool swap(std::vector<Step>& from, std::vector<Step>& to, std::string& writtenFile, std::string& reason);
  void coverage(Texture& t) const;

  std::shared_ptr<const rt::marching::MarchingSurface> surface_;
  std::vector<Texture> textures_;
  std::vector<Step> undo_, redo_;
  bool strokeOpen_ = false;
  uint64_t stroke_ = 0;
  size_t strokeTexture_ = 0;
};

}  // namespace fgsg::cli
