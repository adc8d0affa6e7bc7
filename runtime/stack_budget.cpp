#include "runtime/stack_budget.h"

#include <algorithm>
#include <pthread.h>

namespace fgsg::rt {

namespace {

// The calling thread's stack: its lowest address and size (size 0: unknown).
struct StackExtent {
  void* low = nullptr;
  size_t size = 0;
};

StackExtent askStackExtent() {
  StackExtent e;
  pthread_attr_t attr;
  if (pthread_getattr_np(pthread_self(), &attr) != 0) return e;
  const bool known = pthread_attr_getstack(&attr, &e.low, &e.size) == 0 && e.low && e.size > 0;
  pthread_attr_destroy(&attr);
  if (!known) e = StackExtent{};
  return e;
}

}  // namespace

uintptr_t stackFloor(uintptr_t reserve) {
  // Asked once per thread: on the main thread glibc answers by opening and parsing
  // /proc/self/maps, and it was asked once per seed plant derived there.
  thread_local const StackExtent extent = askStackExtent();
  if (extent.size == 0) return 0;
  const void* low = extent.low;
  const size_t size = extent.size;
  // What the code after a stop needs (unwinding, the engine's own bounded calls, and
  // sanitizers' larger frames): an eighth of the stack, at least 64 KiB, at most 1 MiB.
  const uintptr_t keep = std::max<uintptr_t>(reserve, std::clamp<uintptr_t>(size / 8, 64 << 10, 1 << 20));
  const uintptr_t bottom = reinterpret_cast<uintptr_t>(low);
  const uintptr_t here = reinterpret_cast<uintptr_t>(__builtin_frame_address(0));
  // A stack so small that the caller is already within the reserve: allow nothing more.
  return std::min(bottom + keep, here);
}

}  // namespace fgsg::rt
