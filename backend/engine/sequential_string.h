// The string of a sequential derivation whose grammar has context rules: ABOP's contexts
// (`A < B > C`) read a shape's neighbours in it. It holds the shapes in the order their
// successors wrote them, with the successors' brackets `[ ]`; what a derived shape's
// successor writes takes its place. Contexts read it generation by generation, as a
// parallel derivation does: a shape of depth d sees the string of depth d — its
// neighbours as they were written (even those already derived), and shapes of earlier
// depths that no rule rewrote — whatever order the shapes are derived in. Commands are not
// in it; #ignore'd symbols are stepped over. A linked list: a derived shape stays (hidden
// from deeper generations) and its successor's shapes are linked in before it, so writing
// costs what is written; brackets know their partners, so a branch is skipped in one step.
#pragma once

#include "ir/ir.h"

#include <cstdint>
#include <vector>

namespace fgsg::backend {

class SequentialString {
 public:
  static constexpr uint32_t kNone = UINT32_MAX;

  explicit SequentialString(const ir::Module& m);

  // Writes at the cursor (where the shape being derived stands, else at the end).
  uint32_t addShape(uint32_t symbol, const double* params, uint32_t slotCount);
  uint32_t addOpen();
  void addClose(uint32_t open);  // open: the '[' it closes (kNone: none)

  // What a derived shape's successor writes goes just before the shape, one generation
  // deeper; the shape stays for its own generation. beginRewrite returns what endRewrite
  // gives back (successors derived on the spot nest).
  struct Writing {
    uint32_t cursor, depth;
  };
  Writing beginRewrite(uint32_t node);
  void endRewrite(Writing outer);

  // ABOP's context matching around `node` in its generation; the matched shapes'
  // parameters are written to their slots in `params` (a rule's context parameters
  // follow its own).
  bool matchLeft(const ir::Rule& r, uint32_t node, double* params) const;
  bool matchRight(const ir::Rule& r, uint32_t node, double* params) const;

 private:
  static constexpr uint32_t kOpen = UINT32_MAX - 1, kClose = UINT32_MAX - 2;
  struct Node {
    uint32_t prev = kNone, next = kNone;
    uint32_t symbol = 0;       // a symbol, kOpen or kClose
    uint32_t partner = kNone;  // a bracket's other bracket
    uint32_t firstParam = 0;
    uint32_t depth = 0;        // the generation that wrote it
    bool derived = false;      // a shape that was rewritten: deeper generations see its successor
  };

  uint32_t insert(Node node);
  // Whether generation `depth` has node n in its string.
  bool inGeneration(uint32_t n, uint32_t depth) const {
    return nodes_[n].depth <= depth && (!nodes_[n].derived || nodes_[n].depth == depth);
  }
  uint32_t before(uint32_t n, uint32_t depth) const;  // the previous node of that generation
  uint32_t after(uint32_t n, uint32_t depth) const;
  bool sees(uint32_t n) const { return nodes_[n].symbol < kClose && !ignored_[nodes_[n].symbol]; }
  void bind(const ir::ContextModule& cm, uint32_t n, double* params) const;

  const ir::Module& m_;
  std::vector<uint8_t> ignored_;  // per symbol: #ignore'd
  std::vector<Node> nodes_;       // every node written, by id (the order written)
  std::vector<double> params_;
  uint32_t head_ = kNone, tail_ = kNone;
  uint32_t cursor_ = kNone;  // new nodes go before it; kNone: at the end
  uint32_t depth_ = 0;       // the generation new nodes belong to (the axiom's: 0)
};

}  // namespace fgsg::backend
