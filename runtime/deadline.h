// A wall-clock limit (--max-seconds) that hot loops can ask about at every unit of work
// (a rewrite, a trace step, a block of smoothed vertices) without slowing down: the
// steady clock is read only every `stride` questions, and the stride adapts so that the
// clock is read about every 0.05-0.2 ms of work whatever one unit costs. One deadline is
// made per derivation and passed down to every phase that may run long.
//
// Not thread-safe (the countdown is plain): one thread asks `expired()`; other threads
// may ask `passed()`, which reads the clock every time.
//
// The clock is the steady clock unless a test passes its own time source, so that the
// stride's behaviour is checked without wall-clock thresholds (timing lives in bench/).
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <limits>

namespace fgsg::rt {

// Thrown by Deadline::check() in runtime code that cannot end a derivation itself (a
// trace, smoothing): the engine turns it into its own message where it knows the phase.
struct TimeLimitReached {
  double seconds = 0;  // the limit that was reached
};

class Deadline {
 public:
  using Clock = std::chrono::steady_clock;
  // Where the deadline reads the time: Clock::now, or a test's fake clock.
  using TimeSource = Clock::time_point (*)();

  // Never expires.
  Deadline() = default;
  // Expires `seconds` after `start` (not finite or not positive: never), by `now`'s time.
  Deadline(Clock::time_point start, double seconds, TimeSource now = &Clock::now)
      : start_(start), last_(start), seconds_(seconds), now_(now) {
    if (seconds > 0 && seconds < 1e9)
      end_ = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
  }
  static Deadline after(double seconds) { return Deadline(Clock::now(), seconds); }

  // True once the time is up (and from then on). Cheap: a decrement, and now and then
  // a clock read.
  bool expired() noexcept {
    if (--countdown_ > 0) return false;
    return poll();
  }
  // expired(), throwing TimeLimitReached.
  void check() {
    if (expired()) throw TimeLimitReached{seconds_};
  }
  // Reads the clock now (for checks that are already rare, such as every 4096 rewrites).
  bool expiredNow() noexcept {
    countdown_ = 1;
    return poll();
  }
  // Thread-safe: whether the end has passed, reading the clock.
  bool passed() const noexcept { return expired_ || now_() >= end_; }

  bool limited() const noexcept { return end_ != Clock::time_point::max(); }
  double seconds() const noexcept { return seconds_; }
  Clock::time_point start() const noexcept { return start_; }
  double remainingSeconds() const noexcept {
    if (!limited()) return std::numeric_limits<double>::infinity();
    return std::max(0.0, std::chrono::duration<double>(end_ - now_()).count());
  }
  // When the clock was last read by expired() / expiredNow(): other periodic checks
  // (the memory budget) piggyback on it instead of reading the clock themselves.
  Clock::time_point lastRead() const noexcept { return last_; }

 private:
  // Reads between 50 and 200 microseconds apart: the stride doubles while reads come
  // sooner and drops to a quarter when they come later, so a switch from cheap units of
  // work to costly ones overshoots by at most kMaxStride of the costly ones, once.
  static constexpr int64_t kMaxStride = 1024;

  bool poll() noexcept {
    if (expired_) {  // sticky, and every later question comes straight here
      countdown_ = 0;
      return true;
    }
    const Clock::time_point now = now_();
    const auto gap = now - last_;
    last_ = now;
    if (gap < std::chrono::microseconds(50)) stride_ = std::min(stride_ * 2, kMaxStride);
    else if (gap > std::chrono::microseconds(200)) stride_ = std::max<int64_t>(1, stride_ / 4);
    countdown_ = stride_;
    if (now >= end_) expired_ = true, countdown_ = 0;
    return expired_;
  }

  Clock::time_point start_ = Clock::now();
  Clock::time_point end_ = Clock::time_point::max();
  Clock::time_point last_ = start_;
  double seconds_ = std::numeric_limits<double>::infinity();
  int64_t stride_ = 1;
  int64_t countdown_ = 1;
  bool expired_ = false;
  TimeSource now_ = &Clock::now;
};

}  // namespace fgsg::rt
