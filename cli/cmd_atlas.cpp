// fgsg atlas: lay a mesh out for on-mesh marching (its atlas and indirection geometry
// image, cached like `fgsg run` caches them), say what was built, and optionally draw
// it (--preview), paint a mask for a texture context (--paint ... --mask) or export the
// mesh with its texture coordinates to paint one elsewhere (--export-uv).
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/options.h"
#include "runtime/io/cache_folder.h"
#include "runtime/io/read_input.h"
#include "runtime/marching/atlas_preview.h"
#include "runtime/marching/marching_surface.h"
#include "runtime/surface/load_surface.h"
#include "runtime/texture/atlas_uv_export.h"
#include "runtime/texture/paint_mask.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace fgsg::cli {
namespace {

struct AtlasOptions {
  std::string mesh;
  std::string preview;
  std::string mask;
  std::string exportUv;  // --export-uv: the mesh with the atlas's UVs, as OBJ
  int maskSize = 1024;
  int resolution = 1024;
  bool repair = false;
  double surfaceSize = 0;
  std::vector<rt::texture::Brush> brushes;
};

AtlasOptions parseAtlasOptions(const Args& args) {
  AtlasOptions o;
  CommandLine cl("atlas");
  cl.input(o.mesh, "mesh");
  cl.text("--preview", o.preview);
  cl.whole("--resolution", o.resolution, 16, 8192);
  cl.flag("--repair-surface", o.repair);
  cl.option("--surface-size", [&](const std::string& v) {
    o.surfaceSize = CommandLine::parseNumber("--surface-size", v);
    if (!(o.surfaceSize > 0)) throw UsageError{"--surface-size must be a positive number"};
  });
  cl.repeated("--paint", [&](const std::string& v) {
    // x,y,z,r: a sphere brush in the mesh's coordinates.
    double c[4];
    if (std::sscanf(v.c_str(), "%lf,%lf,%lf,%lf", &c[0], &c[1], &c[2], &c[3]) != 4 || !(c[3] > 0) ||
        !std::isfinite(c[0] + c[1] + c[2] + c[3]))
      throw UsageError{"--paint expects a sphere x,y,z,radius (a positive radius), got '" + v + "'"};
    rt::texture::Brush sphere;
    sphere.centre = rt::Vec3(c[0], c[1], c[2]);
    sphere.radius = c[3];
    o.brushes.push_back(sphere);
  });
  cl.repeated("--paint-slab", [&](const std::string& v) {
    // x,y,z,nx,ny,nz,w: the band within w of the plane through (x,y,z) square to n.
    double c[7];
    const bool read = std::sscanf(v.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf,%lf", &c[0], &c[1], &c[2], &c[3], &c[4], &c[5],
                                  &c[6]) == 7;
    const rt::Vec3 n(c[3], c[4], c[5]);
    if (!read || !(c[6] > 0) || !std::isfinite(c[0] + c[1] + c[2] + c[6]) || !(n.norm() > 0) || !std::isfinite(n.norm()))
      throw UsageError{"--paint-slab expects x,y,z,nx,ny,nz,halfwidth (a non-zero normal, a positive width), got '" + v +
                       "'"};
    rt::texture::Brush slab;
    slab.centre = rt::Vec3(c[0], c[1], c[2]);
    slab.radius = c[6];
    slab.slab = true;
    slab.normal = n.normalized();
    o.brushes.push_back(slab);
  });
  cl.text("--mask", o.mask);
  cl.whole("--mask-size", o.maskSize, 8, 8192);
  cl.text("--export-uv", o.exportUv);
  cl.parse(args);
  if (o.mesh.empty()) throw UsageError{"no mesh given: fgsg atlas MESH [--preview atlas.png]"};
  if (!o.preview.empty() && lowerExtension(o.preview) != ".png")
    throw UsageError{"--preview " + o.preview + ": previews are PNG files (name it .png)"};
  if (!o.mask.empty() && lowerExtension(o.mask) != ".png") throw UsageError{"--mask " + o.mask + ": masks are PNG files (name it .png)"};
  if (!o.exportUv.empty() && lowerExtension(o.exportUv) != ".obj")
    throw UsageError{"--export-uv " + o.exportUv + ": the mesh with its texture coordinates is an OBJ file (name it .obj)"};
  if (!o.brushes.empty() && o.mask.empty())
    throw UsageError{"--paint and --paint-slab need --mask FILE.png to write the mask to"};
  return o;
}

}  // namespace

int atlasCommand(const Args& args) {
  AtlasOptions opt;
  try {
    opt = parseAtlasOptions(args);
  } catch (const UsageError& e) {
    std::cerr << "fgsg atlas: " << e.message << "\n";
    return 2;
  }
  std::string error;
  if (!rt::io::checkInputFile(opt.mesh, "a mesh file", error)) {
    std::cerr << "fgsg atlas: " << error << "\n";
    return 1;
  }
  rt::surface::SurfaceMesh mesh;
  rt::surface::SurfaceLoadOptions load;
  load.repair = opt.repair;
  if (!rt::surface::loadSurface(opt.mesh, mesh, error, load)) {
    std::cerr << "fgsg atlas: " << error << "\n";
    return 1;
  }
  if (opt.surfaceSize > 0) rt::surface::fitToSize(mesh, opt.surfaceSize);
  rt::marching::MarchingOptions options;
  options.resolution = opt.resolution;
  if (const std::string cache = rt::io::cacheFolder(); !cache.empty()) options.cacheDir = cache + "/atlas";
  rt::marching::PrepareStats stats;
  const auto started = std::chrono::steady_clock::now();
  const auto surface = rt::marching::MarchingSurface::prepare(mesh, options, error, &stats);
  if (!surface) {
    std::cerr << "fgsg atlas: " << opt.mesh << ": " << error << "\n";
    return 1;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::printf("%s: %zu faces, %d charts (%s), %dx%d geometry image, %s in %.3f s\n", opt.mesh.c_str(),
              mesh.faceCount(), stats.charts, stats.meshUV ? "the mesh's own texture coordinates" : "generated",
              opt.resolution, opt.resolution, stats.fromCache ? "read from the cache" : "built", seconds);
  if (!opt.preview.empty()) {
    if (!rt::marching::writeAtlasPreview(*surface, opt.preview, error)) {
      std::cerr << "fgsg atlas: " << error << "\n";
      return 1;
    }
    std::printf("wrote %s\n", opt.preview.c_str());
  }
  if (!opt.mask.empty()) {
    const rt::texture::MaskImage mask = rt::texture::paintMask(*surface, opt.maskSize, opt.brushes);
    if (!rt::texture::writeMaskPng(mask, opt.mask, error)) {
      std::cerr << "fgsg atlas: " << error << "\n";
      return 1;
    }
    std::printf("wrote %s (%dx%d, %zu brushes)\n", opt.mask.c_str(), opt.maskSize, opt.maskSize, opt.brushes.size());
  }
  if (!opt.exportUv.empty()) {
    if (!rt::texture::writeAtlasUvObj(*surface, opt.exportUv, error)) {
      std::cerr << "fgsg atlas: " << error << "\n";
      return 1;
    }
    std::printf("wrote %s (%zu faces, their corners' texture coordinates: paint an image over them for a texture context)\n",
                opt.exportUv.c_str(), mesh.faceCount());
  }
  return 0;
}

}  // namespace fgsg::cli
