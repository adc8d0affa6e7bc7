// Between compiled code and the interpreter's world: answers fgsg_rt_query from a
// backend::Frame and QueryHost (catching whatever the host throws), and turns the
// error a compiled call reported into the DeriveError the interpreter would throw.
#pragma once

#include "backend/interp/eval.h"
#include "runtime/abi.h"

#include <optional>

namespace fgsg::backend::native {

class QueryBridge {
 public:
  QueryBridge(const ir::Module& m, const Frame& frame) : m_(m), frame_(frame) {}

  // Points ctx's query hook at this bridge and its stream at the frame's.
  void attach(FgsgContext& ctx) {
    ctx.rng = frame_.rng;
    ctx.query = &QueryBridge::answer;
    ctx.queryUser = this;
  }

  // The DeriveError for ctx's first error (ctx.errorCode != FGSG_OK), with the
  // interpreter's code and message.
  DeriveError error(const FgsgContext& ctx) const;

 private:
  static int32_t answer(void* user, uint32_t kind, uint32_t env, uint32_t extra,
                        const double* args, uint32_t nargs, int32_t line, int32_t col,
                        double* out) noexcept;

  const ir::Module& m_;
  Frame frame_;
  std::optional<DeriveError> hostError_;  // what the host threw, for FGSG_E_HOST
};

}  // namespace fgsg::backend::native
