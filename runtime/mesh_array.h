// The arrays a Mesh keeps its vertices and triangles in. Assembled meshes reach hundreds of
// megabytes (on-mesh marching: 23 M triangles from 64 seeds), and two costs dominated
// filling them: std::vector zero-filling every element on resize (on one thread, before
// the parallel writers overwrite it all) and a page fault per 4 KiB on first touch.
// So resize leaves new elements uninitialised (an explicit value still fills), and
// arrays of 4 MiB or more are 2 MiB-aligned and asked for transparent huge pages.
#pragma once

#include <cstddef>
#include <new>
#include <utility>
#include <vector>

namespace fgsg::rt {

// Raw storage for MeshArray: large blocks aligned and advised for huge pages.
void* allocateMeshStorage(size_t bytes);
void freeMeshStorage(void* p, size_t bytes) noexcept;

template <class T>
struct MeshArrayAllocator {
  using value_type = T;
  MeshArrayAllocator() = default;
  template <class U>
  MeshArrayAllocator(const MeshArrayAllocator<U>&) noexcept {}

  T* allocate(size_t n) {
    if (n > size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(allocateMeshStorage(n * sizeof(T)));
  }
  void deallocate(T* p, size_t n) noexcept { freeMeshStorage(p, n * sizeof(T)); }
  // Default-initialisation: resize(n) writes nothing into a float or an index.
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  friend bool operator==(const MeshArrayAllocator&, const MeshArrayAllocator&) { return true; }
  friend bool operator!=(const MeshArrayAllocator&, const MeshArrayAllocator&) { return false; }
};

template <class T>
using MeshArray = std::vector<T, MeshArrayAllocator<T>>;

}  // namespace fgsg::rt
