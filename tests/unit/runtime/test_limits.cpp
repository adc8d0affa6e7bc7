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

// A fake steady clock the tests move by hand: the deadline's stride is checked exactly,
// with no wall-clock thresholds on a loaded machine (timing lives in bench/).
Clock::time_point fakeNow;
Clock::time_point readFakeClock() { return fakeNow; }

Clock::duration micros(double us) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double, std::micro>(us));
}

// Units of work of `unitMicros` each on the fake clock, one question to the deadline
// after each: how long after the deadline's end the first `true` comes, in units.
double unitsLate(Deadline& d, double unitMicros) {
  const Clock::time_point end = d.start() + micros(d.seconds() * 1e6);
  for (;;) {
    fakeNow += micros(unitMicros);
    if (d.expired()) return std::chrono::duration<double, std::micro>(fakeNow - end).count() / unitMicros;
  }
}

double unitsLate(double limit, double unitMicros) {
  fakeNow = Clock::time_point{};
  Deadline d(fakeNow, limit, readFakeClock);
  return unitsLate(d, unitMicros);
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

TEST_CASE("a deadline is noticed within one stride of units, for cheap and costly units") {
  // The clock is read when the stride's countdown runs out; the stride doubles while reads
  // come under 50 us apart, up to 1024, and falls to a quarter when they come over 200 us
  // apart. So the deadline is noticed at most a stride of units late:
  CHECK(unitsLate(0.05, 0.01) <= 1024);  // 10 ns units: the stride grows to its cap
  CHECK(unitsLate(0.05, 0.01) >= 0);
  // 20 us units: the stride doubles to 4 (reads 80 us apart) and stays there.
  CHECK(unitsLate(0.05, 20) < 4);
  // 0.5 ms units: every unit reads the clock, so the first unit past the end sees it.
  CHECK(unitsLate(0.05, 500) < 1);
  CHECK(unitsLate(0.05, 500) >= 0);
}

TEST_CASE("a passed deadline stays passed, and says so every way") {
  fakeNow = Clock::time_point{};
  Deadline d(fakeNow, 0.01, readFakeClock);
  fakeNow += micros(5000);
  CHECK_FALSE(d.passed());
  CHECK_FALSE(d.expiredNow());
  CHECK(d.remainingSeconds() == Approx(0.005));
  fakeNow += micros(15000);
  CHECK(d.passed());
  CHECK(d.expiredNow());
  fakeNow -= micros(15000);  // even were the clock to go back: expiry is sticky
  CHECK(d.expired());
  CHECK_THROWS_AS(d.check(), TimeLimitReached);
  fakeNow += micros(15000);
  CHECK(d.remainingSeconds() == 0);
}

TEST_CASE("the real clock: a deadline after a short limit has passed once the limit has") {
  // Only a lower bound on elapsed time, which a loaded machine cannot break.
  Deadline d = Deadline::after(0.001);
  std::this_thread::sleep_for(std::chrono::milliseconds(2));
  CHECK(d.passed());
  CHECK(d.expiredNow());
}

TEST_CASE("after cheap units, costly ones are still timed: the stride adapts") {
  fakeNow = Clock::time_point{};
  Deadline d(fakeNow, 0.1, readFakeClock);
  int early = 0;
  for (int i = 0; i < 200000; ++i) {  // 1 ns units: the stride grows to 1024
    fakeNow += micros(0.001);
    early += d.expired();
  }
  CHECK(early == 0);
  // 20 us units from now on: the first read comes at most 1024 units (20 ms) late and
  // quarters the stride, as do the next until it is 4 again, long before the end at 100 ms.
  CHECK(unitsLate(d, 20) < 4);
}
