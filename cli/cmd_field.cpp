// fgsg field: show a grammar's field before anything grows on it (FGSG Fig. 7): its
// streamlines traced from seeds over the surface and its singularities with their
// indices, written as a mesh (the surface, the streamlines as lines, the singularities as
// coloured markers) and drawn with --preview; the singularities are listed.
#include "backend/commands/surface_world.h"
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/derive_flags.h"
#include "cli/compile_file.h"
#include "cli/options.h"
#include "cli/progress_line.h"
#include "runtime/field/field_sketch.h"
#include "runtime/io/atomic_file.h"
#include "runtime/io/read_input.h"
#include "runtime/io/write_mesh.h"
#include "runtime/render/preview.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>

namespace fgsg::cli {
namespace {

struct FieldOptions {
  std::string file, output, preview, field, singularities;
  rt::field::FieldSketchOptions sketch;
  rt::DeriveOptions derive;
};

FieldOptions parseFieldOptions(const Args& args) {
  FieldOptions o;
  CommandLine cl("field");
  cl.input(o.file, "grammar file");
  cl.text("-o,--output", o.output);
  cl.text("--preview", o.preview);
  cl.text("--singularities", o.singularities);
  cl.text("--field", o.field);
  cl.whole("--seeds", o.sketch.seeds, 1, 100000);
  for (const char* flag : {"--length", "--step"}) {
    double& target = std::string(flag) == "--length" ? o.sketch.length : o.sketch.step;
    cl.option(flag, [&target, flag](const std::string& text) {
      const double v = CommandLine::parseNumber(flag, text);
      if (!(v > 0)) throw UsageError{std::string(flag) + " must be a positive number"};
      target = v;
    });
  }
  cl.flag("--minor", o.sketch.minor);
  surfaceFlags(cl, o.derive);
  cl.parse(args);
  if (o.file.empty()) throw UsageError{"no grammar given: fgsg field FILE.fgsg [-o field.glb] [--preview field.png]"};
  if (o.output.empty() && o.preview.empty() && o.singularities.empty())
    throw UsageError{"nothing to write: give -o FILE (.glb .obj .ply), --preview FILE.png or --singularities FILE.json"};
  if (!o.singularities.empty() && lowerExtension(o.singularities) != ".json")
    throw UsageError{"--singularities " + o.singularities + ": the list is written as JSON (name it .json)"};
  if (!o.output.empty()) {
    const auto& known = rt::io::supportedMeshExtensions();
    if (std::find(known.begin(), known.end(), lowerExtension(o.output)) == known.end())
      throw UsageError{"-o " + o.output + ": the sketch is written as .glb, .obj or .ply"};
  }
  if (!o.preview.empty() && lowerExtension(o.preview) != ".png")
    throw UsageError{"--preview " + o.preview + ": previews are PNG files (name it .png)"};
  return o;
}

// The singularities as JSON: per singularity its kind, index (as "+1/2" and as a number)
// and position.
std::string singularitiesJson(const std::string& field, const rt::field::FieldSketch& sketch) {
  std::string s = "{\"field\":\"" + field + "\",\"singularities\":[";
  char buf[256];
  for (size_t i = 0; i < sketch.singularities.size(); ++i) {
    const auto& g = sketch.singularities[i];
    std::snprintf(buf, sizeof buf, "%s\n{\"kind\":\"%s\",\"index\":%g,\"position\":[%.9g,%.9g,%.9g]}", i ? "," : "",
                  rt::field::singularityName(g.kind), g.indexTimesTwo / 2.0, g.position.x(), g.position.y(),
                  g.position.z());
    s += buf;
  }
  return s + "\n]}\n";
}

// How a singularity's index is written: +1/2, -1/2, +1, -1.
std::string indexText(int indexTimesTwo) {
  const std::string sign = indexTimesTwo > 0 ? "+" : "-";
  return indexTimesTwo % 2 ? sign + std::to_string(std::abs(indexTimesTwo)) + "/2" : sign + std::to_string(std::abs(indexTimesTwo) / 2);
}

}  // namespace

int fieldCommand(const Args& args) {
  FieldOptions opt;
  try {
    opt = parseFieldOptions(args);
  } catch (const UsageError& e) {
    std::cerr << "fgsg field: " << e.message << "\n";
    return 2;
  }
  if (!opt.derive.surfaceOverride.empty()) {
    std::string error;
    if (!rt::io::checkInputFile(opt.derive.surfaceOverride, "a mesh file", error)) {
      std::cerr << "fgsg field: --surface " << error << "\n";
      return 1;
    }
    opt.derive.surfaceOverride = std::filesystem::absolute(opt.derive.surfaceOverride).lexically_normal().string();
  }
  auto compiled = compileFile(opt.file, false);
  if (!compiled) return 1;
  const ir::Module& m = compiled->module;
  if (!m.surface.present && opt.derive.surfaceOverride.empty()) {
    std::cerr << "fgsg field: " << opt.file << " declares no surface (fields live on one): add `surface ...;` or "
              << "pass --surface MESH\n";
    return 1;
  }
  std::unique_ptr<backend::SurfaceWorld> world;
  ProgressLine progress("fgsg field", true);
  progress.phase("building the surface and designing its fields");
  try {
    world = std::make_unique<backend::SurfaceWorld>(m, opt.derive, grammarDataDirs(opt.file));
  } catch (const backend::DeriveError& e) {
    progress.done();
    frontend::Diagnostics diags(&compiled->source);
    diags.error(e.code, {{e.loc.line, e.loc.col}, {e.loc.line, e.loc.col}}, e.message);
    diags.print(std::cerr);
    return 1;
  }
  progress.clear();
  const auto fields = world->fields();
  if (fields.empty()) {
    std::cerr << "fgsg field: " << opt.file << " declares no field (`field F = design tensor { ... };` ...)\n";
    return 1;
  }
  const rt::field::TangentField* field = fields.front().second;
  std::string name = fields.front().first;
  if (!opt.field.empty()) {
    field = nullptr;
    std::string names;
    for (const auto& [n, f] : fields) {
      if (n == opt.field) field = f;
      names += (names.empty() ? "" : ", ") + n;
    }
    if (!field) {
      std::cerr << "fgsg field: --field " << opt.field << ": " << opt.file << " declares no such field (" << names
                << ")\n";
      return 2;
    }
    name = opt.field;
  }

  const rt::surface::SurfaceMesh& mesh = world->mesh();
  progress.phase("tracing streamlines");
  const rt::field::FieldSketch sketch = rt::field::sketchField(mesh, *field, opt.sketch);
  progress.done();
  std::map<std::string, int> kinds;
  for (const auto& s : sketch.singularities) ++kinds[rt::field::singularityName(s.kind)];
  std::printf("%s: field %s (%s) on %zu faces: %zu streamlines", opt.file.c_str(), name.c_str(),
              field->isTensor() ? "tensor" : "vector", mesh.faceCount(),
              sketch.majorLines.size() + sketch.minorLines.size());
  std::printf(", %zu singularities", sketch.singularities.size());
  for (const auto& [kind, count] : kinds) std::printf(" (%d %s)", count, kind.c_str());
  std::printf("\n");
  for (const auto& s : sketch.singularities)
    std::printf("  %s, index %s at (%g, %g, %g)\n", rt::field::singularityName(s.kind),
                indexText(s.indexTimesTwo).c_str(), s.position.x(), s.position.y(), s.position.z());

  const rt::Mesh out = rt::field::sketchMesh(world->surfaceMesh(), sketch, 3 * mesh.meanEdgeLength);
  std::string error;
  if (!opt.singularities.empty()) {
    if (!rt::io::writeFileAtomically(opt.singularities, singularitiesJson(name, sketch), error)) {
      std::cerr << "fgsg field: " << error << "\n";
      return 1;
    }
    std::printf("wrote %s (%zu singularities)\n", opt.singularities.c_str(), sketch.singularities.size());
  }
  if (!opt.output.empty()) {
    if (!rt::io::writeMesh(out, opt.output, error)) {
      std::cerr << "fgsg field: " << error << "\n";
      return 1;
    }
    std::printf("wrote %s (%zu triangles, %zu line segments)\n", opt.output.c_str(), out.triangleCount(),
                out.lineCount());
  }
  if (!opt.preview.empty()) {
    if (!rt::render::renderPreview(out, rt::render::PreviewOptions{}, opt.preview, error)) {
      std::cerr << "fgsg field: " << error << "\n";
      return 1;
    }
    std::printf("wrote %s\n", opt.preview.c_str());
  }
  return 0;
}

}  // namespace fgsg::cli
