// L-systems in process, the workloads the npm `lindenmayer` package was measured on (issue
// #17: F -> FFF for 10 and 13 steps, ABOP Fig. 1.24d for 7 and 9), and a parametric one
// (the Koch curve with lengths, Fig. 1.6's rule) that the JIT compiles and a context-sensitive
// one (ABOP Fig. 1.31a, grown to 50 steps): per workload the
// rewriting (modules of the final string per second of the rewriting steps), the turtle
// (segments per second of the rest of the derivation) and the string's bytes per module
// (16 per module plus 8 per argument). The interpreter and the JIT must agree exactly.
// The best of several runs each. Targets on this machine (issue 48): >= 200 M modules/s
// for template rewriting (F -> FFF n=13), >= 20 M segments/s, <= 16 bytes per module.
//   build/bin/bench_lsystem [--quick]
//   build/bin/bench_lsystem --warm FILE REPS
// --warm: one grammar file, compiled by the JIT once and derived REPS times in this process
// (the warm figure bench/lsystem_vs_lindenmayer.sh sets beside lindenmayer's warm one):
// the fastest and median rewriting (`time.rewrite`) and whole derivation (`time.derive`).
#include "backend/interp/interpreter.h"
#include "backend/jit/jit.h"
#include "backend/native/object_cache.h"
#include "bench/bench_grammar.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

using namespace fgsg;

struct Workload {
  const char* name;
  std::string text;
};

std::string fff(int n) { return "derive parallel " + std::to_string(n) + ";\naxiom: F;\nF -> F F F;\n"; }

std::string fig124d(int n) {
  return "derive parallel " + std::to_string(n) +
         ";\nturtle angle 20;\naxiom: X;\nX -> F [ + X ] F [ - X ] + X;\nF -> F F;\n";
}

// ABOP Fig. 1.31a (examples/abop/fig1_31a.fgsg): context-sensitive, with #ignore and
// rules for + and -; every module is matched against its neighbours.
std::string fig131a(int n) {
  return "derive parallel " + std::to_string(n) +
         ";\nturtle angle 22.5;\n#ignore: + - F;\naxiom: F b F b F b;\n"
         "a < a > a -> a;\na < a > b -> b [ + F b F b ];\na < b > a -> b;\na < b > b -> b;\n"
         "b < a > a -> a;\nb < a > b -> b F b;\nb < b > a -> b;\nb < b > b -> a;\n+ -> -;\n- -> +;\n";
}

std::string koch(int n) {
  return "derive parallel " + std::to_string(n) +
         ";\nturtle angle 60;\naxiom: F(1);\nF(l) -> F(l / 3) + F(l / 3) - - F(l / 3) + F(l / 3);\n";
}

struct Run {
  rt::DeriveResult result;
  double rewrite = 1e30, turtle = 1e30;
};

template <class Derive>
Run best(int reps, Derive derive) {
  Run b;
  for (int i = 0; i < reps; ++i) {
    rt::DeriveResult r = derive();
    if (!r.ok) {
      std::fprintf(stderr, "derivation failed: %s\n", r.messages.empty() ? "?" : r.messages[0].message.c_str());
      std::exit(1);
    }
    b.rewrite = std::min(b.rewrite, r.stats.rewriteSeconds);
    b.turtle = std::min(b.turtle, r.stats.deriveSeconds - r.stats.rewriteSeconds);
    b.result = std::move(r);
  }
  return b;
}

bool same(const rt::DeriveResult& a, const rt::DeriveResult& b) {
  const auto& x = a.instances.instances;
  const auto& y = b.instances.instances;
  if (x.size() != y.size() || a.stats.stringLength != b.stats.stringLength || a.stats.rewrites != b.stats.rewrites)
    return false;
  for (size_t i = 0; i < x.size(); ++i)
    if (x[i].transform != y[i].transform || x[i].asset != y[i].asset) return false;
  return true;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

// --warm FILE REPS: per repetition, the derivation's own clocks (compilation excluded).
int warm(const char* path, int reps) {
  const ir::Module m = bench::compileGrammarFile(path);
  backend::jit::Jit jit;
  rt::AssetLibrary assets;
  const auto code = jit.compileProgram(m, path, backend::native::ObjectCache(std::string()));
  std::vector<double> rewrite, derive;
  rt::DeriveResult r;
  for (int i = 0; i < reps; ++i) {
    r = backend::deriveCompiled(m, code.program(), {}, assets);
    if (!r.ok) {
      std::fprintf(stderr, "%s: derivation failed: %s\n", path, r.messages.empty() ? "?" : r.messages[0].message.c_str());
      return 1;
    }
    rewrite.push_back(r.stats.rewriteSeconds);
    derive.push_back(r.stats.deriveSeconds);
  }
  std::printf("{\"modules\":%llu,\"segments\":%zu,\"reps\":%d,\"rewrite_s\":%.6f,\"rewrite_median_s\":%.6f,"
              "\"derive_s\":%.6f,\"derive_median_s\":%.6f}\n",
              static_cast<unsigned long long>(r.stats.stringLength), r.instances.instances.size(), reps,
              *std::min_element(rewrite.begin(), rewrite.end()), median(rewrite),
              *std::min_element(derive.begin(), derive.end()), median(derive));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "--warm") == 0) {
    if (argc != 4 || std::atoi(argv[3]) < 1) {
      std::fprintf(stderr, "usage: bench_lsystem --warm FILE REPS\n");
      return 2;
    }
    return warm(argv[2], std::atoi(argv[3]));
  }
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const int reps = quick ? 2 : 5;
  std::vector<Workload> workloads = {{"F->FFF n=10", fff(10)},
                                     {"F->FFF n=13", fff(13)},
                                     {"ABOP 1.24d n=7", fig124d(7)},
                                     {"ABOP 1.24d n=9", fig124d(9)},
                                     {"Koch F(l) n=8", koch(8)},
                                     {"ABOP 1.31a n=50 (context)", fig131a(50)}};
  if (quick) workloads.erase(workloads.begin() + 1), workloads.erase(workloads.begin() + 2);
  backend::jit::Jit jit;
  rt::AssetLibrary assets;
  for (const Workload& w : workloads) {
    const ir::Module m = bench::compileGrammarText(w.text);
    const auto code = jit.compileProgram(m, w.text, backend::native::ObjectCache(std::string()));
    const Run interp = best(reps, [&] { return backend::interpret(m, {}, assets); });
    const Run jitted = best(reps, [&] { return backend::deriveCompiled(m, code.program(), {}, assets); });
    if (!same(interp.result, jitted.result)) {
      std::fprintf(stderr, "%s: the JIT's result differs from the interpreter's\n", w.name);
      return 1;
    }
    const auto& s = interp.result.stats;
    const double modules = double(s.stringLength);
    const double segments = double(interp.result.instances.instances.size());
    const double rewrite = std::min(interp.rewrite, jitted.rewrite);
    const double turtle = std::min(interp.turtle, jitted.turtle);
    std::printf("{\"bench\":\"lsystem\",\"workload\":\"%s\",\"modules\":%.0f,\"segments\":%.0f,"
                "\"interp_rewrite_s\":%.6f,\"jit_rewrite_s\":%.6f,\"modules_per_s\":%.0f,\"turtle_s\":%.6f,"
                "\"segments_per_s\":%.0f,\"bytes_per_module\":%.1f}\n",
                w.name, modules, segments, interp.rewrite, jitted.rewrite, modules / rewrite, turtle,
                segments / turtle, double(s.stringBytes) / modules);
    std::fflush(stdout);
  }
  return 0;
}
