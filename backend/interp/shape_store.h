// The live shapes of a sequential derivation, stored as structure-of-arrays. A shape's
// slot is recycled once it has been derived, and parameters live in one pool with a
// fixed stride (the largest parameter block of any symbol), so deriving allocates
// nothing per shape and memory follows the number of shapes waiting, not the total.
#pragma once

#include "runtime/geometry.h"
#include "runtime/scope.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace fgsg::backend {

class ShapeStore {
 public:
  explicit ShapeStore(uint32_t paramStride = 0) : stride_(std::max<uint32_t>(paramStride, 1)) {}

  uint32_t add(uint32_t symbol, const rt::Scope& scope, const rt::GeomRef& geom, uint32_t depth,
               uint32_t index, uint64_t key, uint32_t creator, const double* params,
               uint32_t slotCount) {
    uint32_t s;
    if (!free_.empty()) {
      s = free_.back();
      free_.pop_back();
    } else {
      s = static_cast<uint32_t>(symbol_.size());
      symbol_.emplace_back(), scope_.emplace_back(), geom_.emplace_back(), depth_.emplace_back();
      index_.emplace_back(), key_.emplace_back(), creator_.emplace_back();
      params_.resize(params_.size() + stride_);
    }
    symbol_[s] = symbol;
    scope_[s] = scope;
    geom_[s] = geom;
    depth_[s] = depth;
    index_[s] = index;
    key_[s] = key;
    creator_[s] = creator;
    std::copy(params, params + slotCount, params_.begin() + static_cast<size_t>(s) * stride_);
    return s;
  }

  void prefetch(uint32_t s) const {
    __builtin_prefetch(&scope_[s]);
    __builtin_prefetch(reinterpret_cast<const char*>(&scope_[s]) + 64);
    __builtin_prefetch(params_.data() + static_cast<size_t>(s) * stride_);
    __builtin_prefetch(&key_[s]);
  }

  // The shape has been derived: its slot may be reused.
  void release(uint32_t s) { free_.push_back(s); }

  size_t live() const { return symbol_.size() - free_.size(); }
  uint32_t symbol(uint32_t s) const { return symbol_[s]; }
  const rt::Scope& scope(uint32_t s) const { return scope_[s]; }
  const rt::GeomRef& geom(uint32_t s) const { return geom_[s]; }
  uint32_t depth(uint32_t s) const { return depth_[s]; }
  uint32_t index(uint32_t s) const { return index_[s]; }
  uint64_t key(uint32_t s) const { return key_[s]; }
  uint32_t creator(uint32_t s) const { return creator_[s]; }  // rule index or UINT32_MAX
  const double* params(uint32_t s) const { return params_.data() + static_cast<size_t>(s) * stride_; }

 private:
  uint32_t stride_;
  std::vector<uint32_t> symbol_;
  std::vector<rt::Scope> scope_;
  std::vector<rt::GeomRef> geom_;
  std::vector<uint32_t> depth_;
  std::vector<uint32_t> index_;
  std::vector<uint64_t> key_;
  std::vector<uint32_t> creator_;
  std::vector<double> params_;
  std::vector<uint32_t> free_;
};

}  // namespace fgsg::backend
