// The JIT against the interpreter, one core: derivation throughput of the same grammars
// (bench/bench_grammars.h; the best of several runs each, the JIT's compile excluded),
// and compile latency of a 30-rule grammar: cold (an empty object cache, a new JIT) until
// the first tier can run, cold for the optimised tier alone, and from the cache. Each derivation pair is checked to agree exactly.
//   build/bin/bench_jit [--quick]
#include "backend/interp/interpreter.h"
#include "backend/jit/jit.h"
#include "backend/native/object_cache.h"
#include "bench/bench_grammar.h"
#include "bench/bench_grammars.h"
#include "frontend/diagnostics.h"
#include "ir/pipeline.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>

#include <unistd.h>

namespace {

using namespace fgsg;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

ir::Module compile(const std::string& text) { return bench::compileGrammarText(text); }

template <class Derive>
double best(int reps, Derive derive, rt::DeriveResult& last) {
  double b = 1e30;
  for (int i = 0; i < reps; ++i) {
    const auto t0 = Clock::now();
    rt::DeriveResult r = derive();
    b = std::min(b, since(t0));
    if (!r.ok) {
      std::fprintf(stderr, "derivation failed: %s\n", r.messages.empty() ? "?" : r.messages[0].message.c_str());
      std::exit(1);
    }
    last = std::move(r);
  }
  return b;
}

bool same(const rt::DeriveResult& a, const rt::DeriveResult& b) {
  const auto& x = a.instances.instances;
  const auto& y = b.instances.instances;
  if (x.size() != y.size() || a.stats.shapesCreated != b.stats.shapesCreated ||
      a.stats.terminals != b.stats.terminals || a.stats.rewrites != b.stats.rewrites)
    return false;
  for (size_t i = 0; i < x.size(); ++i)
    if (x[i].transform != y[i].transform || x[i].asset != y[i].asset)
      return false;
  return true;
}

void compare(const char* name, const char* text, int reps, backend::jit::Jit& jit) {
  const ir::Module m = compile(text);
  rt::AssetLibrary assets;
  const auto code = jit.compileProgram(m, text, backend::native::ObjectCache(std::string()));
  const auto firstTier = jit.compileProgram(m, text, backend::native::ObjectCache(std::string()),
                                            backend::native::Tiering::Baseline);
  rt::DeriveResult ri, rj, rb;
  const double interp = best(reps, [&] { return backend::interpret(m, {}, assets); }, ri);
  const double jitted = best(reps, [&] { return backend::deriveCompiled(m, code.program(), {}, assets); }, rj);
  const double baseline = best(reps, [&] { return backend::deriveCompiled(m, firstTier.program(), {}, assets); }, rb);
  if (!same(ri, rj) || !same(ri, rb)) {
    std::fprintf(stderr, "%s: the JIT's result differs from the interpreter's\n", name);
    std::exit(1);
  }
  const auto& s = rj.stats;
  std::printf("{\"bench\":\"jit\",\"grammar\":\"%s\",\"shapes\":%llu,\"terminals\":%llu,"
              "\"interp_s\":%.6f,\"jit_s\":%.6f,\"speedup\":%.2f,\"jit_terminals_per_s\":%.0f,"
              "\"jit_shapes_per_s\":%.0f,\"interp_terminals_per_s\":%.0f,\"first_tier_s\":%.6f,"
              "\"first_tier_speedup\":%.2f}\n",
              name, (unsigned long long)s.shapesCreated, (unsigned long long)s.terminals, interp, jitted,
              interp / jitted, s.terminals / jitted, s.shapesCreated / jitted, s.terminals / interp, baseline,
              interp / baseline);
  std::fflush(stdout);
}

// 30 rules with parameters, guards, random weights and nested brackets.
std::string thirtyRules() {
  std::string g = "attr depth = 6;\nAxiom ~> R0(0);\n";
  for (int i = 0; i < 30; ++i) {
    const std::string self = "R" + std::to_string(i), next = "R" + std::to_string((i + 1) % 30);
    g += self + "(n) : n < depth ~> [ Rz(" + std::to_string(10 + i) + ") T(0.5, Rand(0, 1), 0) " + next +
         "(n + 1) ] S(1r, 0.9r, 1r) " + next + "(n + 2) : 0.7 ~> Rx(n * 3) " + next + "(n + 1) : 0.3;\n";
  }
  return g;
}

void compileLatency(int reps) {
  const std::string text = thirtyRules();
  const ir::Module m = compile(text);
  const auto folder = std::filesystem::temp_directory_path() / ("fgsg-bench-cache-" + std::to_string(::getpid()));
  double cold = 1e30, optimized = 1e30, cached = 1e30;
  for (int i = 0; i < reps; ++i) {
    // Cold: a new JIT and an empty cache, until the code can run (the first tier; the
    // optimised object is compiled meanwhile for the cache).
    std::filesystem::remove_all(folder);
    const backend::native::ObjectCache cache(folder.string());
    auto t0 = Clock::now();
    {
      backend::jit::Jit jit;
      const auto code = jit.compileProgram(m, text, cache);
      cold = std::min(cold, since(t0));
      if (code.fromCache()) std::exit(1);
    }  // waits for the optimising compile
    // From the cache: a new JIT loading the optimised object.
    t0 = Clock::now();
    {
      backend::jit::Jit jit;
      const auto again = jit.compileProgram(m, text, cache);
      cached = std::min(cached, since(t0));
      if (!again.fromCache() || !again.optimized()) {
        std::fprintf(stderr, "the object cache did not answer with optimised code\n");
        std::exit(1);
      }
    }
    // The optimised tier alone, cold.
    std::filesystem::remove_all(folder);
    t0 = Clock::now();
    {
      backend::jit::Jit jit;
      jit.compileProgram(m, text, backend::native::ObjectCache(std::string()));
      optimized = std::min(optimized, since(t0));
    }
  }
  std::filesystem::remove_all(folder);
  std::printf("{\"bench\":\"jit_compile\",\"rules\":%zu,\"cold_s\":%.6f,\"cold_optimized_s\":%.6f,"
              "\"cached_s\":%.6f}\n",
              m.rules.size(), cold, optimized, cached);
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const int reps = quick ? 1 : 5;
  backend::jit::Jit jit;
  compare("planar", bench::kPlanar, reps, jit);
  compare("stochastic", bench::kStochastic, reps, jit);
  compare("lsystem", bench::kLSystem, reps, jit);
  compare("planar_instances", bench::kPlanarInstances, reps, jit);
  compileLatency(quick ? 2 : 5);
  return 0;
}
