// The shapes of a sequential derivation that wait to be derived, one queue per priority.
// Shapes are stored as records in the order they are taken: breadth-first a queue reads
// from its front and appends at its back; depth-first it is a stack. Both walk memory
// sequentially, which matters: a wide breadth-first frontier holds millions of shapes,
// and reading them in scattered order made the derivation wait on memory. Nothing is
// allocated per shape; parameters sit in one pool with a fixed stride (the largest
// parameter block of any symbol).
#pragma once

#include "runtime/geometry.h"
#include "runtime/lines/line_network.h"
#include "runtime/scope.h"

#include <sys/mman.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

namespace fgsg::backend {

// A shape taken out of its queue, with everything deriving it needs.
struct WaitingShape {
  uint64_t key = 0;
  uint32_t symbol = 0, depth = 0, index = 0;
  uint32_t creator = UINT32_MAX;  // the rule that created it (UINT32_MAX: the axiom)
  uint32_t node = UINT32_MAX;     // its place in the sequential string (grammars with contexts)
  rt::LineCursor line;            // the line its LineSeg commands extend, if any
  rt::GeomRef geom;
  rt::Scope scope;
};

class ShapeQueue {
 public:
  ShapeQueue(uint32_t paramStride, bool lastInFirstOut)
      : stride_(std::max<uint32_t>(paramStride, 1)), lifo_(lastInFirstOut) {}

  // Appends a shape with its parameters; the caller fills in the returned record (in
  // place: a record is large, and this is the hot path of every derivation).
  WaitingShape& push(const double* params, uint32_t slotCount) {
    if (tail_ == chunks_.size() * kChunk) grow();
    Chunk& c = *chunks_[tail_ / kChunk];
    const size_t i = tail_ % kChunk;
    std::copy(params, params + slotCount, c.params.begin() + i * stride_);
    ++tail_;
    return c.shapes[i];
  }

  bool empty() const { return head_ == tail_; }

  // Takes the next shape; its parameters are copied to `params` (stride values).
  void pop(WaitingShape& out, std::vector<double>& params) {
    const size_t at = lifo_ ? tail_ - 1 : head_;
    const Chunk& c = *chunks_[at / kChunk];
    const size_t i = at % kChunk;
    out = c.shapes[i];
    params.assign(c.params.begin() + i * stride_, c.params.begin() + (i + 1) * stride_);
    if (lifo_) {
      --tail_;
      return;
    }
    ++head_;
    if (head_ == tail_) {
      head_ = tail_ = 0;
    } else if (head_ == kChunk) {
      // The first chunk is used up: move it to the back for reuse.
      std::rotate(chunks_.begin(), chunks_.begin() + 1, chunks_.end());
      head_ -= kChunk;
      tail_ -= kChunk;
    } else if (i + 4 < kChunk) {
      __builtin_prefetch(&c.shapes[i + 4]);
      __builtin_prefetch(reinterpret_cast<const char*>(&c.shapes[i + 4]) + 64);
      __builtin_prefetch(reinterpret_cast<const char*>(&c.shapes[i + 4]) + 128);
    }
  }

  // The position the next push goes to; with reverseSince, a stack hands out the
  // shapes one successor created in the order the successor wrote them.
  size_t mark() const { return tail_; }
  void reverseSince(size_t mark) {
    if (!lifo_) return;
    for (size_t a = mark, b = tail_ - 1; tail_ > 0 && a < b; ++a, --b) {
      Chunk& ca = *chunks_[a / kChunk];
      Chunk& cb = *chunks_[b / kChunk];
      std::swap(ca.shapes[a % kChunk], cb.shapes[b % kChunk]);
      std::swap_ranges(ca.params.begin() + (a % kChunk) * stride_,
                       ca.params.begin() + (a % kChunk + 1) * stride_,
                       cb.params.begin() + (b % kChunk) * stride_);
    }
  }

 private:
  // Shapes live in fixed chunks that are recycled, so a queue never copies the shapes it
  // holds when it grows or drains. A chunk's records fill one 2 MiB block, aligned and
  // offered to the kernel as a huge page: a wide frontier touches hundreds of MiB, and
  // faulting them in 4 KiB at a time cost more than deriving the shapes.
  static constexpr size_t kBlockBytes = size_t(2) << 20;
  static constexpr size_t kChunk = kBlockBytes / sizeof(WaitingShape);
  struct Chunk {
    explicit Chunk(uint32_t stride) : params(kChunk * stride) {
      void* block = std::aligned_alloc(kBlockBytes, kBlockBytes);
      if (!block) throw std::bad_alloc();
      madvise(block, kBlockBytes, MADV_HUGEPAGE);  // a hint; without it, plain pages
      shapes = static_cast<WaitingShape*>(block);
      std::uninitialized_default_construct_n(shapes, kChunk);
    }
    ~Chunk() {
      std::destroy_n(shapes, kChunk);
      std::free(shapes);
    }
    Chunk(const Chunk&) = delete;
    Chunk& operator=(const Chunk&) = delete;

    WaitingShape* shapes = nullptr;
    std::vector<double> params;
  };
  void grow() { chunks_.push_back(std::make_unique<Chunk>(stride_)); }

  uint32_t stride_;
  bool lifo_;
  size_t head_ = 0, tail_ = 0;  // positions over the chunks in order
  std::vector<std::unique_ptr<Chunk>> chunks_;
};

}  // namespace fgsg::backend
