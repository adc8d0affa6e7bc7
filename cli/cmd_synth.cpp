// fgsg synth EXAMPLE --size X Y Z [--block N] [--seed N] [--labels out.txt] [-o out.glb]
//            [--preview out.png] [--periodic] [--mask image.png] [--stats] ...
// Discrete model synthesis from an example grid (.txt), a WFC tile set (.json) or a
// labelled image (.png). See docs/synthesis.md.
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/progress_line.h"
#include "cli/synth_like_run.h"
#include "runtime/assemble.h"
#include "runtime/assets.h"
#include "runtime/io/write_mesh.h"
#include "runtime/render/preview.h"
#include "runtime/synthesis/checker.h"
#include "runtime/synthesis/continuous/example_file.h"
#include "runtime/synthesis/synthesis.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <functional>
#include <string>

namespace fgsg::cli {

namespace {

using namespace fgsg::rt::synthesis;

const char* const kSynthUsage =
    "usage: fgsg synth EXAMPLE --size X Y Z [--block N] [--seed N] [--labels out.txt]\n"
    "                  [-o out.glb|.obj|.ply] [--preview out.png] [--periodic] [--mask image.png]\n"
    "                  [--order scanline|entropy] [--retries N] [--attempts N] [--closed]\n"
    "                  [--border FACE=LABEL] [--symmetry mirror-x|mirror-y|rotate-90|rotate-180|translate-x:N|translate-y:N]\n"
    "                  [--connect N] [--max-steps N] [--max-seconds S] [--cell SIZE] [--stats]\n";

int usage(const std::string& msg) {
  std::fprintf(stderr, "fgsg synth: error: %s\n%s", msg.c_str(), kSynthUsage);
  return 2;
}

constexpr long long kMaxExtent = 1 << 20;  // cells along one axis, as in label-grid files

bool toInt(const std::string& s, long long lo, long long hi, long long& v) {
  auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size() && v >= lo && v <= hi;
}

// Digits with an optional sign, of any length: meant as a number, in range or not.
bool looksLikeInteger(const std::string& s) {
  const size_t from = !s.empty() && (s[0] == '-' || s[0] == '+') ? 1 : 0;
  return s.size() > from && s.find_first_not_of("0123456789", from) == std::string::npos;
}

bool toDouble(const std::string& s, double& v) {
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return !s.empty() && end == s.c_str() + s.size() && v >= 0 && v < 1e9;
}

std::string dirOf(const std::string& path) {
  auto slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}

}  // namespace

// Both forms: a label grid / tile set / image, and a polygonal example.
const char* synthUsage() {
  static const std::string both = std::string(kSynthUsage) + continuousSynthUsage();
  return both.c_str();
}

int synthCommand(const Args& args) {
  // A mesh example (not the value of an output option) means continuous synthesis.
  for (size_t i = 0; i < args.size(); ++i) {
    const bool value = i > 0 && (args[i - 1] == "-o" || args[i - 1] == "--output" || args[i - 1] == "--preview" ||
                                 args[i - 1] == "--labels" || args[i - 1] == "--mask");
    if (!value && args[i].rfind("-", 0) != 0 && rt::synthesis::continuous::isPolygonalExampleFile(args[i])) return continuousSynthCommand(args);
  }
  std::string example, labelsOut, meshOut, previewOut, maskPath;
  SynthesisOptions o;
  bool haveSize = false, stats = false, closed = false, periodic = false;
  double cell = 1.0;
  std::vector<std::pair<int, std::string>> borders;
  int connectSeeds = 0;
  o.attempts = 10;
  // Each option's own message (tests and scripts match them); usage() adds the usage lines.
  auto need = [](bool ok, const std::string& message) {
    if (!ok) throw UsageError{message};
  };
  auto wholeOption = [&](CommandLine& cl, const char* flag, long long lo, long long hi, const std::string& message,
                         std::function<void(long long)> use) {
    cl.option(flag, [=](const std::string& s) {
      long long v = 0;
      need(toInt(s, lo, hi, v), message);
      use(v);
    });
  };
  std::string trailing;  // `--size X Y FILE`: Z left out, the file after it
  try {
    CommandLine cl("synth");
    cl.input(example, "example");
    cl.values("--size", 2, 3, [&](const std::vector<std::string>& n) {
      const std::string message = "--size needs X Y [Z]: whole numbers from 1 to " + std::to_string(kMaxExtent);
      // Z may be left out for a planar model: a third value that is no integer at all is the
      // example file; one out of range is still an error, not a file name.
      long long v[3] = {0, 0, 1};
      need(n.size() >= 2 && looksLikeInteger(n[1]), message);
      for (size_t k = 0; k < n.size(); ++k) {
        if (k == 2 && !looksLikeInteger(n[k])) {
          trailing = n[k];
          break;
        }
        need(toInt(n[k], 1, kMaxExtent, v[k]), message);
      }
      o.size = {int(v[0]), int(v[1]), int(v[2])};
      haveSize = true;
    });
    wholeOption(cl, "--block", 0, kMaxExtent,
                "--block needs a block size N from 0 to " + std::to_string(kMaxExtent) + " (0: whole grid)",
                [&](long long v) { o.block = {int(v), int(v), int(v)}; });
    wholeOption(cl, "--seed", 0, INT64_MAX, "--seed needs a whole number from 0 to " + std::to_string(INT64_MAX),
                [&](long long v) { o.seed = uint64_t(v); });
    cl.text("--labels", labelsOut);
    cl.text("-o,--output", meshOut);
    cl.text("--preview", previewOut);
    cl.text("--mask", maskPath);
    cl.flag("--periodic", periodic);
    cl.flag("--closed", closed);
    cl.flag("--stats", stats);
    cl.option("--order", [&](const std::string& s) {
      need(s == "scanline" || s == "entropy", "--order is scanline or entropy");
      o.order = s == "entropy" ? CellOrder::kMinEntropy : CellOrder::kScanline;
    });
    wholeOption(cl, "--retries", 0, 1000, "--retries needs an integer 0..1000", [&](long long v) { o.blockRetries = int(v); });
    wholeOption(cl, "--attempts", 1, 100000, "--attempts needs an integer 1..100000",
                [&](long long v) { o.attempts = int(v); });
    wholeOption(cl, "--connect", 1, 100000, "--connect needs a seed count from 1 to 100000",
                [&](long long v) { connectSeeds = int(v); });
    wholeOption(cl, "--max-steps", 1, INT64_MAX, "--max-steps needs a whole number from 1 to " + std::to_string(INT64_MAX),
                [&](long long v) { o.maxAssignments = uint64_t(v); });
    synthMaxSecondsFlag(cl, o.timeLimitSeconds);
    cl.option("--cell", [&](const std::string& s) {
      need(toDouble(s, cell) && cell > 0, "--cell needs a size greater than 0 and below 1e9");
    });
    cl.repeated("--symmetry", [&](const std::string& s) {
      SymmetrySpec sym;
      need(parseSymmetry(s, sym), "--symmetry is mirror-x, mirror-y, rotate-90, rotate-180, translate-x:N or "
                                  "translate-y:N (N from 1 to " + std::to_string(kMaxTranslation) + ")");
      o.symmetry.push_back(sym);
    });
    cl.repeated("--border", [&](const std::string& spec) {
      const auto eq = spec.find('=');
      const int face = eq == std::string::npos ? -1 : faceFromName(spec.substr(0, eq));
      need(face >= 0, "--border needs FACE=LABEL with FACE one of xmin xmax ymin ymax zmin zmax");
      borders.push_back({face, spec.substr(eq + 1)});
    });
    cl.parse(args);
    if (!trailing.empty()) {
      need(example.empty(), "more than one example given (`" + example + "` and `" + trailing + "`)");
      example = trailing;
    }
  } catch (const UsageError& e) {
    return usage(e.message);
  }
  if (periodic) o.periodic = {true, true, false};
  if (example.empty()) return usage("no example file given");
  if (!haveSize) return usage("--size X Y Z is required");
  if (meshOut.empty() && labelsOut.empty()) meshOut = defaultModelOutput(example);  // as fgsg run

  Example ex;
  Diagnostics diags;
  if (!loadExample(example, ex, diags)) {
    std::fputs(formatDiagnostics(diags).c_str(), stderr);
    return 1;
  }
  BorderSpec border = ex.border;
  if (closed) border = closedLikeExample(ex, border);
  for (const auto& [face, label] : borders) {
    const int32_t l = ex.findLabel(label);
    if (l < 0) return usage("--border: unknown label `" + label + "` in " + example);
    border.outside[size_t(face)] = l;
  }
  o.border = border;
  if (connectSeeds > 0) {
    o.connectivity.enabled = true;
    o.connectivity.seeds = connectSeeds;
  }
  if (!maskPath.empty()) {
    std::string err;
    if (!maskFromImage(maskPath, o.size, ex, 4.0, o.weights, err)) {
      std::fprintf(stderr, "%s: error[E731]: %s\n", maskPath.c_str(), err.c_str());
      return 1;
    }
  }

  ProgressLine progress("fgsg synth", true);
  progress.phase("synthesizing");
  SynthesisResult r = synthesize(ex, o);
  progress.done();
  if (stats) {  // on stdout, as fgsg run --stats prints its figures; messages go to stderr
    const std::pair<const char*, uint64_t> figures[] = {
        {"consistent", r.consistent},        {"size.x", uint64_t(o.size.nx)},
        {"size.y", uint64_t(o.size.ny)},     {"size.z", uint64_t(o.size.nz)},
        {"labels", uint64_t(ex.labelCount())}, {"assignments", r.stats.assignments},
        {"propagation.steps", r.stats.propagationSteps}, {"support.misses", r.stats.supportMisses},
        {"blocks", uint64_t(r.stats.blocks)}, {"blocks.failed", uint64_t(r.stats.blocksFailed)},
        {"block.retries", uint64_t(r.stats.blockRetries)}, {"backtracks", r.stats.backtracks},
        {"repairs", r.stats.repairs},         {"attempts", uint64_t(r.stats.attempts)},
        {"catalog.bytes", r.stats.catalogBytes}};
    for (const auto& [name, value] : figures) printStat(name, value);
    printStatSeconds("synthesize", r.stats.seconds);
  }
  if (!r.ok) {
    std::fprintf(stderr, "%s: error[E740]: synthesis failed: %s\n", example.c_str(), r.failure.message.c_str());
    if (!r.consistent) return 1;
  } else if (r.stats.blocksFailed > 0) {
    std::fprintf(stderr, "%s: warning: %d of %d blocks could not be modified and were kept; last: %s\n",
                 example.c_str(), r.stats.blocksFailed, r.stats.blocks, r.failure.message.c_str());
  }
  // Belt and braces: never write a model the independent checker rejects.
  CheckSpec spec;
  spec.periodic = o.periodic;
  spec.border = o.border;
  spec.symmetry = o.symmetry;
  spec.weights = o.weights.empty() ? nullptr : &o.weights;
  spec.connectivity = o.connectivity;
  if (auto v = checkModel(r.labels, ex, spec); !v.empty()) {
    std::fprintf(stderr, "%s: error[E741]: internal error: output fails the checker: %s\n", example.c_str(),
                 v[0].what.c_str());
    return 1;
  }

  // Never a silent empty file (#46): a model that is empty space in every cell (every block
  // failed, or the mask or borders left room for nothing else) is an error.
  const auto& cells = r.labels.data();
  if (r.ok && ex.emptyLabel >= 0 && !cells.empty() &&
      std::all_of(cells.begin(), cells.end(), [&](int32_t l) { return l == ex.emptyLabel; })) {
    std::fprintf(stderr,
                 "%s: error[E746]: the synthesized model is empty space in every cell (label %s), nothing "
                 "was written: %s; try another --seed, more --retries or --attempts, a larger --size, or "
                 "fewer constraints (--mask, --border, --closed, --symmetry)\n",
                 example.c_str(), ex.labels[size_t(ex.emptyLabel)].name.c_str(),
                 r.stats.blocksFailed > 0 ? (std::to_string(r.stats.blocksFailed) + " of " +
                                             std::to_string(r.stats.blocks) + " blocks found no consistent labels")
                                                .c_str()
                                          : "the constraints allow nothing but empty space here");
    return 1;
  }

  // The label grid, mesh and preview are staged and replace their files together, only
  // when all of them could be written.
  rt::io::OutputTransaction outputs;
  if (!labelsOut.empty()) {
    std::string err;
    if (!outputs.stage(labelsOut, writeLabelGridText(r.labels, ex), err)) {
      std::fprintf(stderr, "%s: error[E742]: cannot write the label grid: %s\n", labelsOut.c_str(), err.c_str());
      return 1;
    }
  }
  if (!meshOut.empty() || !previewOut.empty()) {
    PlacementFrame frame;
    frame.cellSize = {cell, cell, cell};
    rt::InstanceList list;
    appendInstances(piecePlacements(r.labels, ex, frame), "Synth", list);
    rt::AssetLibrary lib;
    lib.addSearchDir(dirOf(example));
    std::vector<int> meshOf;
    std::string err;
    if (!rt::resolveAssets(list, lib, meshOf, err)) {
      std::fprintf(stderr, "%s: error[E743]: %s\n", example.c_str(), err.c_str());
      return 1;
    }
    rt::Mesh mesh = rt::assembleInstances(list, lib, meshOf);
    if (!meshOut.empty() && !rt::io::stageMesh(mesh, meshOut, outputs, err)) {
      std::fprintf(stderr, "%s: error[E744]: %s\n", meshOut.c_str(), err.c_str());
      return 1;
    }
    if (!previewOut.empty()) {
      rt::render::PreviewOptions po;
      std::string warning;
      if (!rt::render::stagePreview(mesh, po, previewOut, outputs, err, &warning)) {
        std::fprintf(stderr, "%s: error[E745]: %s\n", previewOut.c_str(), err.c_str());
        return 1;
      }
      if (!warning.empty()) std::fprintf(stderr, "%s: warning: %s\n", previewOut.c_str(), warning.c_str());
    }
  }
  if (std::string err; !outputs.commit(err)) {
    std::fprintf(stderr, "fgsg synth: error[E742]: %s\n", err.c_str());
    return 1;
  }
  // What was written, as fgsg run says it.
  std::string wrote;
  for (const std::string* f : {&meshOut, &labelsOut, &previewOut})
    if (!f->empty()) wrote += (wrote.empty() ? "" : ", ") + *f;
  if (!wrote.empty())
    std::fprintf(stderr, "wrote %s (%d x %d x %d cells, %d labels)\n", wrote.c_str(), r.labels.size().nx,
                 r.labels.size().ny, r.labels.size().nz, ex.labelCount());
  return r.ok ? 0 : 1;
}

}  // namespace fgsg::cli
