#include "runtime/abandonable.h"

namespace fgsg::rt {

namespace detail {
std::atomic<int>& abandonedWorkerCount() noexcept {
  static std::atomic<int> count{0};
  return count;
}
}  // namespace detail

int abandonedWorkers() noexcept { return detail::abandonedWorkerCount().load(); }

}  // namespace fgsg::rt
