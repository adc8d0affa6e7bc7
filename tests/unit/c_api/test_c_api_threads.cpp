// fgsg_write from many threads at once: each call writes its own temporary (a random
// name, created exclusively) and renames it, so threads writing distinct paths or the
// same path all succeed and the file is always one whole result. Before, every thread of
// a process used PATH.tmp.<pid>: 5 to 7 of 8 same-path writes failed and the file could
// match none of the results (shared/repro/c_api_threads_same_path.c).
#include "backend/aot/fgsg_api.h"
#include "runtime/abi.h"

#include <catch2/catch.hpp>

#include <dlfcn.h>
#include <stdlib.h>

#include <algorithm>
#include <barrier>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::string readWhole(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

fs::path threadsScratchDir() {
  std::string tmpl = (fs::temp_directory_path() / "fgsg-c-api-threads-XXXXXX").string();
  if (!::mkdtemp(tmpl.data())) FAIL("mkdtemp failed");
  return tmpl;
}

// A grammar whose mesh depends on the seed, compiled with `fgsg compile` and loaded.
const FgsgProgram& seededProgram(const fs::path& dir) {
  const FgsgProgram* program = [&] {
    const fs::path grammar = dir / "seeded.fgsg";
    std::ofstream(grammar) << "Axiom ~> A(5);\n"
                              "A(n): n > 0 ~> I(\"cube\") T(1, 0, 0) R(0, 0, rand(-30, 30)) A(n - 1);\n";
    const fs::path lib = dir / "libseeded.so";
    const std::string cmd = std::string(FGSG_EXE) + " compile '" + grammar.string() + "' -o '" + lib.string() +
                            "' --quiet > '" + (dir / "compile.log").string() + "' 2>&1";
    if (std::system(cmd.c_str()) != 0) FAIL("fgsg compile failed:\n" << readWhole(dir / "compile.log"));
    void* handle = ::dlopen(lib.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) FAIL("dlopen: " << ::dlerror());
    auto* p = static_cast<const FgsgProgram*>(::dlsym(handle, "fgsg_program_seeded"));
    if (!p) FAIL("no fgsg_program_seeded in " << lib);
    return p;
  }();
  return *program;
}

}  // namespace

TEST_CASE("8 threads fgsg_write distinct and identical paths: every call succeeds", "[c_api][threads]") {
  const fs::path dir = threadsScratchDir();
  const FgsgProgram& program = seededProgram(dir);
  constexpr int kThreads = 8, kRounds = 10;
  const fs::path shared = dir / "same.ply";
  std::vector<int> failures(kThreads, 0);
  std::vector<std::string> firstError(kThreads);
  std::barrier start(kThreads);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      fgsg_generator* g = fgsg_generator_create(&program);
      if (!g || fgsg_set_seed(g, uint64_t(t) + 1) != 0 || fgsg_generate(g) != 0) {
        failures[t] = kRounds * 2;
        if (g) firstError[t] = fgsg_last_error(g);
        start.arrive_and_drop();
        fgsg_generator_free(g);
        return;
      }
      start.arrive_and_wait();  // all threads write at once
      const std::string own = (dir / ("own" + std::to_string(t) + ".ply")).string();
      for (int round = 0; round < kRounds; ++round)
        for (const std::string& path : {shared.string(), own})
          if (fgsg_write(g, path.c_str()) != 0) {
            if (failures[t]++ == 0) firstError[t] = fgsg_last_error(g);
          }
      fgsg_generator_free(g);
    });
  for (auto& th : threads) th.join();

  std::vector<std::string> results;
  for (int t = 0; t < kThreads; ++t) {
    INFO("thread " << t << ": " << firstError[t]);
    CHECK(failures[t] == 0);
    results.push_back(readWhole(dir / ("own" + std::to_string(t) + ".ply")));
    CHECK(results.back().size() > 100);
  }
  CHECK(std::count(results.begin(), results.end(), results[0]) < kThreads);  // the seeds differ
  const std::string final = readWhole(shared);
  CHECK(std::find(results.begin(), results.end(), final) != results.end());
  // Only the outputs: no temporary left behind.
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".ply") ++files;
  CHECK(files == kThreads + 1);
  for (const auto& e : fs::directory_iterator(dir)) CHECK(e.path().string().find(".tmp.") == std::string::npos);
  std::error_code ec;
  fs::remove_all(dir, ec);
}
