#include "backend/commands/surface_geometry.h"

#include "backend/interp/eval.h"
#include "runtime/abandonable.h"
#include "runtime/field/geodesics.h"
#include "runtime/field/tangent_frames.h"
#include "runtime/io/find_file.h"
#include "runtime/surface/load_surface.h"
#include "runtime/surface/locate.h"
#include "runtime/surface/procedural.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>
#include <string_view>

namespace fgsg::backend {

namespace fs = std::filesystem;

std::shared_ptr<const SurfaceGeometry> SurfaceGeometry::build(const ir::SurfaceSpec& spec,
                                                              const rt::DeriveOptions& options,
                                                              const std::vector<std::string>& searchDirs,
                                                              rt::Deadline* deadline) {
  std::shared_ptr<SurfaceGeometry> g(new SurfaceGeometry());
  g->mesh_ = std::make_unique<rt::surface::SurfaceMesh>();
  std::string error;
  rt::surface::SurfaceLoadOptions load;
  load.repair = options.repairSurface;
  load.maxMemoryBytes = options.maxMemoryBytes;
  bool ok = false;
  if (!options.surfaceOverride.empty()) {
    ok = rt::surface::loadSurface(options.surfaceOverride, *g->mesh_, error, load);
  } else if (!spec.path.empty()) {
    ok = rt::surface::loadSurface(rt::io::findFile(spec.path, searchDirs), *g->mesh_, error, load);
  } else {
    // Some generators run CGAL's booleans and remeshing (three tori: seconds), which read
    // no deadline: on a worker that --max-seconds abandons (R004, runtime/abandonable.h).
    struct Made {
      bool ok;
      rt::surface::SurfaceMesh mesh;
      std::string error;
    };
    Made made = rt::runAbandonable(deadline, false, [generator = spec.generator, args = spec.args] {
      Made out{false, {}, {}};
      out.ok = rt::surface::makeProceduralSurface(generator, args, out.mesh, out.error);
      return out;
    });
    ok = made.ok;
    *g->mesh_ = std::move(made.mesh);
    error = std::move(made.error);
  }
  if (!ok) throw DeriveError{spec.loc, "R015", error};
  if (options.surfaceSize > 0) rt::surface::fitToSize(*g->mesh_, options.surfaceSize);
  g->locator_ = std::make_unique<rt::surface::SurfaceLocator>(*g->mesh_);
  g->frames_ = std::make_shared<const rt::field::TangentFrames>(*g->mesh_);
  return g;
}

SurfaceGeometry::~SurfaceGeometry() = default;

std::shared_ptr<const rt::field::HeatGeodesics> SurfaceGeometry::heatGeodesics() const {
  std::call_once(heatBuilt_, [this] { heat_ = std::make_shared<const rt::field::HeatGeodesics>(frames_); });
  return heat_;
}

namespace {

// A double's exact bits, as text.
std::string surfaceGeometryExact(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%a", v);
  return text;
}

// What a geometry is built from, as one string; empty: not to be cached.
std::string surfaceGeometryKey(const ir::SurfaceSpec& spec, const rt::DeriveOptions& options,
                               const std::vector<std::string>& searchDirs) {
  std::ostringstream key;
  key << "size " << surfaceGeometryExact(options.surfaceSize) << " repair " << options.repairSurface << " memory "
      << options.maxMemoryBytes << "\n";
  if (options.surfaceOverride.empty() && spec.path.empty()) {
    key << "generator " << spec.generator;
    for (double a : spec.args) key << " " << surfaceGeometryExact(a);
    return key.str();
  }
  const std::string path =
      options.surfaceOverride.empty() ? rt::io::findFile(spec.path, searchDirs) : options.surfaceOverride;
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec);
  if (ec) return "";
  std::string ext = absolute.extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".gltf") return "";  // its buffers are other files
  const auto time = fs::last_write_time(absolute, ec);
  if (ec) return "";
  const auto size = fs::file_size(absolute, ec);
  if (ec) return "";
  std::ifstream in(absolute, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.is_open() || bytes.size() != size) return "";  // unreadable, or changing while read
  key << "file " << absolute.string() << "\nbytes " << bytes.size() << " modified "
      << time.time_since_epoch().count() << " hash " << std::hash<std::string_view>{}(bytes);
  return key.str();
}

}  // namespace

std::shared_ptr<const SurfaceGeometry> SurfaceGeometryCache::obtain(const ir::SurfaceSpec& spec,
                                                                    const rt::DeriveOptions& options,
                                                                    const std::vector<std::string>& searchDirs,
                                                                    rt::Deadline* deadline) {
  const std::string key = surfaceGeometryKey(spec, options, searchDirs);
  if (!key.empty()) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = std::find_if(kept_.begin(), kept_.end(), [&](const auto& k) { return k.first == key; });
    if (it != kept_.end()) {
      std::rotate(it, it + 1, kept_.end());  // now the newest
      return kept_.back().second;
    }
  }
  std::shared_ptr<const SurfaceGeometry> built = SurfaceGeometry::build(spec, options, searchDirs, deadline);
  // A file rewritten while it was read is not kept under either version's key.
  const bool unchanged = !key.empty() && surfaceGeometryKey(spec, options, searchDirs) == key;
  std::lock_guard<std::mutex> lock(mutex_);
  ++builds_;
  if (!unchanged) return built;
  if (kept_.size() == kKept) kept_.erase(kept_.begin());
  kept_.emplace_back(key, built);
  return built;
}

size_t SurfaceGeometryCache::builds() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return builds_;
}

}  // namespace fgsg::backend
