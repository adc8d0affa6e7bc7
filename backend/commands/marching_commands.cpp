#include "backend/commands/marching_commands.h"

#include "backend/engine/derivation.h"
#include "backend/engine/surface_reuse.h"
#include "runtime/abandonable.h"
#include "runtime/io/find_file.h"
#include "runtime/marching/marching_surface.h"
#include "runtime/marching/smooth_curves.h"
#include "runtime/texture/texture_map.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace fgsg::backend {
namespace {

using rt::Vec3;
using rt::marching::MarchingSurface;
using rt::marching::MarchPoint;

static_assert(static_cast<uint32_t>(rt::marching::TerminalSmoothness::C1) == ir::kMarchC1 &&
                  static_cast<uint32_t>(rt::marching::TerminalSmoothness::C0) == ir::kMarchC0 &&
                  static_cast<uint32_t>(rt::marching::TerminalSmoothness::Discontinuous) == ir::kMarchDiscontinuous,
              "Marching's op.index is a TerminalSmoothness");

// Branch(n) makes at most this many branches: beyond, a grammar has a bug, not a plant.
constexpr double kMaxBranches = 1000;

// The direction `turn` degrees counter-clockwise (seen from outside) from d in the image.
rt::marching::Vec2 turnedDirection(const rt::marching::Vec2& d, double degrees) {
  const double r = degrees * 3.14159265358979323846 / 180.0;
  const double c = std::cos(r), s = std::sin(r);
  return {c * d.x() - s * d.y(), s * d.x() + c * d.y()};
}

}  // namespace

MarchingCommands::MarchingCommands(Derivation& derivation) : d_(derivation) {}
MarchingCommands::~MarchingCommands() = default;

std::vector<ir::OpKind> MarchingCommands::kinds() const {
  using K = ir::OpKind;
  return {K::Marching, K::MarchCondition, K::Branch};
}

void MarchingCommands::apply(const ir::Op& op, const double* a, uint32_t, State& st, Exec& ex, Frame& f) {
  switch (op.kind) {
    case ir::OpKind::Marching: march(op, a, st, ex, f); break;
    case ir::OpKind::MarchCondition: condition_ = a[0] != 0.0; break;
    default: branch(op, a, st, ex, f); break;
  }
}

void MarchingCommands::loadTextures() {
  const ir::Module& m = d_.module();
  textures_.clear();
  textures_.resize(m.environment.size());
  for (size_t k = 0; k < m.environment.size(); ++k) {
    const auto& env = m.environment[k];
    if (env.kind != "texture") continue;
    auto texture = std::make_shared<rt::texture::TextureMap>();
    std::string error;
    if (!texture->load(rt::io::findFile(env.detail, d_.options().assetDirs), error))
      throw DeriveError{env.loc, "R023", "texture '" + env.name + "': " + error};
    textures_[k] = std::move(texture);
  }
}

void MarchingCommands::prepareSurface() {
  if (prepared_) return;
  prepared_ = true;
  if (!d_.surface()) {
    unpreparedCode_ = "R022";
    unpreparedWhy_ = "on-mesh marching and texture contexts need a surface: declare one "
                     "(`surface \"bunny.off\";`) or pass --surface MESH";
    return;
  }
  rt::marching::MarchingOptions options;
  options.resolution = d_.options().atlasResolution;
  options.cacheDir = d_.options().atlasCacheDir;
  // Laid out once per derivation; the disk cache (options.cacheDir) spares the next run.
  // Laying out a large mesh takes seconds in many steps (charts, their flattening and
  // packing, the geometry image): on a worker that --max-seconds abandons. It reads
  // only the surface, which it shares.
  const auto start = std::chrono::steady_clock::now();
  // fgsg view: the layout of the last derivation on this surface (surface_reuse.h).
  SurfaceReuse* reuse = SurfaceReuseScope::current();
  if (reuse) {
    std::lock_guard<std::mutex> lock(reuse->mutex);
    if (reuse->world == d_.surface() && reuse->marching) {
      surface_ = reuse->marching;
      d_.stats().surfaceSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return;
    }
  }
  std::pair<std::shared_ptr<const MarchingSurface>, std::string> prepared;
  try {
    prepared = rt::runAbandonable(&d_.deadline(), false, [world = d_.surface(), options] {
      std::string error;
      auto surface = MarchingSurface::prepare(world->mesh(), options, error);
      return std::make_pair(std::move(surface), std::move(error));
    });
  } catch (const rt::TimeLimitReached&) {
    d_.stats().surfaceSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    prepared_ = false;  // asked again, it stops again at once
    throw d_.timeLimit();
  }
  surface_ = std::move(prepared.first);
  if (reuse && surface_) {
    std::lock_guard<std::mutex> lock(reuse->mutex);
    if (reuse->world == d_.surface()) reuse->marching = surface_;
  }
  d_.stats().surfaceSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!surface_)
    unpreparedCode_ = "R023", unpreparedWhy_ = "the surface cannot be laid out for marching: " + prepared.second;
}

