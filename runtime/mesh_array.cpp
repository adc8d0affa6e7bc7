#include "runtime/mesh_array.h"

#include <cstdint>
#include <cstdlib>
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace fgsg::rt {

namespace {

constexpr size_t kHugePage = size_t(2) << 20;
constexpr size_t kLarge = size_t(4) << 20;

size_t roundedUp(size_t bytes) { return (bytes + kHugePage - 1) / kHugePage * kHugePage; }

}  // namespace

void* allocateMeshStorage(size_t bytes) {
  if (bytes < kLarge) return ::operator new(bytes);
  if (bytes > SIZE_MAX - kHugePage) throw std::bad_alloc();  // roundedUp would wrap to a tiny block
  void* p = std::aligned_alloc(kHugePage, roundedUp(bytes));
  if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // Advice only: where transparent huge pages are off this changes nothing.
  madvise(p, roundedUp(bytes), MADV_HUGEPAGE);
#endif
  return p;
}

void freeMeshStorage(void* p, size_t bytes) noexcept {
  if (bytes < kLarge)
    ::operator delete(p);
  else
    std::free(p);
}

}  // namespace fgsg::rt
