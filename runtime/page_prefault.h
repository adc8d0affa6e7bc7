// Faulting in fresh memory ahead of its writer. A large output array (the instances of a
// million-segment L-system: 268 MB) is filled by one thread, and the kernel zeroing each
// page on first touch was a third of that thread's time. PrefaultAhead asks the kernel to
// map the pages (MADV_POPULATE_WRITE) on a second thread while the first fills them;
// populating never changes what a page already holds, so the two need no coordination.
// Where the kernel cannot (before Linux 5.14, other systems) nothing happens.
#pragma once

#include <atomic>
#include <cstddef>
#include <thread>

namespace fgsg::rt {

class PrefaultAhead {
 public:
  // Starts populating [begin, begin + bytes) from its start; small ranges are left alone.
  PrefaultAhead(void* begin, size_t bytes);
  ~PrefaultAhead();  // stops and waits: the range may be freed after this
  PrefaultAhead(const PrefaultAhead&) = delete;
  PrefaultAhead& operator=(const PrefaultAhead&) = delete;

 private:
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace fgsg::rt