void MarchingCommands::shareFrom(const MarchingCommands& other) {
  surface_ = other.surface_;
  prepared_ = other.prepared_;
  unpreparedCode_ = other.unpreparedCode_;
  unpreparedWhy_ = other.unpreparedWhy_;
  textures_ = other.textures_;
}

const MarchingSurface& MarchingCommands::surface(ir::Loc at) {
  prepareSurface();
  if (!surface_) throw DeriveError{at, unpreparedCode_, unpreparedWhy_};
  return *surface_;
}

double MarchingCommands::sampleTexture(const rt::Scope& scope, uint32_t env, ir::Loc at) {
  const MarchingSurface& s = surface(at);
  if (scope.face < 0)
    throw DeriveError{at, "R022", "a texture context is sampled at a point of the surface, and this scope is on none"};
  const rt::marching::Vec2 uv = s.texCoord({scope.face, scope.bary});
  if (recordReads_) noteTextureRead(env, uv.x(), uv.y());
  return textures_.at(env)->sample(uv.x(), uv.y());
}

// The tiles holding the texels TextureMap::sample reads at (u, v): its four nearest
// centres, taken here with one texel more on each side (the same clamping, not its
// exact corner cases), so the tiles marked always cover them.
void MarchingCommands::noteTextureRead(uint32_t env, double u, double v) {
  const rt::texture::TextureMap& t = *textures_.at(env);
  if (t.empty() || std::isnan(u) || std::isnan(v)) return;  // reads 0 whatever the texels
  const int w = t.width(), h = t.height();
  if (reads_.size() <= env) reads_.resize(env + 1);
  TextureTiles& tiles = reads_[env];
  if (tiles.bits.empty()) {
    tiles.columns = (w + kTextureTile - 1) / kTextureTile;
    tiles.rows = (h + kTextureTile - 1) / kTextureTile;
    tiles.bits.assign((size_t(tiles.columns) * size_t(tiles.rows) + 63) / 64, 0);
  }
  const int x = int(std::clamp(u * w - 0.5, 0.0, double(w - 1)));
  const int y = int(std::clamp((1.0 - v) * h - 0.5, 0.0, double(h - 1)));
  for (int r = std::max(y - 1, 0) / kTextureTile; r <= std::min(y + 1, h - 1) / kTextureTile; ++r)
    for (int c = std::max(x - 1, 0) / kTextureTile; c <= std::min(x + 1, w - 1) / kTextureTile; ++c) {
      const size_t bit = size_t(r) * size_t(tiles.columns) + size_t(c);
      tiles.bits[bit / 64] |= uint64_t(1) << (bit % 64);
    }
}

