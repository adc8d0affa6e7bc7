#include "runtime/out_of_resources.h"

#include "runtime/memory_budget.h"
#include "runtime/plugins/plugin_library.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <new>
#include <stdexcept>
#include <system_error>

namespace fgsg::rt {

std::string outOfResources(const std::exception& e) {
  if (dynamic_cast<const std::bad_alloc*>(&e)) return "no memory left";
  if (const auto* s = dynamic_cast<const std::system_error*>(&e)) {
    const std::error_code c = s->code();
    if (c == std::errc::not_enough_memory || c == std::errc::resource_unavailable_try_again)
      return std::string("cannot start a thread: ") + s->what();
    return "";
  }
  if (const auto* p = dynamic_cast<const PluginError*>(&e); p && p->outOfMemory)
    return std::string("cannot load a part of fgsg: ") + e.what();
  static constexpr const char kTbbThread[] = "pthread_create has failed";
  if (dynamic_cast<const std::runtime_error*>(&e) && std::strncmp(e.what(), kTbbThread, sizeof kTbbThread - 1) == 0)
    return std::string("cannot start a worker thread: ") + e.what();
  return "";
}

std::string memoryLimitInForce() {
  const long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGE_SIZE);
  const uint64_t physical = pages > 0 && size > 0 ? uint64_t(pages) * uint64_t(size) : 0;
  const uint64_t available = availableMemoryBytes();  // the cgroup's limit when lower
  uint64_t bytes = available;
  std::string limit = available > 0 && available < physical ? "the cgroup's memory limit of "
                                                            : "the machine's ";
  struct rlimit as {};
  if (::getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY && (bytes == 0 || as.rlim_cur < bytes)) {
    bytes = as.rlim_cur;
    limit = "the address-space limit (ulimit -v) of ";
  }
  if (bytes == 0) return "no memory limit known";
  limit += formatMemorySize(bytes);
  if (limit.rfind("the machine's ", 0) == 0) limit += " of memory";
  if (const uint64_t used = residentMemoryBytes()) limit += "; " + formatMemorySize(used) + " in use";
  return limit;
}

}  // namespace fgsg::rt
