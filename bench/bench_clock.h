// Clocks the benchmarks read: wall time since a point, and this process's processor
// time (on a shared machine the wall clock also counts waiting).
#pragma once

#include <chrono>
#include <ctime>

namespace fgsg::bench {

inline double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

inline double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

}  // namespace fgsg::bench
