// The context-taking entry points of runtime/abi.def. All noexcept: errors are
// recorded in the context, never thrown through generated frames.
#include "runtime/abi.h"

extern "C" {

double fgsg_rt_rand(FgsgContext* ctx, double lo, double hi) noexcept {
  return fgsg_rt_rand_scale(lo, hi, ctx->rng->next());
}

double fgsg_rt_next(FgsgContext* ctx) noexcept { return ctx->rng->next(); }

void fgsg_rt_error(FgsgContext* ctx, int32_t code, int32_t line, int32_t col) noexcept {
  if (ctx->errorCode != FGSG_OK) return;  // the first error is the one reported
  ctx->errorCode = code;
  ctx->stop = 1;
  ctx->errorLine = line;
  ctx->errorCol = col;
}

int32_t fgsg_rt_query(FgsgContext* ctx, uint32_t kind, uint32_t env, uint32_t extra,
                      const double* args, uint32_t nargs, int32_t line, int32_t col,
                      double* out) noexcept {
  int32_t rc = ctx->query ? ctx->query(ctx->queryUser, kind, env, extra, args, nargs, line, col, out)
                          : int32_t{FGSG_E_INTERNAL};
  if (rc != FGSG_OK) fgsg_rt_error(ctx, rc, line, col);
  return rc;
}

}  // extern "C"
