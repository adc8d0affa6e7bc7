#include "cli/view_paint.h"

#include "runtime/io/atomic_file.h"
#include "runtime/io/find_file.h"
#include "runtime/io/png_encode.h"
#include "runtime/texture/texture_map.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

namespace fgsg::cli {

namespace fs = std::filesystem;
using rt::Vec3;
using Vec2 = rt::marching::Vec2;

namespace {

// Why `file` may not be written from the page, or "" when it may.
std::string unwritable(const fs::path& file, const fs::path& grammarDir) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext != ".png") return "it is not a .png file (fgsg view writes PNG only)";
  std::error_code ec;
  const fs::file_status link = fs::symlink_status(file, ec);
  if (ec || !fs::exists(link)) return "its file " + file.string() + " does not exist";
  if (fs::is_symlink(link)) return "its file " + file.string() + " is a symbolic link";
  if (!fs::is_regular_file(link)) return "its file " + file.string() + " is not a regular file";
  const fs::path real = fs::canonical(file, ec);
  if (ec) return "cannot resolve " + file.string();
  const fs::path inside = real.lexically_relative(grammarDir);
  if (inside.empty() || *inside.begin() == "..")
    return "its file " + real.string() + " lies outside the grammar's folder " + grammarDir.string();
  return "";
}

// The corners of face f in texel units, v up (TextureMap's convention: texel column i,
// row j from the top is centred at ((i + 0.5) / W, 1 - (j + 0.5) / H)).
void texelCorners(const rt::marching::MarchingSurface& s, int f, int width, int height, Vec2 uv[3]) {
  for (int k = 0; k < 3; ++k) {
    Vec3 corner = Vec3::Zero();
    corner[k] = 1;
    const Vec2 t = s.texCoord({f, corner});
    uv[k] = Vec2(t.x() * width, t.y() * height);
  }
}

// Calls visit(column, row, barycentric) for each texel whose centre lies in the triangle.
template <class Visit>
void rasterize(const Vec2 uv[3], int width, int height, Visit visit) {
  const double area = (uv[1] - uv[0]).x() * (uv[2] - uv[0]).y() - (uv[1] - uv[0]).y() * (uv[2] - uv[0]).x();
  if (area == 0 || !std::isfinite(area)) return;
  const int x0 = std::max(0, static_cast<int>(std::floor(std::min({uv[0].x(), uv[1].x(), uv[2].x()}))));
  const int x1 = std::min(width - 1, static_cast<int>(std::ceil(std::max({uv[0].x(), uv[1].x(), uv[2].x()}))));
  const int y0 = std::max(0, static_cast<int>(std::floor(std::min({uv[0].y(), uv[1].y(), uv[2].y()}))));
  const int y1 = std::min(height - 1, static_cast<int>(std::ceil(std::max({uv[0].y(), uv[1].y(), uv[2].y()}))));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const Vec2 p(x + 0.5, y + 0.5);
      auto edge = [&](const Vec2& a, const Vec2& b) {
        return ((b - a).x() * (p - a).y() - (b - a).y() * (p - a).x()) / area;
      };
      const Vec3 bary(edge(uv[1], uv[2]), edge(uv[2], uv[0]), edge(uv[0], uv[1]));
      if (bary.minCoeff() < -1e-9) continue;
      visit(x, height - 1 - y, bary);
    }
}

}  // namespace

void ViewPaint::reset(const ir::Module& module, const std::string& grammarPath, const std::vector<std::string>& dataDirs,
                      std::shared_ptr<const rt::marching::MarchingSurface> surface) {
  surface_ = std::move(surface);
  std::vector<Texture> before = std::move(textures_);
  textures_.clear();
  std::error_code ec;
  const fs::path grammarDir = fs::weakly_canonical(fs::absolute(grammarPath).parent_path(), ec);
  for (const ir::EnvDecl& env : module.environment) {
    if (env.kind != "texture") continue;
    Texture t;
    t.name = env.name;
    t.file = fs::absolute(rt::io::findFile(env.detail, dataDirs), ec).lexically_normal().string();
    t.why = surface_ ? unwritable(t.file, grammarDir) : "the grammar has no surface to paint on";
    rt::texture::TextureMap map;
    std::string error;
    if (t.why.empty() && !map.load(t.file, error)) t.why = error;
    if (t.why.empty()) {
      t.width = map.width();
      t.height = map.height();
      t.grey.resize(size_t(t.width) * size_t(t.height));
      for (int row = 0; row < t.height; ++row)
        for (int col = 0; col < t.width; ++col)
          t.grey[size_t(row) * t.width + col] = static_cast<uint8_t>(std::lround(map.texel(col, row) * 255));
      t.original = t.grey;
    }
    textures_.push_back(std::move(t));
  }
  keepHistory(before);
}

void ViewPaint::keepHistory(const std::vector<Texture>& before) {
  // A recompile (the grammar edited, any file in its folder written, as `fgsg run -o` does)
  // loads the textures again. One whose file still holds what was last painted or loaded
  // keeps its strokes: clearing them made the page's Undo refuse after such a recompile
  // (#49). One changed outside, resized, renamed or no longer paintable loses them.
  std::vector<size_t> now(before.size(), SIZE_MAX);
  for (size_t k = 0; k < before.size(); ++k)
    for (size_t j = 0; j < textures_.size(); ++j) {
      Texture& t = textures_[j];
      const Texture& old = before[k];
      if (t.why.empty() && old.why.empty() && t.name == old.name && t.file == old.file && t.grey == old.grey) {
        t.original = old.original;  // erase still goes back to the texels before any stroke
        now[k] = j;
      }
    }
  const auto remap = [&](std::vector<Step>& steps) {
    std::vector<Step> kept;
    for (Step& s : steps)
      if (now[s.texture] != SIZE_MAX) kept.push_back({now[s.texture], std::move(s.grey)});
    steps = std::move(kept);
  };
  remap(undo_);
  remap(redo_);
  if (strokeOpen_ && now[strokeTexture_] != SIZE_MAX) strokeTexture_ = now[strokeTexture_];
  else strokeOpen_ = false;
}

