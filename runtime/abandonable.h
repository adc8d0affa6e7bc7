// Work inside a library that cannot be interrupted (CGAL's straight skeleton, whose time
// grows as the cube of a polygon's corners) made to honour --max-seconds: it runs on a
// worker thread that the caller waits for only until the deadline. When the deadline
// passes first, the worker is abandoned: detached, its result dropped when it ends, and
// the caller throws TimeLimitReached like every phase that reads the deadline itself.
//
// The work must own copies of everything it reads and touch nothing shared (capture by
// value): the caller's data may be gone when an abandoned worker ends. A process that
// ends while abandonedWorkers() > 0 must leave with std::_Exit after flushing, so that
// no static object is destroyed under a running worker (as for abandoned JIT compiles).
#pragma once

#include "runtime/deadline.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <type_traits>
#include <utility>

namespace fgsg::rt {

// Workers abandoned at their deadline that are still running.
int abandonedWorkers() noexcept;

namespace detail {
std::atomic<int>& abandonedWorkerCount() noexcept;
}  // namespace detail

// work() on a worker, its result (or what it threw) once it ends; TimeLimitReached when
// `deadline` passes first. Without a limited deadline, or with `inline_` (work known to
// be small: a thread costs tens of microseconds), work() runs on the calling thread.
template <class Work>
auto runAbandonable(const Deadline* deadline, bool inline_, Work work) -> std::invoke_result_t<Work&> {
  using Result = std::invoke_result_t<Work&>;
  if (inline_ || !deadline || !deadline->limited()) return work();
  if (deadline->passed()) throw TimeLimitReached{deadline->seconds()};
  struct Shared {
    std::mutex m;
    std::condition_variable done;
    std::optional<Result> result;
    std::exception_ptr thrown;
    bool finished = false;
    bool abandoned = false;
  };
  auto shared = std::make_shared<Shared>();
  std::thread([shared, work = std::move(work)]() mutable {
    std::optional<Result> result;
    std::exception_ptr thrown;
    try {
      result.emplace(work());
    } catch (...) {
      thrown = std::current_exception();
    }
    std::lock_guard<std::mutex> lock(shared->m);
    if (shared->abandoned) {
      --detail::abandonedWorkerCount();
      return;  // the result is dropped with the last reference
    }
    shared->result = std::move(result);
    shared->thrown = thrown;
    shared->finished = true;
    shared->done.notify_one();
  }).detach();
  const auto end = Deadline::Clock::now() + std::chrono::duration_cast<Deadline::Clock::duration>(
                                                std::chrono::duration<double>(deadline->remainingSeconds()));
  std::unique_lock<std::mutex> lock(shared->m);
  if (!shared->done.wait_until(lock, end, [&] { return shared->finished; })) {
    shared->abandoned = true;
    ++detail::abandonedWorkerCount();
    throw TimeLimitReached{deadline->seconds()};
  }
  if (shared->thrown) std::rethrow_exception(shared->thrown);
  return std::move(*shared->result);
}

}  // namespace fgsg::rt
