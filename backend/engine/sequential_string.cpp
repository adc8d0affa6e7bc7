#include "backend/engine/sequential_string.h"

namespace fgsg::backend {

SequentialString::SequentialString(const ir::Module& m) : m_(m), ignored_(m.symbols.size(), 0) {
  for (uint32_t s : m.contextIgnored)
    if (s < ignored_.size()) ignored_[s] = 1;
}

uint32_t SequentialString::insert(Node node) {
  const uint32_t id = static_cast<uint32_t>(nodes_.size());
  node.depth = depth_;
  nodes_.push_back(node);
  Node& n = nodes_.back();
  n.next = cursor_;
  n.prev = cursor_ == kNone ? tail_ : nodes_[cursor_].prev;
  (n.prev == kNone ? head_ : nodes_[n.prev].next) = id;
  (cursor_ == kNone ? tail_ : nodes_[cursor_].prev) = id;
  return id;
}

uint32_t SequentialString::addShape(uint32_t symbol, const double* params, uint32_t slotCount) {
  Node n;
  n.symbol = symbol;
  n.firstParam = static_cast<uint32_t>(params_.size());
  params_.insert(params_.end(), params, params + slotCount);
  return insert(n);
}

uint32_t SequentialString::addOpen() {
  Node n;
  n.symbol = kOpen;
  return insert(n);
}

void SequentialString::addClose(uint32_t open) {
  Node n;
  n.symbol = kClose;
  n.partner = open;
  const uint32_t id = insert(n);
  if (open != kNone) nodes_[open].partner = id;
}

SequentialString::Writing SequentialString::beginRewrite(uint32_t node) {
  const Writing outer{cursor_, depth_};
  nodes_[node].derived = true;
  cursor_ = node;
  depth_ = nodes_[node].depth + 1;
  return outer;
}

void SequentialString::endRewrite(Writing outer) {
  cursor_ = outer.cursor;
  depth_ = outer.depth;
}

uint32_t SequentialString::before(uint32_t n, uint32_t depth) const {
  do n = nodes_[n].prev;
  while (n != kNone && !inGeneration(n, depth));
  return n;
}

uint32_t SequentialString::after(uint32_t n, uint32_t depth) const {
  do n = nodes_[n].next;
  while (n != kNone && !inGeneration(n, depth));
  return n;
}

void SequentialString::bind(const ir::ContextModule& cm, uint32_t n, double* params) const {
  const ir::Symbol& s = m_.symbols[cm.symbol];
  const double* src = params_.data() + nodes_[n].firstParam;
  for (size_t k = 0; k < cm.paramSlots.size() && k < s.paramTypes.size(); ++k) {
    const int w = ir::slotWidth(s.paramTypes[k]);
    for (int c = 0; c < w; ++c) params[cm.paramSlots[k] + c] = src[c];
    src += w;
  }
}

// Leftwards: over #ignore'd symbols and whole branches, and out of the current branch
// into its parent (as parallel_rewriter.cpp's matchLeft).
bool SequentialString::matchLeft(const ir::Rule& r, uint32_t node, double* params) const {
  const uint32_t d = nodes_[node].depth;
  uint32_t j = before(node, d);
  for (size_t p = r.left.size(); p-- > 0;) {
    const ir::ContextModule& cm = r.left[p];
    if (cm.bracket != 0) return false;
    while (j != kNone && !sees(j)) {
      const Node& n = nodes_[j];
      j = before(n.symbol == kClose && n.partner != kNone ? n.partner : j, d);
    }
    if (j == kNone || nodes_[j].symbol != cm.symbol) return false;
    bind(cm, j, params);
    j = before(j, d);
  }
  return true;
}

// Rightwards: a pattern symbol skips branches the pattern does not enter, a pattern '['
// enters the next branch, a pattern ']' goes to the end of the current branch.
bool SequentialString::matchRight(const ir::Rule& r, uint32_t node, double* params) const {
  const uint32_t d = nodes_[node].depth;
  uint32_t j = after(node, d);
  const auto symbol = [&](uint32_t n) { return nodes_[n].symbol; };
  for (const auto& cm : r.right) {
    if (cm.bracket == 1) {
      while (j != kNone && !sees(j) && symbol(j) != kOpen && symbol(j) != kClose) j = after(j, d);
      if (j == kNone || symbol(j) != kOpen) return false;
      j = after(j, d);
    } else if (cm.bracket == -1) {
      int nesting = 0;
      for (; j != kNone; j = after(j, d)) {
        if (symbol(j) == kOpen) ++nesting;
        if (symbol(j) == kClose && nesting-- == 0) break;
      }
      if (j == kNone) return false;
      j = after(j, d);
    } else {
      while (j != kNone && !sees(j)) {
        if (symbol(j) == kClose) return false;
        const uint32_t close = symbol(j) == kOpen ? nodes_[j].partner : j;
        j = close == kNone ? kNone : after(close, d);  // an unclosed '[' runs to the end
      }
      if (j == kNone || symbol(j) != cm.symbol) return false;
      bind(cm, j, params);
      j = after(j, d);
    }
  }
  return true;
}

}  // namespace fgsg::backend