std::vector<Vec3> MarchingCommands::densitySeeds(const std::string& name, uint32_t count, uint64_t key) {
  const ir::Module& m = d_.module();
  size_t env = m.environment.size();
  for (size_t k = 0; k < m.environment.size(); ++k)
    if (m.environment[k].kind == "texture" && m.environment[k].name == name) env = k;
  if (env == m.environment.size())
    throw DeriveError{{}, "R023", "--seed-density " + name + ": the grammar declares no texture '" + name +
                                      "' (texture " + name + " = \"paint.png\";)"};
  const MarchingSurface& s = surface({});
  const auto& mesh = s.mesh();
  // Each face weighs its area times the texture at its centre; draws walk the running sum.
  std::vector<double> total(mesh.faceCount());
  double sum = 0;
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const rt::marching::Vec2 uv = s.texCoord({static_cast<int>(f), Vec3(1.0 / 3, 1.0 / 3, 1.0 / 3)});
    sum += mesh.faceAreas[f] * std::max(0.0, textures_[env]->sample(uv.x(), uv.y()));
    total[f] = sum;
  }
  if (!(sum > 0))
    throw DeriveError{m.environment[env].loc, "R023",
                      "--seed-density " + name + ": the texture is black all over the surface: no seed can be drawn"};
  rt::RandomStream rng{key, 0};
  std::vector<Vec3> points;
  for (uint32_t k = 0; k < count; ++k) {
    const double at = rng.next() * sum;
    const size_t f = std::min<size_t>(std::upper_bound(total.begin(), total.end(), at) - total.begin(),
                                      mesh.faceCount() - 1);
    double a = rng.next(), b = rng.next();
    if (a + b > 1) a = 1 - a, b = 1 - b;  // uniform in the triangle
    points.push_back(rt::surface::SurfacePoint{static_cast<int>(f), Vec3(1 - a - b, a, b)}.position(mesh));
  }
  return points;
}

int32_t MarchingCommands::nodeAt(const rt::Scope& scope) {
  if (scope.marchNode >= 0) return scope.marchNode;
  nodes_.push_back({scope.P, scope.Z()});
  return static_cast<int32_t>(nodes_.size() - 1);
}

// Marching(length, angle, cond[, smoothness]){ Top, Extruded } (§5): the scope's X,
// turned by `angle` about the normal, is the marching direction; the first direction
// whose destination satisfies `cond` wins — straight ahead first, then marchCandidates
// others spread over the half circle ahead, nearest first, alternating sides (§8).
// Without one the march stops here and nothing is derived. The segment keeps the op's
// smoothness (op.index, ir::kMarchC1 ...) for its terminals' curve (§6).
void MarchingCommands::march(const ir::Op& op, const double* a, State& st, Exec& ex, Frame& f) {
  const double length = a[0], angle = a[1];
  if (!(std::isfinite(length) && length > 0))
    throw DeriveError{op.loc, "R024", "the marching length must be a positive number, but it is " +
                                          std::to_string(length)};
  if (!std::isfinite(angle))
    throw DeriveError{op.loc, "R024", "the marching angle is not a finite number"};
  const MarchingSurface& s = surface(op.loc);
  if (st.scope.face < 0)
    throw DeriveError{op.loc, "R022", "Marching starts from a point of the surface, and this scope is on none"};
  const auto& options = d_.options();
  if (!tally_.hasFirst) tally_.first = op.loc, tally_.hasFirst = true;
  ++tally_.marches;
  tally_.candidates = std::max(0, options.marchCandidates);
  const auto unit = options.marchInTexels ? rt::marching::LengthUnit::Image : rt::marching::LengthUnit::Surface;
  // No two points of the surface are farther apart than its bounding box's diagonal: a
  // longer step has no destination, and would only walk far before finding so.
  const auto& mesh = s.mesh();
  if (unit == rt::marching::LengthUnit::Surface && length > (mesh.boundsMax - mesh.boundsMin).norm()) {
    ++tally_.tooLong;
    return;
  }
  bool landed = false;  // some direction reached a destination (where the condition failed)
  MarchPoint from = s.place({st.scope.face, st.scope.bary}, st.scope.X());
  const rt::marching::Vec2 ahead = turnedDirection(from.dir, angle);
  const int sides = std::max(0, options.marchCandidates);
  // p per side, the farthest 90 p / (p + 0.5) degrees out: 8 give ±20, ±40, ±60, ±80.
  const int perSide = (sides + 1) / 2;
  const double spacing = sides > 0 ? 90.0 / (perSide + 0.5) : 0.0;
  for (int k = 0; k <= sides; ++k) {
    // 0, +1, -1, +2, -2 ... steps of `spacing` degrees: all strictly inside ±90°.
    const int step = (k + 1) / 2;
    from.dir = turnedDirection(ahead, (k % 2 ? 1 : -1) * step * spacing);
    MarchPoint to;
    if (!s.march(from, length, unit, to)) continue;  // the surface's edge came first
    landed = true;
    rt::Scope top = st.scope;
    d_.surface()->placeOn(top, to.at.face, to.at.bary, s.direction(to));
    condition_ = false;
    d_.runBody(op, 2, top, st.geom, st, ex, f);
    if (ex.culled) {  // the condition's own body ended the shape: it did land
      ++tally_.steps;
      return;
    }
    if (!condition_) continue;
    ++tally_.steps;
    // The destination is a new node; the segment to it carries the Extruded part.
    const int32_t start = nodeAt(st.scope);
    nodes_.push_back({top.P, top.Z()});
    top.marchNode = static_cast<int32_t>(nodes_.size() - 1);
    top.marchSegment = -1;
    const auto smoothness = static_cast<rt::marching::TerminalSmoothness>(op.index);
    segments_.push_back({static_cast<uint32_t>(start), static_cast<uint32_t>(top.marchNode), smoothness});
    // A discontinuous march's terminals name no curve: they stay rigid (march_graph.h).
    const bool bent = smoothness != rt::marching::TerminalSmoothness::Discontinuous;
    rt::Scope extruded = chord(st.scope, top, bent ? static_cast<int32_t>(segments_.size() - 1) : -1);
    extruded.marchNode = start;
    d_.runBody(op, 0, top, st.geom, st, ex, f);
    if (ex.culled) return;
    d_.runBody(op, 1, extruded, st.geom, st, ex, f);
    return;
  }
  ++(landed ? tally_.conditionFailed : tally_.atEdge);
}