void ViewPaint::coverage(Texture& t) const {
  if (!t.covered.empty()) return;
  t.covered.assign(t.grey.size(), 0);
  for (int f = 0; f < static_cast<int>(surface_->mesh().faceCount()); ++f) {
    Vec2 uv[3];
    texelCorners(*surface_, f, t.width, t.height, uv);
    rasterize(uv, t.width, t.height, [&](int x, int row, const Vec3&) { t.covered[size_t(row) * t.width + x] = 1; });
  }
}

bool ViewPaint::write(Texture& t, std::string& reason) {
  std::string png;
  if (!rt::io::encodePng(t.width, t.height, 1, t.grey.data(), png)) {
    reason = "paint: cannot encode texture '" + t.name + "' as PNG";
    return false;
  }
  if (!rt::io::writeFileAtomically(t.file, png, reason)) {
    reason = "paint: " + reason;
    return false;
  }
  return true;
}

bool ViewPaint::paint(const PagePaint& stroke, std::string& writtenFile, std::string& reason) {
  size_t index = textures_.size();
  for (size_t k = 0; k < textures_.size(); ++k)
    if (textures_[k].name == stroke.texture) index = k;
  if (index == textures_.size()) {
    reason = "paint: the grammar declares no texture '" + stroke.texture + "'";
    return false;
  }
  Texture& t = textures_[index];
  if (!t.why.empty()) {
    reason = "paint: texture '" + t.name + "' cannot be painted: " + t.why;
    return false;
  }
  const std::vector<uint8_t> before = t.grey;
  coverage(t);
  const auto& mesh = surface_->mesh();
  std::vector<size_t> touched;
  for (const auto& dab : stroke.dabs) {
    const Vec3 c(dab[0], dab[1], dab[2]);
    for (int f = 0; f < static_cast<int>(mesh.faceCount()); ++f) {
      const Vec3& a = mesh.vertices[mesh.faces[f][0]];
      const Vec3& b = mesh.vertices[mesh.faces[f][1]];
      const Vec3& d = mesh.vertices[mesh.faces[f][2]];
      // Far faces first: no corner within the radius and the centre not near the face.
      const Vec3 centre = (a + b + d) / 3;
      const double reach = std::max({(a - centre).norm(), (b - centre).norm(), (d - centre).norm()});
      if ((centre - c).norm() > stroke.radius + reach) continue;
      Vec2 uv[3];
      texelCorners(*surface_, f, t.width, t.height, uv);
      rasterize(uv, t.width, t.height, [&](int x, int row, const Vec3& l) {
        if ((l[0] * a + l[1] * b + l[2] * d - c).norm() > stroke.radius) return;
        const size_t i = size_t(row) * t.width + x;
        const double target = stroke.erase ? t.original[i] : stroke.value * 255;
        t.grey[i] = static_cast<uint8_t>(std::lround(t.grey[i] + (target - t.grey[i]) * stroke.strength));
        touched.push_back(i);
      });
    }
  }
  // Texels no face covers but bilinear sampling at a chart's edge reads take the value of
  // the painted texel beside them (two rings, as paintMask's gutter).
  for (const size_t i : touched) {
    const int x = static_cast<int>(i % t.width), y = static_cast<int>(i / t.width);
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx) {
        const int nx = x + dx, ny = y + dy;
        if (nx < 0 || ny < 0 || nx >= t.width || ny >= t.height) continue;
        const size_t n = size_t(ny) * t.width + nx;
        if (!t.covered[n]) t.grey[n] = t.grey[i];
      }
  }
  if (!write(t, reason)) {
    t.grey = before;
    return false;
  }
  // The pieces of one stroke are one undo step: the texels before its first piece.
  if (!strokeOpen_ || stroke.stroke != stroke_ || index != strokeTexture_) {
    undo_.push_back({index, before});
    size_t bytes = 0;
    for (const Step& s : undo_) bytes += s.grey.size();
    while (undo_.size() > kMaxUndoStrokes || (bytes > kMaxUndoBytes && undo_.size() > 1)) {
      bytes -= undo_.front().grey.size();
      undo_.erase(undo_.begin());
    }
    redo_.clear();
    strokeOpen_ = true;
    stroke_ = stroke.stroke;
    strokeTexture_ = index;
  }
  writtenFile = t.file;
  return true;
}

bool ViewPaint::swap(std::vector<Step>& from, std::vector<Step>& to, std::string& writtenFile, std::string& reason) {
  strokeOpen_ = false;  // the next piece starts a new stroke
  if (from.empty()) return false;
  Step step = std::move(from.back());
  from.pop_back();
  Texture& t = textures_[step.texture];
  std::swap(t.grey, step.grey);
  if (!write(t, reason)) {
    std::swap(t.grey, step.grey);
    from.push_back(std::move(step));
    return false;
  }
  to.push_back(std::move(step));
  writtenFile = t.file;
  return true;
}

bool ViewPaint::undo(std::string& writtenFile, std::string& reason) {
  if (swap(undo_, redo_, writtenFile, reason)) return true;
  if (reason.empty()) reason = "undo: no stroke to undo";
  return false;
}

bool ViewPaint::redo(std::string& writtenFile, std::string& reason) {
  if (swap(redo_, undo_, writtenFile, reason)) return true;
  if (reason.empty()) reason = "redo: no stroke to redo";
  return false;
}

}  // namespace fgsg::cli
