// fgsg evolve TILES.json: the genetic algorithm of Chan & Hui 2013 (§4) on a tile file,
// outside any grammar: it reports the best and mean fitness of every generation (a
// progress line while it runs, on a terminal), prints the best L-system, and can write
// it with its history as JSON (--json) and draw its pattern (--preview). With --lsystem
// it skips the search and measures and draws the L-system given (the paper's Figs. 2-3).
// With --surface it lays the pattern on a mesh through the inverse poly-cube map (§5),
// leaving out cells stretched beyond --max-stretch (§6.4), and --stats prints the
// ornament's figures, the cells' stretch among them. See docs/evolve.md.
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/options.h"
#include "runtime/evolve/genetic.h"
#include "runtime/evolve/pattern_picture.h"
#include "runtime/evolve/polycube_map.h"
#include "runtime/evolve/surface_ornament.h"
#include "runtime/io/atomic_file.h"
#include "runtime/io/png_encode.h"
#include "runtime/io/read_input.h"
#include "runtime/surface/load_surface.h"

#include <nlohmann/json.hpp>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>

namespace fgsg::cli {
namespace {

namespace ev = rt::evolve;

const char* kEvolveUsage =
    "usage: fgsg evolve TILES.json [--k K] [--axiom-side A] [--generation G] [--p4] [--seed N]\n"
    "                   [--population N] [--max-generations N] [--threshold F] [--parents N]\n"
    "                   [--elite N] [--crossover P] [--mutation P] [--weights a,b,c[,d]]\n"
    "                   [--max-seconds S] [--lsystem '{...}'] [--json out.json]\n"
    "                   [--preview out.png] [--cell-pixels N] [-q]\n"
    "                   [--surface MESH [--resolution N] [--max-stretch R] [--stats]]\n";

struct EvolveCommandOptions {
  std::string tiles, json, preview, lsystem, surface;
  ev::EvolveOptions ga;
  int resolution = 8;                         // polycube cells along the surface's largest extent
  double maxStretch = ev::kDefaultMaxStretch;  // 0: no limit
  bool stats = false;
  double maxSeconds = 0;  // 0: no limit
  int cellPixels = 32;
  bool quiet = false;
};

double probability(const std::string& flag, const std::string& v) {
  const double p = CommandLine::parseNumber(flag, v);
  if (!(p >= 0 && p <= 1)) throw UsageError{flag + " expects a probability from 0 to 1, got " + std::to_string(p)};
  return p;
}

// --weights a,b,c or a,b,c,d: Eq. 6's symmetry, connectivity, complexity (and p4) weights.
ev::FitnessWeights weights(const std::string& v) {
  double w[4] = {0, 0, 0, ev::FitnessWeights{}.p4};
  std::istringstream in(v);
  std::string part;
  int n = 0;
  while (std::getline(in, part, ',')) {
    char* end = nullptr;
    const double d = std::strtod(part.c_str(), &end);
    if (n == 4 || part.empty() || *end != '\0' || !std::isfinite(d) || d < 0) n = 5;
    if (n < 4) w[n] = d;
    ++n;
  }
  if (n != 3 && n != 4)
    throw UsageError{"--weights expects a,b,c or a,b,c,d (numbers >= 0: symmetry, connectivity, complexity, p4), got '" +
                     v + "'"};
  if (w[0] + w[1] + w[2] <= 0) throw UsageError{"--weights: a, b and c cannot all be 0"};
  return {w[0], w[1], w[2], w[3]};
}

EvolveCommandOptions parseOptions(const Args& args) {
  EvolveCommandOptions o;
  bool parentsGiven = false, eliteGiven = false;
  CommandLine cl("evolve");
  cl.input(o.tiles, "tile file");
  cl.whole("--k", o.ga.ruleSide, 1, 16);
  cl.whole("--axiom-side", o.ga.axiomSide, 1, 16);
  cl.whole("--generation", o.ga.generation, 0, 12);
  cl.flag("--p4", o.ga.p4);
  cl.whole("--seed", o.ga.seed);
  cl.whole("--population", o.ga.population, 2, 100000);
  cl.whole("--max-generations", o.ga.maxGenerations, 0, 1000000);
  auto rate = [&](const char* flag, double& target) {
    cl.option(flag, [&target, flag](const std::string& v) { target = probability(flag, v); });
  };
  rate("--threshold", o.ga.threshold);
  cl.option("--parents", [&](const std::string& v) {
    o.ga.parents = int(CommandLine::parseWhole("--parents", v, 1, 100000));
    parentsGiven = true;
  });
  cl.option("--elite", [&](const std::string& v) {
    o.ga.elite = int(CommandLine::parseWhole("--elite", v, 0, 100000));
    eliteGiven = true;
  });
  rate("--crossover", o.ga.crossoverRate);
  rate("--mutation", o.ga.mutationRate);
  cl.option("--weights", [&](const std::string& v) { o.ga.weights = weights(v); });
  cl.option("--max-seconds", [&](const std::string& v) {
    o.maxSeconds = CommandLine::parseNumber("--max-seconds", v);
    if (!(o.maxSeconds > 0)) throw UsageError{"--max-seconds expects a positive number of seconds"};
  });
  cl.text("--lsystem", o.lsystem);
  cl.text("--json", o.json);
  cl.text("--preview", o.preview);
  cl.whole("--cell-pixels", o.cellPixels, 4, 1024);
  cl.flag("-q,--quiet", o.quiet);
  cl.text("--surface", o.surface);
  cl.whole("--resolution", o.resolution, 1, ev::kMaxPolycubeResolution);
  cl.option("--max-stretch", [&](const std::string& v) {
    o.maxStretch = CommandLine::parseNumber("--max-stretch", v);
    if (!(o.maxStretch == 0 || (o.maxStretch >= 1 && std::isfinite(o.maxStretch))))
      throw UsageError{"--max-stretch expects a ratio of at least 1 (longest to shortest side of a cell), or 0 for "
                       "no limit, got '" + v + "'"};
  });
  cl.flag("--stats", o.stats);
  cl.parse(args);
  if (o.surface.empty() && o.stats)
    throw UsageError{"--stats reports the ornament on a surface: give --surface MESH"};
  if (o.tiles.empty()) throw UsageError{"no tile file given (docs/evolve.md describes the format)"};
  if (!o.preview.empty() && lowerExtension(o.preview) != ".png")
    throw UsageError{"--preview " + o.preview + ": previews are PNG files (name it .png)"};
  if (!o.json.empty() && lowerExtension(o.json) != ".json")
    throw UsageError{"--json " + o.json + ": name the file .json"};
  // Defaults that would not fit a small population are capped at it; given ones are not.
  if (o.ga.parents > o.ga.population) {
    if (parentsGiven) throw UsageError{"--parents cannot exceed --population"};
    o.ga.parents = o.ga.population;
  }
  if (o.ga.elite >= o.ga.population) {
    if (eliteGiven) throw UsageError{"--elite must be smaller than --population"};
    o.ga.elite = o.ga.population - 1;
  }
  return o;
}

const char* stopWords(ev::StopReason s) {
  switch (s) {
    case ev::StopReason::kThreshold: return "threshold";
    case ev::StopReason::kGenerationLimit: return "generation-limit";
    case ev::StopReason::kDeadline: return "time-limit";
  }
  return "";
}

nlohmann::json termsJson(const ev::FitnessTerms& t) {
  return {{"fitness", t.fitness}, {"symmetry", t.fH}, {"symmetries", t.symmetries},
          {"connectivity", t.fCon}, {"complexity", t.fCom}, {"p4", t.fP4}};
}

std::string describeTerms(const ev::FitnessTerms& t, bool p4) {
  char line[256];
  std::snprintf(line, sizeof line, "fitness %.4f: symmetry %.4f (%d of 6), connectivity %.4f, complexity %.4f",
                t.fitness, t.fH, t.symmetries, t.fCon, t.fCom);
  std::string s = line;
  if (p4) {
    std::snprintf(line, sizeof line, ", p4 %.4f%s", t.fP4, t.fP4 == 1 ? " (a p4 pattern)" : "");
    s += line;
  }
  return s;
}

// One transaction per file: written whole or not at all.
bool writeFile(const std::string& path, const std::string& bytes) {
  std::string error;
  if (rt::io::writeFileAtomically(path, bytes, error)) return true;
  std::cerr << "fgsg evolve: cannot write '" << path << "': " << error << "\n";
  return false;
}

// --surface: the pattern on the mesh (no height limit: the stretch is in the surface's
// plane), its figures on stdout with --stats and a counted warning for the cells left out.
int ornamentSurface(const EvolveCommandOptions& opt, const ev::TileSet& tiles, const ev::LSystem2D& best) {
  rt::surface::SurfaceMesh mesh;
  std::string error;
  if (!rt::surface::loadSurface(opt.surface, mesh, error)) {
    std::cerr << "fgsg evolve: --surface " << error << "\n";
    return 1;
  }
  ev::SurfaceOrnamentStats stats;
  try {
    const ev::PolycubeMap map(mesh, ev::PolycubeOptions{0, opt.resolution});
    ev::surfaceOrnament(tiles, ev::expand(best, opt.ga.generation, opt.ga.maxCells), map, {}, {}, &stats,
                        opt.maxStretch);
  } catch (const std::invalid_argument& e) {
    std::cerr << "fgsg evolve: --surface " << opt.surface << ": " << e.what() << "\n";
    return 1;
  }
  if (stats.stretchedCells)
    std::cerr << "fgsg evolve: warning: " << stats.stretchedCells << " of " << stats.cells
              << " cells were left out, stretched beyond --max-stretch " << opt.maxStretch << " (at most "
              << stats.stretch.max << ")\n";
  if (opt.stats)
    std::printf("surface.facelets %zu\nsurface.cells %zu\nsurface.triangles %zu\nsurface.dropped_triangles %zu\n"
                "stretch.median %.6f\nstretch.p95 %.6f\nstretch.max %.6f\nstretch.limit %.6f\n"
                "stretch.left_out_cells %zu\nstretch.emitted_max %.6f\n",
                stats.facelets, stats.cells, stats.triangles, stats.droppedTriangles, stats.stretch.median,
                stats.stretch.p95, stats.stretch.max, opt.maxStretch, stats.stretchedCells, stats.emittedStretch.max);
  return 0;
}

}  // namespace

const char* evolveUsage() { return kEvolveUsage; }

int evolveCommand(const Args& args) {
  EvolveCommandOptions opt;
  try {
    opt = parseOptions(args);
    if (opt.lsystem.empty()) ev::checkOptions(opt.ga);  // --lsystem runs no GA
  } catch (const UsageError& e) {
    std::cerr << "fgsg evolve: " << e.message << "\n" << kEvolveUsage;
    return 2;
  } catch (const std::invalid_argument& e) {
    std::cerr << "fgsg evolve: " << e.what() << "\n" << kEvolveUsage;
    return 2;
  }
  std::string error;
  if (!rt::io::checkInputFile(opt.tiles, "a tile file", error)) {
    std::cerr << "fgsg evolve: " << error << "\n";
    return 1;
  }
  ev::TileSet tiles;
  try {
    tiles = ev::readTileFile(opt.tiles);
  } catch (const ev::TileFileError& e) {
    std::cerr << "fgsg evolve: " << e.what() << "\n";
    return 1;
  }

  ev::LSystem2D best;
  ev::FitnessTerms terms;
  std::optional<ev::EvolveResult> run;
  const auto started = std::chrono::steady_clock::now();
  if (!opt.lsystem.empty()) {
    try {
      best = ev::parseLSystem(opt.lsystem, tiles.letters());
      ev::checkLSystem(best);
      if (best.rules.size() != size_t(tiles.symbolCount()))
        throw std::invalid_argument("the L-system has " + std::to_string(best.rules.size()) + " rules, the tile set " +
                                    std::to_string(tiles.symbolCount()) + " symbols (one rule per symbol)");
      terms = ev::PatternMeasure(tiles).evaluate(ev::expand(best, opt.ga.generation, opt.ga.maxCells), opt.ga.weights,
                                                 opt.ga.p4);
    } catch (const std::exception& e) {
      std::cerr << "fgsg evolve: --lsystem '" << opt.lsystem << "': " << e.what() << "\n";
      return 1;
    }
  } else {
    rt::Deadline deadline = opt.maxSeconds > 0 ? rt::Deadline::after(opt.maxSeconds) : rt::Deadline();
    opt.ga.deadline = &deadline;
    const bool progressLine = !opt.quiet && isatty(STDERR_FILENO);
    if (progressLine)
      opt.ga.progress = [&](const ev::GenerationStats& s) {
        std::fprintf(stderr, "\rgeneration %d of at most %d: best %.4f, mean %.4f (%.1f s)   ", s.generation,
                     opt.ga.maxGenerations, s.best, s.mean, s.seconds);
        std::fflush(stderr);
      };
    try {
      run = ev::evolve(tiles, opt.ga);
    } catch (const rt::TimeLimitReached&) {
      if (progressLine) std::fputs("\n", stderr);
      std::cerr << "fgsg evolve: --max-seconds " << opt.maxSeconds
                << " ran out before the first population was measured; nothing was written\n";
      return 1;
    } catch (const std::invalid_argument& e) {
      if (progressLine) std::fputs("\n", stderr);
      std::cerr << "fgsg evolve: " << e.what() << "\n";
      return 1;
    }
    if (progressLine) std::fputs("\r\033[K", stderr);
    best = run->best;
    terms = run->terms;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const std::string text = ev::formatLSystem(best, tiles.letters());

  if (!opt.quiet && run) {
    std::printf("generation  best    mean    p4\n");
    for (const ev::GenerationStats& s : run->history)
      std::printf("%10d  %.4f  %.4f  %.4f\n", s.generation, s.best, s.mean, s.bestP4);
  }
  std::printf("%s\n", text.c_str());
  if (!opt.quiet) {
    std::printf("%s\n", describeTerms(terms, opt.ga.p4).c_str());
    if (run) {
      const char* why = run->stop == ev::StopReason::kThreshold ? "the fitness threshold was reached"
                        : run->stop == ev::StopReason::kDeadline ? "--max-seconds ran out"
                                                                  : "the generation limit was reached";
      std::printf("%d generations in %.2f s: %s\n", run->generations, seconds, why);
    }
  }

  // The pattern of the measured generation, for --json and --preview.
  ev::AlleleGrid pattern;
  if (!opt.json.empty() || !opt.preview.empty()) pattern = ev::expand(best, opt.ga.generation, opt.ga.maxCells);
  if (!opt.json.empty()) {
    nlohmann::json j = {{"lsystem", text}, {"generation", opt.ga.generation}, {"k", best.ruleSide()},
                        {"seed", opt.ga.seed}, {"p4", opt.ga.p4}, {"terms", termsJson(terms)}};
    if (run) {
      j["stop"] = stopWords(run->stop);
      j["generations"] = run->generations;
      nlohmann::json history = nlohmann::json::array();
      for (const ev::GenerationStats& s : run->history)
        history.push_back({{"generation", s.generation}, {"best", s.best}, {"mean", s.mean}, {"p4", s.bestP4},
                           {"seconds", s.seconds}});
      j["history"] = std::move(history);
    }
    nlohmann::json rows = nlohmann::json::array();
    for (int r = 0; r < pattern.side; ++r) {
      ev::AlleleGrid row(1);
      std::string line;
      for (int c = 0; c < pattern.side; ++c) {
        row.at(0, 0) = pattern.at(r, c);
        line += ev::formatGrid(row, tiles.letters());
      }
      rows.push_back(line);
    }
    j["pattern"] = std::move(rows);
    if (!writeFile(opt.json, j.dump(1) + "\n")) return 1;
  }
  if (!opt.preview.empty()) {
    ev::PatternPicture pic;
    try {
      pic = ev::drawPattern(tiles, pattern, opt.cellPixels);
    } catch (const std::invalid_argument& e) {
      std::cerr << "fgsg evolve: --preview: " << e.what() << "\n";
      return 1;
    }
    std::string png;
    if (!rt::io::encodePng(pic.width, pic.height, 3, pic.rgb.data(), png)) {
      std::cerr << "fgsg evolve: cannot encode the preview picture\n";
      return 1;
    }
    if (!writeFile(opt.preview, png)) return 1;
    if (!opt.quiet) std::printf("wrote %s (%dx%d, %d cells a side)\n", opt.preview.c_str(), pic.width, pic.height,
                                pattern.side);
  }
  if (!opt.surface.empty()) return ornamentSurface(opt, tiles, best);
  return 0;
}

}  // namespace fgsg::cli