// The Extruded part's scope: X along the straight segment from `from` to `to`, Z the
// mean of their normals (made square to X), as long as the segment, keeping the other
// sizes, placed so that the segment runs along the middle of its bottom face: a unit
// terminal across Y and Z (the `bark` cylinder) rests on the surface.
rt::Scope MarchingCommands::chord(const rt::Scope& from, const rt::Scope& to, int32_t segment) {
  rt::Scope s = from;
  const Vec3 along = to.P - from.P;
  const double length = along.norm();
  const Vec3 x = length > 0 ? Vec3(along / length) : from.X();
  Vec3 z = from.Z() + to.Z();
  z -= x * x.dot(z);
  if (z.norm() < 1e-12) z = from.Z() - x * x.dot(from.Z());
  z.normalize();
  s.axes.col(0) = x;
  s.axes.col(1) = z.cross(x);
  s.axes.col(2) = z;
  s.S.x() = length;
  s.P = from.P - 0.5 * s.S.y() * s.axes.col(1);
  s.marchSegment = segment;
  return s;
}

// Branch(n){ A, B }: n branches leave the scope's point — the first n-1 derive A, the
// last derives the last part (with one part, all derive it), in that order.
void MarchingCommands::branch(const ir::Op& op, const double* a, State& st, Exec& ex, Frame& f) {
  const double n = a[0];
  if (!(n >= 0 && n <= kMaxBranches && n == std::floor(n)))
    throw DeriveError{op.loc, "R024", "Branch(n) takes a whole number of branches from 0 to 1000"};
  const size_t count = static_cast<size_t>(n);
  if (st.scope.face >= 0 && count > 0) st.scope.marchNode = nodeAt(st.scope);
  for (size_t k = 0; k < count; ++k) {
    const size_t body = k + 1 < count ? 0 : op.bodies.size() - 1;
    d_.runBody(op, body, st.scope, st.geom, st, ex, f);
    if (ex.culled) return;
  }
}

std::vector<rt::CurveSegment> MarchingCommands::curves() const {
  return rt::marching::smoothSegments(nodes_, segments_);
}

}  // namespace fgsg::backend
