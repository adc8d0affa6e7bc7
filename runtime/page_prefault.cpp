#include "runtime/page_prefault.h"

#include <cstdint>
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace fgsg::rt {

namespace {

constexpr size_t kStep = size_t(2) << 20;     // one huge page per call, so stopping is prompt
constexpr size_t kWorthIt = size_t(16) << 20;  // below this a thread costs more than it saves

}  // namespace

PrefaultAhead::PrefaultAhead(void* begin, size_t bytes) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  if (bytes < kWorthIt) return;
  // madvise takes page-aligned ranges: the first whole page on.
  const uintptr_t page = 4096;
  const uintptr_t from = (reinterpret_cast<uintptr_t>(begin) + page - 1) / page * page;
  const uintptr_t to = (reinterpret_cast<uintptr_t>(begin) + bytes) / page * page;
  if (to <= from) return;
  thread_ = std::thread([this, from, to] {
    for (uintptr_t at = from; at < to && !stop_.load(std::memory_order_relaxed); at += kStep) {
      const size_t len = to - at < kStep ? to - at : kStep;
      if (madvise(reinterpret_cast<void*>(at), len, MADV_POPULATE_WRITE) != 0) return;  // unsupported: give up
    }
  });
#else
  (void)begin;
  (void)bytes;
#endif
}

PrefaultAhead::~PrefaultAhead() {
  stop_.store(true, std::memory_order_relaxed);
  if (thread_.joinable()) thread_.join();
}

}  // namespace fgsg::rt
