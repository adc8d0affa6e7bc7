#include "backend/commands/texture_commands.h"

#include "runtime/io/find_file.h"
#include "runtime/texture/color_texture.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace fgsg::backend {

namespace {

constexpr uint32_t kUnresolved = std::numeric_limits<uint32_t>::max();

// Whether `op` names an image file in op.str: Texture, Material's maps.
bool namesImage(const ir::Op& op) {
  return op.kind == ir::OpKind::Texture || (op.kind == ir::OpKind::Material && ir::materialPropertyIsImage(op.index));
}

// R027 unless x is a number.
double finiteArg(double x, const ir::Op& op, const char* what) {
  if (!std::isfinite(x))
    throw DeriveError{op.loc, "R027", op.name + ": " + what + " is not a number (a parameter became NaN or infinite)"};
  return x;
}

// (u, v) -> M (u, v): the 2x3 affine `m` after `t`.
std::array<double, 6> composeUv(const std::array<double, 6>& m, const std::array<double, 6>& t) {
  return {m[0] * t[0] + m[1] * t[3], m[0] * t[1] + m[1] * t[4], m[0] * t[2] + m[1] * t[5] + m[2],
          m[3] * t[0] + m[4] * t[3], m[3] * t[1] + m[4] * t[4], m[3] * t[2] + m[4] * t[5] + m[5]};
}

// A size of SetupProjection or TileUV: absolute, relative to `extent` (1r, CGA's '1) or
// floating (~w: the extent divided into whole tiles of about w).
double uvSize(const ir::Op& op, size_t k, double value, double extent) {
  finiteArg(value, op, "a tile size");
  switch (op.sizes[k].kind) {
    case ir::Size::Relative: return value * extent;
    case ir::Size::Floating: {
      if (value == 0 || !(extent > 0)) return value;
      const double tiles = std::max(1.0, std::round(extent / std::abs(value)));
      return std::copysign(extent / tiles, value);
    }
    default: return value;
  }
}

}  // namespace

