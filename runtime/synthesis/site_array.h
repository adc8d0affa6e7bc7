// Per-site arrays of large grids, left uninitialised (the solver writes a site before it
// reads it) and, on Linux, backed by 2 MiB pages where the kernel grants them
// (MADV_HUGEPAGE). A 200x200x20 model touches ~30 MB of fresh memory; with 4 KiB pages its
// first-touch faults and the zero fill of std::vector took about a third of the run on the
// benchmark VM.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace fgsg::rt::synthesis {

template <class T>
class SiteArray {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

 public:
  SiteArray() = default;
  explicit SiteArray(size_t n) : n_(n) {
    constexpr size_t kHuge = size_t(2) << 20;
    const size_t bytes = n * sizeof(T);
    if (bytes >= kHuge) {
      // Whole huge pages: aligned_alloc wants a multiple of the alignment.
      const size_t rounded = (bytes + kHuge - 1) / kHuge * kHuge;
      p_.reset(static_cast<T*>(std::aligned_alloc(kHuge, rounded)));
#if defined(__linux__) && defined(MADV_HUGEPAGE)
      if (p_) madvise(p_.get(), rounded, MADV_HUGEPAGE);
#endif
    } else {
      p_.reset(static_cast<T*>(std::malloc(bytes ? bytes : 1)));
    }
    if (!p_) throw std::bad_alloc();
  }

  size_t size() const { return n_; }
  T* data() { return p_.get(); }
  const T* data() const { return p_.get(); }
  T& operator[](size_t i) { return p_.get()[i]; }
  const T& operator[](size_t i) const { return p_.get()[i]; }
  void fill(const T& v) { std::uninitialized_fill_n(p_.get(), n_, v); }

 private:
  struct Free {
    void operator()(T* p) const { std::free(p); }
  };
  std::unique_ptr<T, Free> p_;
  size_t n_ = 0;
};

}  // namespace fgsg::rt::synthesis
