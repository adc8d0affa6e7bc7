// Start-up as a user meets it (issue #18 item 2): whole `fgsg` processes, wall time from
// the spawn to the exit, the median of N runs each. Cases: `--version`, `check`, `synth`
// of a 10x10x10 output, and `run` of a 1 024-shape grammar with its code cached (the
// cache's shared library, no LLVM) and compiled afresh (the LLVM plugin loaded).
// With --before BIN, the same cases for another fgsg binary (an older build) in the same
// run, side by side.
//   build/bin/bench_startup [N] [--before OTHER_FGSG]
#include "bench/bench_clock.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace {

namespace fs = std::filesystem;

// 32 x 32 cubes through two repeats: 1 024 leaf shapes, 1 058 shapes in all.
const char* kGrid = R"(Axiom ~> S(32, 1, 32) Rows;
Rows ~> Repeat("X", 1){ Row };
Row ~> Repeat("Z", 1){ Cell };
Cell ~> S(0.8, 1, 0.8) I("cube");
)";

// One process: argv with stdout/stderr to /dev/null; seconds of wall time, or -1 when it
// did not exit with 0.
double timeProcess(const std::vector<std::string>& args, const std::vector<std::string>& env) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  std::vector<std::string> envStrings(env);
  for (char** e = environ; *e; ++e) envStrings.push_back(*e);
  std::vector<char*> envp;
  for (auto& e : envStrings) envp.push_back(e.data());
  envp.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) return -1;
  int status = 0;
  waitpid(pid, &status, 0);
  const double seconds = fgsg::bench::secondsSince(start);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? seconds : -1;
}

struct Case {
  const char* name;
  std::vector<std::string> args;  // after the binary
  bool freshCache;                // an empty cache folder before each run
  double targetMs;                // issue #18's target; 0: none
};

double medianMs(const std::string& fgsg, const Case& c, int runs, const fs::path& cacheDir) {
  std::vector<std::string> args{fgsg};
  args.insert(args.end(), c.args.begin(), c.args.end());
  const std::vector<std::string> env{"FGSG_CACHE_DIR=" + cacheDir.string()};
  if (!c.freshCache && timeProcess(args, env) < 0) return -1;  // fills the cache
  std::vector<double> ms;
  for (int i = 0; i < runs; ++i) {
    if (c.freshCache) fs::remove_all(cacheDir);
    const double s = timeProcess(args, env);
    if (s < 0) return -1;
    ms.push_back(1e3 * s);
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 21;
  std::string before;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--before" && i + 1 < argc) {
      before = fs::absolute(argv[++i]).string();
    } else if (std::atoi(a.c_str()) > 0) {
      runs = std::atoi(a.c_str());
    } else {
      std::fprintf(stderr, "usage: bench_startup [N] [--before OTHER_FGSG]\n");
      return 2;
    }
  }
  const std::string fgsg = (fs::path(FGSG_BINARY_DIR) / "bin" / "fgsg").string();
  const fs::path work = fs::temp_directory_path() / ("fgsg-bench-startup-" + std::to_string(getpid()));
  fs::create_directories(work);
  const std::string grid = (work / "grid.fgsg").string();
  std::ofstream(grid) << kGrid;
  const std::string castle = std::string(FGSG_SOURCE_DIR) + "/examples/synthesis/castle.txt";
  const std::string koch = std::string(FGSG_SOURCE_DIR) + "/examples/koch.fgsg";
  const std::string glb = (work / "out.glb").string();

  const std::vector<Case> cases{
      {"fgsg --version", {"--version"}, false, 10},
      {"fgsg check koch.fgsg", {"check", koch}, false, 0},
      {"fgsg synth castle.txt --size 10 10 10", {"synth", castle, "--size", "10", "10", "10", "--labels",
                                                  (work / "labels.txt").string()}, false, 20},
      {"fgsg run grid (1 024 shapes), cached", {"run", grid, "-q", "-o", glb}, false, 30},
      {"fgsg run grid, compiled (empty cache)", {"run", grid, "-q", "-o", glb}, true, 0},
      {"fgsg run grid --engine=interp", {"run", grid, "-q", "--engine=interp", "-o", glb}, false, 0},
  };
  std::printf("median wall time of %d processes each (ms)\n", runs);
  std::printf("%-42s %9s%s %8s\n", "case", "this", before.empty() ? "" : "    before", "target");
  for (const Case& c : cases) {
    const double now = medianMs(fgsg, c, runs, work / "cache");
    std::printf("%-42s %9.1f", c.name, now);
    if (!before.empty()) std::printf(" %9.1f", medianMs(before, c, runs, work / "cache-before"));
    if (c.targetMs > 0)
      std::printf(" %8s", (std::string("<= ") + std::to_string(int(c.targetMs))).c_str());
    std::printf("\n");
  }
  fs::remove_all(work);
  return 0;
}
