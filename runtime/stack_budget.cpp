#include "runtime/stack_budget.h"

#include <algorithm>
#include <pthread.h>

namespace fgsg::rt {

uintptr_t stackFloor(uintptr_t reserve) {
  pthread_attr_t attr;
  if (pthread_getattr_np(pthread_self(), &attr) != 0) return 0;
  void* low = nullptr;
  size_t size = 0;
  const bool known = pthread_attr_getstack(&attr, &low, &size) == 0 && low && size > 0;
  pthread_attr_destroy(&attr);
  if (!known) return 0;
  // What the code after a stop needs (unwinding, the engine's own bounded calls, and
  // sanitizers' larger frames): an eighth of the stack, at least 64 KiB, at most 1 MiB.
  const uintptr_t keep = std::max<uintptr_t>(reserve, std::clamp<uintptr_t>(size / 8, 64 << 10, 1 << 20));
  const uintptr_t bottom = reinterpret_cast<uintptr_t>(low);
  const uintptr_t here = reinterpret_cast<uintptr_t>(__builtin_frame_address(0));
  // A stack so small that the caller is already within the reserve: allow nothing more.
  return std::min(bottom + keep, here);
}

}  // namespace fgsg::rt
