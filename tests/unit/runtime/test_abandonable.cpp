// runtime/abandonable.h: work on a worker thread, waited for until a deadline.
#include "runtime/abandonable.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <stdexcept>
#include <thread>

using namespace fgsg::rt;

TEST_CASE("abandonable: work that ends in time gives its result or what it threw", "[abandonable]") {
  Deadline deadline = Deadline::after(60);
  CHECK(runAbandonable(&deadline, false, [] { return 42; }) == 42);
  CHECK(runAbandonable(&deadline, true, [] { return 7; }) == 7);      // inline
  CHECK(runAbandonable(nullptr, false, [] { return 8; }) == 8);       // no deadline: inline
  CHECK_THROWS_AS(runAbandonable(&deadline, false, []() -> int { throw std::runtime_error("no"); }),
                  std::runtime_error);
}

TEST_CASE("abandonable: work past the deadline is abandoned with TimeLimitReached", "[abandonable]") {
  const int before = abandonedWorkers();
  Deadline deadline = Deadline::after(0.05);
  const auto start = std::chrono::steady_clock::now();
  CHECK_THROWS_AS(runAbandonable(&deadline, false,
                                 [] {
                                   std::this_thread::sleep_for(std::chrono::milliseconds(400));
                                   return 1;
                                 }),
                  TimeLimitReached);
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::milliseconds(300));
  CHECK(abandonedWorkers() == before + 1);
  // A deadline already passed: refused at once, no worker started.
  CHECK_THROWS_AS(runAbandonable(&deadline, false, [] { return 1; }), TimeLimitReached);
  // The abandoned worker ends on its own and is no longer counted.
  for (int i = 0; i < 100 && abandonedWorkers() > before; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  CHECK(abandonedWorkers() == before);
}
