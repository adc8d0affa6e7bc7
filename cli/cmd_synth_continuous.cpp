// fgsg synth EXAMPLE.obj --size X Y Z [--spacing S] [--seed N] [--block N] [--fill F]
//            [--fixed-width A,B,C:N] [--floating] [-o out.glb] [--preview out.png] [--stats]
// Continuous model synthesis (Merrell ch. 4) from a closed polygonal example: the mode
// `fgsg synth` takes when the example is a mesh file. The box is X wide, Y deep and Z
// high, as label grids are; solids stand on its floor unless --floating. See
// docs/synthesis.md.
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/progress_line.h"
#include "cli/synth_like_run.h"
#include "runtime/io/output_transaction.h"
#include "runtime/io/write_mesh.h"
#include "runtime/render/preview.h"
#include "runtime/synthesis/image_reader.h"
#include "runtime/synthesis/continuous/continuous.h"

#include <cstdio>
#include <string>

namespace fgsg::cli {

namespace {

using namespace fgsg::rt::synthesis::continuous;

const char* const kSynthContinuousUsage =
    "usage: fgsg synth EXAMPLE.obj|.ply|.off|.stl|.glb --size X Y Z [--spacing S] [--seed N] [--block N]\n"
    "                  [--fill F] [--fixed-width A,B,C:N] [--plane-step A,B,C:N] [--floating] [--connect N]\n"
    "                  [--mask image.png] [--symmetry mirror-x|mirror-z] [--perturb D] [--retries N] [--passes N] [--max-seconds S]\n"
    "                  [-o out.glb|.obj|.ply] [--preview out.png] [--stats]\n";

int usageError(const std::string& msg) {
  std::fprintf(stderr, "fgsg synth: error: %s\n%s", msg.c_str(), kSynthContinuousUsage);
  return 2;
}

// "1,0,1:2": a face direction and a width in plane spacings.
bool parseFixedWidth(const std::string& s, FixedWidth& f) {
  long long a = 0, b = 0, c = 0;
  int n = 0, used = 0;
  if (std::sscanf(s.c_str(), "%lld,%lld,%lld:%d%n", &a, &b, &c, &n, &used) != 4 || size_t(used) != s.size()) return false;
  if (std::llabs(a) > 1000 || std::llabs(b) > 1000 || std::llabs(c) > 1000 || (a == 0 && b == 0 && c == 0)) return false;
  f.normal = {a, b, c};
  f.planes = n;
  return n >= 1 && n <= 1000;
}

// Why a synthesis that succeeded holds no solid, and what to try: a --fixed-width wider
// than the box along its direction can never fit (planes a.x = k, k whole in lattice units:
// the box spans sum |a_i| size_i / spacing of them); otherwise the constraints together
// left only empty space.
std::string whyEmpty(const ContinuousOptions& o) {
  for (const FixedWidth& f : o.fixedWidth) {
    double span = 0;
    for (int i = 0; i < 3; ++i)
      span += double(f.normal[i] < 0 ? -f.normal[i] : f.normal[i]) * o.size[size_t(i)] / o.spacing;
    if (f.planes > span + 1e-9) {
      const long long a = f.normal[0], b = f.normal[1], c = f.normal[2];
      char buf[400];
      std::snprintf(buf, sizeof buf,
                    "--fixed-width %lld,%lld,%lld:%d makes every object %d plane spacings across along "
                    "(%lld,%lld,%lld), but the box spans only %g of them that way%s: enlarge --size or give "
                    "a smaller width",
                    a, b, c, f.planes, f.planes, a, b, c, span,
                    a == 0 && c == 0 ? " (it is the box's height, --size's Z)" : "");
      return buf;
    }
  }
  return "every vertex of the box took empty space: the constraints (--fixed-width, --mask, --connect, "
         "standing on the ground, --fill) leave no solid the example allows here; try a larger --size, "
         "another --seed, a higher --fill, --floating or fewer constraints";
}

}  // namespace

const char* continuousSynthUsage() { return kSynthContinuousUsage; }

int continuousSynthCommand(const Args& args) {
  std::string example, meshOut, previewOut, maskPath;
  ContinuousOptions o;
  bool haveSize = false, stats = false, onGround = false, floating = false;
  auto need = [](bool ok, const std::string& message) {
    if (!ok) throw UsageError{message};
  };
  try {
    CommandLine cl("synth");
    cl.input(example, "example");
    // As for label grids, Z is the height: X wide, Y deep, Z high (the example's y).
    cl.values("--size", 3, 3, [&](const std::vector<std::string>& v) {
      need(v.size() == 3, "--size needs X Y Z: the box's width, depth and height in world units");
      double s[3];
      for (size_t k = 0; k < 3; ++k) {
        s[k] = CommandLine::parseNumber("--size", v[k]);
        need(s[k] > 0, "--size needs X Y Z: positive numbers");
      }
      o.size = {s[0], s[2], s[1]};
      haveSize = true;
    });
    cl.option("--spacing", [&](const std::string& s) {
      o.spacing = CommandLine::parseNumber("--spacing", s);
      need(o.spacing > 0, "--spacing needs a positive number (world units between planes)");
    });
    cl.whole("--seed", o.seed);
    cl.option("--block", [&](const std::string& s) {
      o.block = int(CommandLine::parseWhole("--block", s, 0, 4096));
    });
    // Solids stand on the floor unless --floating (--on-ground says the default).
    cl.flag("--on-ground", onGround);
    cl.flag("--floating", floating);
    cl.whole("--connect", o.growSeeds, 1, 100000);
    cl.text("--mask", maskPath);
    cl.repeated("--symmetry", [&](const std::string& s) {
      need(s == "mirror-x" || s == "mirror-z", "--symmetry is mirror-x or mirror-z for a polygonal example");
      o.mirrorAxes.push_back(s == "mirror-x" ? 0 : 2);
    });
    cl.option("--perturb", [&](const std::string& s) {
      o.perturb = CommandLine::parseNumber("--perturb", s);
      need(o.perturb >= 0, "--perturb needs a distance of 0 or more (world units)");
    });
    cl.whole("--retries", o.blockRetries, 0, 1000);
    cl.whole("--passes", o.passes, 1, 100);
    cl.option("--fill", [&](const std::string& s) {
      o.fill = CommandLine::parseNumber("--fill", s);
      need(o.fill >= 0 && o.fill <= 1, "--fill needs a number from 0 to 1");
    });
    synthMaxSecondsFlag(cl, o.timeLimitSeconds);
    cl.repeated("--fixed-width", [&](const std::string& s) {
      FixedWidth f;
      need(parseFixedWidth(s, f), "--fixed-width needs A,B,C:N: a face direction of the example (integers) and a width "
                                  "of N plane spacings (1 to 1000)");
      o.fixedWidth.push_back(f);
    });
    cl.repeated("--plane-step", [&](const std::string& s) {
      FixedWidth f;
      need(parseFixedWidth(s, f), "--plane-step needs A,B,C:N: a face direction of the example (integers) and N: "
                                  "every N-th plane only (1 to 1000)");
      o.planeStep.push_back(f);
    });
    cl.text("-o,--output", meshOut);
    cl.text("--preview", previewOut);
    cl.flag("--stats", stats);
    cl.parse(args);
  } catch (const UsageError& e) {
    return usageError(e.message);
  }
  if (example.empty()) return usageError("no example file given");
  if (!haveSize) return usageError("--size X Y Z is required");
  if (onGround && floating) return usageError("--on-ground and --floating exclude each other");
  o.onGround = !floating;
  if (meshOut.empty()) meshOut = defaultModelOutput(example);  // as fgsg run

  // --max-seconds counts from here: reading a large example is part of the run.
  rt::Deadline deadline = rt::Deadline::after(o.timeLimitSeconds);
  o.deadline = &deadline;
  ExampleSolid ex;
  std::string err;
  if (!maskPath.empty()) {
    // As the discrete --mask: dark pixels are where solids may stand (a letter drawn on white).
    rt::synthesis::RgbImage img;
    if (!rt::synthesis::readRgbImage(maskPath, img, err)) {
      std::fprintf(stderr, "%s: error[E731]: %s\n", maskPath.c_str(), err.c_str());
      return 1;
    }
    o.maskWidth = img.width;
    o.maskHeight = img.height;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        const uint32_t c = img.pixel(x, y);
        o.mask.push_back(0.299 * ((c >> 16) & 255) + 0.587 * ((c >> 8) & 255) + 0.114 * (c & 255) < 128.0 ? 1.0f : 0.0f);
      }
  }
  if (!loadExampleSolid(example, ex, err, &deadline)) {
    if (deadline.passed()) {  // reading a large example took the time: the limit's error
      std::fprintf(stderr, "%s: error[E751]: continuous synthesis failed: stopped by the time limit (%s s)\n",
                   example.c_str(), std::to_string(o.timeLimitSeconds).c_str());
      return 1;
    }
    // The message starts with where ("house.obj: face 7 ...", "house.obj:12: ..."): the
    // code goes after that place, as in every fgsg diagnostic.
    const size_t at = err.rfind(example, 0) == 0 ? err.find(": ", example.size()) : std::string::npos;
    if (at == std::string::npos)
      std::fprintf(stderr, "%s: error[E750]: %s\n", example.c_str(), err.c_str());
    else
      std::fprintf(stderr, "%s: error[E750]: %s\n", err.substr(0, at).c_str(), err.substr(at + 2).c_str());
    return 1;
  }
  ProgressLine progress("fgsg synth", true);
  progress.phase("synthesizing");
  ContinuousResult r = synthesizeContinuous(ex, o);
  progress.done();
  const auto& s = r.stats;
  if (stats) {  // on stdout, as fgsg run --stats prints its figures
    const std::pair<const char*, uint64_t> figures[] = {
        {"example.polygons", uint64_t(s.exampleFaces)}, {"directions", uint64_t(s.directions)},
        {"labels", uint64_t(s.labels)},                 {"relations", uint64_t(s.relations)},
        {"vertices", s.vertices},                       {"edges", s.edges},
        {"output.polygons", s.outputPolygons},          {"arrangement.faces", s.arrangementFaces},
        {"parts", s.parts},                             {"triangles", s.triangles},
        {"blocks", uint64_t(s.blocks)},                 {"blocks.failed", uint64_t(s.blocksFailed)},
        {"assignments", s.assignments}};
    for (const auto& [name, value] : figures) printStat(name, value);
    printStatSeconds("synthesize", s.seconds);
    printStatSeconds("compile", s.compileSeconds);
    printStatSeconds("assign", s.assignSeconds);
    printStatSeconds("surface", s.surfaceSeconds);
  }
  if (!r.ok) {
    std::fprintf(stderr, "%s: error[E751]: continuous synthesis failed: %s\n", example.c_str(), r.error.c_str());
    return 1;
  }
  if (s.parts == 0) {  // never a silent empty file (#46)
    std::fprintf(stderr, "%s: error[E752]: the synthesized model is empty (0 parts), nothing was written: %s\n",
                 example.c_str(), whyEmpty(o).c_str());
    return 1;
  }
  if (s.blocksFailed > 0)
    std::fprintf(stderr, "%s: note: %d of %d blocks kept as they were (no consistent labels found in %d tries)\n",
                 example.c_str(), s.blocksFailed, s.blocks, o.blockRetries + 1);
  rt::io::OutputTransaction outputs;
  if (!meshOut.empty() && !rt::io::stageMesh(r.mesh, meshOut, outputs, err)) {
    std::fprintf(stderr, "%s: error[E744]: %s\n", meshOut.c_str(), err.c_str());
    return 1;
  }
  if (!previewOut.empty()) {
    rt::render::PreviewOptions po;
    std::string warning;
    if (!rt::render::stagePreview(r.mesh, po, previewOut, outputs, err, &warning)) {
      std::fprintf(stderr, "%s: error[E745]: %s\n", previewOut.c_str(), err.c_str());
      return 1;
    }
    if (!warning.empty()) std::fprintf(stderr, "%s: warning: %s\n", previewOut.c_str(), warning.c_str());
  }
  if (!outputs.commit(err)) {
    std::fprintf(stderr, "fgsg synth: error[E742]: %s\n", err.c_str());
    return 1;
  }
  std::string wrote;
  for (const std::string* f : {&meshOut, &previewOut})
    if (!f->empty()) wrote += (wrote.empty() ? "" : ", ") + *f;
  if (!wrote.empty())
    std::fprintf(stderr, "wrote %s (%zu parts, %zu polygons, %zu triangles; %zu plane vertices, %d labels)\n",
                 wrote.c_str(), s.parts, s.outputPolygons, s.triangles, s.vertices, s.labels);
  return 0;
}

}  // namespace fgsg::cli
