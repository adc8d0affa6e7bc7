// The shapes of a sequential derivation, stored as structure-of-arrays in growing
// vectors: adding a shape appends to each array and its parameters to one pool, so no
// shape owns a heap allocation.
#pragma once

#include "runtime/geometry.h"
#include "runtime/scope.h"

#include <cstdint>
#include <vector>

namespace fgsg::backend {

class ShapeStore {
 public:
  uint32_t add(uint32_t symbol, const rt::Scope& scope, const rt::GeomRef& geom, uint32_t depth,
               uint32_t index, uint64_t key, uint32_t creator, const double* params,
               uint32_t slotCount) {
    const auto id = static_cast<uint32_t>(symbol_.size());
    symbol_.push_back(symbol);
    scope_.push_back(scope);
    geom_.push_back(geom);
    depth_.push_back(depth);
    index_.push_back(index);
    key_.push_back(key);
    creator_.push_back(creator);
    firstParam_.push_back(static_cast<uint32_t>(params_.size()));
    params_.insert(params_.end(), params, params + slotCount);
    return id;
  }

  size_t size() const { return symbol_.size(); }
  uint32_t symbol(uint32_t s) const { return symbol_[s]; }
  const rt::Scope& scope(uint32_t s) const { return scope_[s]; }
  const rt::GeomRef& geom(uint32_t s) const { return geom_[s]; }
  uint32_t depth(uint32_t s) const { return depth_[s]; }
  uint32_t index(uint32_t s) const { return index_[s]; }
  uint64_t key(uint32_t s) const { return key_[s]; }
  uint32_t creator(uint32_t s) const { return creator_[s]; }  // rule index or UINT32_MAX
  const double* params(uint32_t s) const { return params_.data() + firstParam_[s]; }

  void reserve(size_t n) {
    symbol_.reserve(n), scope_.reserve(n), geom_.reserve(n), depth_.reserve(n);
    index_.reserve(n), key_.reserve(n), creator_.reserve(n), firstParam_.reserve(n);
  }

 private:
  std::vector<uint32_t> symbol_;
  std::vector<rt::Scope> scope_;
  std::vector<rt::GeomRef> geom_;
  std::vector<uint32_t> depth_;
  std::vector<uint32_t> index_;
  std::vector<uint64_t> key_;
  std::vector<uint32_t> creator_;
  std::vector<uint32_t> firstParam_;
  std::vector<double> params_;
};

}  // namespace fgsg::backend