void TextureCommands::prepare(const ir::Module& m, const std::vector<std::string>& dirs) {
  strings_ = &m.strings;
  textureOf_.assign(m.strings.size(), kUnresolved);
  std::function<void(const ir::Block&)> visit = [&](const ir::Block& b) {
    for (const ir::Op& op : b) {
      if (namesImage(op) && textureOf_[op.str] == kUnresolved && m.strings[op.str] != kNoTexture) {
        const std::string path = rt::io::findFile(m.strings[op.str], dirs);
        std::string error;
        if (!rt::texture::ColorTexture::probe(path, error)) throw DeriveError{op.loc, "R003", op.name + ": " + error};
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

uint32_t TextureCommands::internFinish(const rt::Finish& f) {
  if (f == kDefault_) return 0;
  const auto [it, added] = finishIndex_.emplace(f, uint32_t(finishes_.size() + 1));
  if (added) finishes_.push_back(f);
  return it->second;
}

uint32_t TextureCommands::addProjection(const rt::cga::UvProjection& p) {
  projections_.push_back(p);
  return static_cast<uint32_t>(projections_.size());
}

uint32_t TextureCommands::withProjection(uint32_t scopeProjection, uint32_t set, uint32_t projection) {
  UvLayout layout{};
  if (scopeProjection) layout = layouts_[scopeProjection - 1];
  layout[set] = projection;
  if (std::all_of(layout.begin(), layout.end(), [](uint32_t p) { return p == 0; })) return 0;
  layouts_.push_back(layout);
  return static_cast<uint32_t>(layouts_.size());
}

void TextureCommands::apply(const ir::Op& op, const double* a, uint32_t n, State& st, Exec&, Frame&) {
  if (op.kind == ir::OpKind::Material) return material(op, a, st);
  if (op.kind == ir::OpKind::Uv) return uv(op, a, st);
  if (textureOf_.at(op.str) == kUnresolved) {  // Texture("none")
    st.scope.projection = withProjection(st.scope.projection, 0, 0);
    return;
  }
  const double width = n >= 2 ? a[0] : 0, height = n >= 2 ? a[1] : 0;
  for (double size : {width, height})
    if (!std::isfinite(size) || size < 0 || (n >= 2 && size == 0))
      throw DeriveError{op.loc, "R027",
                        "Texture: a tile size must be a positive number of metres, not " + std::to_string(size)};
  st.scope.projection =
      withProjection(st.scope.projection, 0, addProjection(rt::cga::projectionAt(st.scope, width, height, textureOf_.at(op.str))));
}

// CGA's material attributes. Numbers are clamped to 0..1 as Color's are; a colour
// component starts from CityEngine's default white where no colour was set.
void TextureCommands::material(const ir::Op& op, const double* a, State& st) {
  const auto property = static_cast<ir::MaterialProperty>(op.index);
  using P = ir::MaterialProperty;
  if (property == P::ColorMap) {
    // texture(): the image of the scope's projection, its frame kept; none yet: one over the scope.
    const uint32_t image = textureOf_.at(op.str), current = projectionIndex(st.scope.projection, 0);
    if (current) {
      rt::cga::UvProjection p = projections_[current - 1];
      if (!p.setup) p.setup = current;
      p.texture = image == kUnresolved ? rt::cga::UvProjection::kNoImage : image;
      st.scope.projection = withProjection(st.scope.projection, 0, addProjection(p));
    } else if (image != kUnresolved) {
      st.scope.projection = withProjection(st.scope.projection, 0, addProjection(rt::cga::projectionAt(st.scope, 0, 0, image)));
    }
    return;
  }
  rt::Finish f = finish(st.scope.finish);
  if (ir::materialPropertyIsImage(op.index)) {
    // Another texture layer (bumpmap ... metallicmap): its image, "none" none.
    const uint32_t image = textureOf_.at(op.str);
    f.maps[ir::materialLayerOf(property)] = image == kUnresolved ? UINT32_MAX : image;
  } else {
    const float value = float(std::clamp(finiteArg(a[0], op, "the value"), 0.0, 1.0));
    switch (property) {
      case P::Roughness: f.roughness = value; break;
      case P::Metallic: f.metallic = value; break;
      case P::Opacity: f.opacity = value; break;
      case P::EmissiveR:
      case P::EmissiveG:
      case P::EmissiveB: f.emissive[size_t(op.index) - size_t(P::EmissiveR)] = value; break;
      default: {
        if (!st.scope.colored) st.scope.color = {1.0f, 1.0f, 1.0f};
        st.scope.color[size_t(op.index) - size_t(P::ColorR)] = value;
        st.scope.colored = true;
        return;
      }
    }
  }
  st.scope.finish = internFinish(f);
}

// CGA's uv operations, on the op's uv set: the scope's projection of that set (and so, for
// set 0, its leaves' texture coordinates) replaced by one made from it. Without a
// projection, or after deleteUV, only setupProjection (and projectUV after deleteUV) does
// something, as CityEngine's operations need projected coordinates. The image a
// projection carries is set 0's (the colour map's): a set's own stays with it.
void TextureCommands::uv(const ir::Op& op, const double* a, State& st) {
  const auto kind = static_cast<ir::UvOp>(op.index);
  const rt::Scope& s = st.scope;
  const uint32_t set = op.uvSet, current = projectionIndex(s.projection, set);
  const auto replace = [&](const rt::cga::UvProjection& p) {
    st.scope.projection = withProjection(s.projection, set, addProjection(p));
  };
  if (kind == ir::UvOp::Copy) {
    // copyUV(source, set): the set's coordinates become the source's (none: none), its image kept.
    const double source = finiteArg(a[0], op, "the source uv set");
    const uint32_t from = projectionIndex(s.projection, uint32_t(source));
    if (from == current) return;
    if (!from) {
      st.scope.projection = withProjection(s.projection, set, 0);
      return;
    }
    rt::cga::UvProjection p = projections_[from - 1];
    p.texture = current ? projections_[current - 1].texture : rt::cga::UvProjection::kNoImage;
    return replace(p);
  }
  if (kind == ir::UvOp::Setup) {
    // The scope's origin and the two of its axes the words name (u, v), or the world's
    // ("world.xz"); their cross product third. Relative and floating sizes measure the
    // scope's box along u and v (for the scope's axes: its sizes).
    const std::string& words = (*strings_)[op.str];
    const bool world = words.rfind("world.", 0) == 0;
    const std::string axes = world ? words.substr(6) : words;
    const int iu = axes[0] - 'x', iv = axes[1] - 'x';
    const rt::Mat3 frame = world ? rt::Mat3::Identity() : s.axes;
    rt::cga::UvProjection p;
    p.origin = world ? rt::Vec3::Zero() : s.P;
    p.axes.col(0) = frame.col(iu);
    p.axes.col(1) = frame.col(iv);
    p.axes.col(2) = frame.col(iu).cross(frame.col(iv));
    const std::array<double, 4> extent = rt::cga::uvRangeOfScope(p, s);  // tile sizes 1: metres
    p.tileWidth = uvSize(op, 0, a[0], world ? extent[1] - extent[0] : s.S[iu]);
    p.tileHeight = uvSize(op, 1, a[1], world ? extent[3] - extent[2] : s.S[iv]);
    if (p.tileWidth == 0 || p.tileHeight == 0)
      throw DeriveError{op.loc, "R027", op.name + ": a tile size of 0 (CGA's texture sizes may be negative, which mirrors, but not 0)"};
    p.planar = true;
    p.texture = current ? projections_[current - 1].texture : rt::cga::UvProjection::kNoImage;
    return replace(p);
  }
  if (!current) return;
  rt::cga::UvProjection p = projections_[current - 1];
  if (kind == ir::UvOp::Project) {
    // fgsg projects at output: only coordinates deleteUV removed need projecting again,
    // from the setup (with the image the shape has now).
    if (p.coordinates) return;
    rt::cga::UvProjection again = projections_[p.setup - 1];
    again.texture = p.texture;
    again.setup = p.setup;
    return replace(again);
  }
  if (!p.coordinates) return;
  if (!p.setup) p.setup = current;
  std::array<double, 6> m{1, 0, 0, 0, 1, 0};
  switch (kind) {
    case ir::UvOp::Scale:
      m[0] = finiteArg(a[0], op, "the u factor"), m[4] = finiteArg(a[1], op, "the v factor");
      p.uvTransform = composeUv(m, p.uvTransform);
      break;
    case ir::UvOp::Translate:
      m[2] = finiteArg(a[0], op, "the u offset"), m[5] = finiteArg(a[1], op, "the v offset");
      p.uvTransform = composeUv(m, p.uvTransform);
      break;
    case ir::UvOp::Rotate: {
      // About u = v = 0, counter-clockwise in uv space.
      double c, sn;
      rt::cosSinDegrees(finiteArg(a[0], op, "the angle"), c, sn);
      m = {c, -sn, 0, sn, c, 0};
      p.uvTransform = composeUv(m, p.uvTransform);
      break;
    }
    case ir::UvOp::Tile: {
      // One tile every w metres along the frame's u (h along v), measured over the shape's
      // scope box; the uv operations before it are replaced. 0 keeps that axis.
      p.uvTransform = {1, 0, 0, 0, 1, 0};
      const double oldW = p.tileWidth, oldH = p.tileHeight;
      p.tileWidth = p.tileHeight = 1;
      const std::array<double, 4> metres = rt::cga::uvRangeOfScope(p, s);
      const double w = uvSize(op, 0, a[0], metres[1] - metres[0]), h = uvSize(op, 1, a[1], metres[3] - metres[2]);
      p.tileWidth = w == 0 ? oldW : w;
      p.tileHeight = h == 0 ? oldH : h;
      break;
    }
    case ir::UvOp::Normalize: {
      // The scope box's (u, v) range onto [0, 1]: both axes ("uv"), one ("u", "v"), or both
      // by the larger range ("uvUniform"). An axis without extent stays as it is.
      const std::string& mode = (*strings_)[op.str];
      const std::array<double, 4> r = rt::cga::uvRangeOfScope(p, s);
      double du = r[1] - r[0], dv = r[3] - r[2];
      if (mode == "uvUniform") du = dv = std::max(du, dv);
      const bool doU = mode != "v" && du > 0, doV = mode != "u" && dv > 0;
      if (doU) m[0] = 1 / du, m[2] = -r[0] / du;
      if (doV) m[4] = 1 / dv, m[5] = -r[2] / dv;
      p.uvTransform = composeUv(m, p.uvTransform);
      break;
    }
    case ir::UvOp::Delete: p.coordinates = false; break;
    default: break;
  }
  replace(p);
}

}  // namespace fgsg::backend
