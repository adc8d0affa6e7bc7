// Storage for the strings of parallel (L-system) derivations, kept from one derivation
// to the next in the same process. A program that derives again and again (the viewer's
// live loop, the Python package, a batch, bench_lsystem --warm) otherwise has the kernel
// fault in and clear a fresh buffer for every large string: F -> FFF n = 13 is 34 MB,
// and clearing its pages was a fifth of a repeated derivation's time on this project's
// VM (ABOP Fig. 1.24d n = 9 is 2 MB, and a fresh buffer was a third of its rewriting). At
// most four blocks of 64 KiB or more (two strings' modules and arguments), 128 MiB in
// all, are kept; everything else goes back to the system as before. Blocks are handed
// out whole and not cleared (a StringBuffer never reads what it has not written).
#pragma once

#include "runtime/mesh_array.h"

#include <cstddef>
#include <mutex>

namespace fgsg::backend {

class StringStoragePool {
 public:
  StringStoragePool() = default;  // the process has one (instance()); tests make their own
  StringStoragePool(const StringStoragePool&) = delete;
  StringStoragePool& operator=(const StringStoragePool&) = delete;
  static StringStoragePool& instance() {
    static StringStoragePool pool;
    return pool;
  }

  // A block of at least `bytes`; `granted` is set to its size.
  void* take(size_t bytes, size_t& granted) {
    if (bytes >= kKeptFrom) {
      std::lock_guard<std::mutex> lock(mutex_);
      Block* fit = nullptr;
      for (Block& b : blocks_)
        if (b.data && b.bytes >= bytes && (!fit || b.bytes < fit->bytes)) fit = &b;
      if (fit) {
        void* data = fit->data;
        granted = fit->bytes;
        *fit = Block{};
        return data;
      }
    }
    granted = bytes;
    return rt::allocateMeshStorage(bytes);
  }

  // Keeps a large block in place of an empty slot or of a smaller kept one, within the
  // cap; frees what is not kept.
  void giveBack(void* data, size_t bytes) noexcept {
    if (bytes >= kKeptFrom && bytes <= kKeptBytes) {
      std::lock_guard<std::mutex> lock(mutex_);
      Block* slot = nullptr;
      for (Block& b : blocks_)
        if (!slot || b.bytes < slot->bytes) slot = &b;  // an empty slot has 0 bytes
      if (slot->bytes < bytes && keptBytes() - slot->bytes + bytes <= kKeptBytes) {
        if (slot->data) rt::freeMeshStorage(slot->data, slot->bytes);
        *slot = Block{data, bytes};
        return;
      }
    }
    rt::freeMeshStorage(data, bytes);
  }

  ~StringStoragePool() {
    for (Block& b : blocks_)
      if (b.data) rt::freeMeshStorage(b.data, b.bytes);
  }

 private:
  struct Block {
    void* data = nullptr;
    size_t bytes = 0;
  };
  static constexpr size_t kKeptFrom = size_t(64) << 10;
  static constexpr size_t kKeptBytes = size_t(128) << 20;

  size_t keptBytes() const {
    size_t sum = 0;
    for (const Block& b : blocks_) sum += b.bytes;
    return sum;
  }

  std::mutex mutex_;
  Block blocks_[4];
};

}  // namespace fgsg::backend
