// The deadline (--max-seconds) and the memory budget (--max-memory): sizes as written on
// the command line, and a deadline noticed soon after it passes however cheap or costly
// each question's unit of work is.
#include "runtime/deadline.h"
#include "runtime/memory_budget.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <thread>
#include <vector>

using namespace fgsg::rt;
using Clock = std::chrono::steady_clock;

namespace {

// Busy work of about `micros` microseconds, then one question to the deadline; the
// seconds from the deadline's end to the first `true`.
double overshoot(double limit, double micros) {
  Deadline d = Deadline::after(limit);
  const auto end = d.start() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limit));
  for (;;) {
    const auto until = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double, std::micro>(micros));
    while (Clock::now() < until) {
    }
    if (d.expired()) return std::chrono::duration<double>(Clock::now() - end).count();
  }
}

}  // namespace

TEST_CASE("memory sizes: binary units, optional B or iB, any case") {
  CHECK(parseMemorySize("512M") == 512ull << 20);
  CHECK(parseMemorySize("2G") == 2ull << 30);
  CHECK(parseMemorySize("2g") == 2ull << 30);
  CHECK(parseMemorySize("2GB") == 2ull << 30);
  CHECK(parseMemorySize("2GiB") == 2ull << 30);
  CHECK(parseMemorySize("1.5G") == 3ull << 29);
  CHECK(parseMemorySize("64k") == 64ull << 10);
  CHECK(parseMemorySize("1000") == 1000ull);
  CHECK(parseMemorySize("1T") == 1ull << 40);
  for (const char* bad : {"", "0", "-5", "M", "12X", "2GG", "1.5Q", "nan", "inf", " 2G", "2 G", "1e30G"})
    CHECK_FALSE(parseMemorySize(bad).has_value());
  CHECK(formatMemorySize(512ull << 20) == "512M");
  CHECK(formatMemorySize(3ull << 29) == "1.5G");
  CHECK(formatMemorySize(100) == "100B");
}

TEST_CASE("the machine's memory and this process's are read") {
  CHECK(availableMemoryBytes() > (64ull << 20));
  CHECK(defaultMemoryBudget() <= availableMemoryBytes());
  const uint64_t before = residentMemoryBytes();
  CHECK(before > 0);
  std::vector<char> touched(64 << 20, 1);  // 64 MiB, every page written
  CHECK(residentMemoryBytes() >= before + (48ull << 20));
  CHECK(touched[12345] == 1);
}

TEST_CASE("a deadline without a limit never expires") {
  Deadline d;
  for (int i = 0; i < 100000; ++i) REQUIRE_FALSE(d.expired());
  CHECK_FALSE(d.limited());
  CHECK_FALSE(Deadline::after(0).limited());
  CHECK_FALSE(Deadline::after(-1).limited());
}

TEST_CASE("a deadline is noticed within a millisecond or so, for cheap and costly units") {
  // Loose bounds: the tests share a loaded machine, where a thread may lose its core for
  // tens of milliseconds (22 ms was seen under ctest -j2); a stride gone wrong overshoots
  // by far more.
  CHECK(overshoot(0.05, 0.01) < 0.05);  // 10 ns units: the stride grows to its cap
  CHECK(overshoot(0.05, 20) < 0.05);    // 20 us units: a clock read every few units
  CHECK(overshoot(0.05, 500) < 0.05);   // 0.5 ms units: every unit
  Deadline d = Deadline::after(0.01);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  CHECK(d.passed());
  CHECK(d.expiredNow());
  CHECK(d.expired());  // and from then on
  CHECK_THROWS_AS(d.check(), TimeLimitReached);
  CHECK(d.remainingSeconds() == 0);
}

TEST_CASE("after cheap units, costly ones are still timed: the stride adapts") {
  Deadline d = Deadline::after(0.1);
  int early = 0;
  for (int i = 0; i < 200000; ++i) early += d.expired();  // ~1 ns units: the stride grows
  CHECK(early == 0);
  while (!d.expired()) {  // 20 us units from now on
    const auto until = Clock::now() + std::chrono::microseconds(20);
    while (Clock::now() < until) {
    }
  }
  const auto end = d.start() + std::chrono::milliseconds(100);
  CHECK(std::chrono::duration<double>(Clock::now() - end).count() < 0.02);
}
