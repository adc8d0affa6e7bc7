// The C ABI between generated code and the runtime: the context every compiled
// function receives, and the prototypes of runtime/abi.def. Generated code sees the
// context only as a pointer; it never reads its fields.
#pragma once

#include "runtime/builtins_math.h"
#include "runtime/random.h"

#include <cstdint>

// Errors generated code can report (fgsg_rt_error) or a query can answer with. The
// engine turns the first one into its DeriveError after the compiled call returns.
enum FgsgErrorCode : int32_t {
  FGSG_OK = 0,
  FGSG_E_VEC_UNAVAILABLE = 1,  // R001: a vector value not available yet (vector queries)
  FGSG_E_FIELD = 2,            // retired (field queries are answered by the host); kept for numbering
  FGSG_E_TEXTURE = 3,          // R001: texture contexts are not supported yet
  FGSG_E_NO_SCOPE = 4,         // R006: a scope query in a parallel rewriting step
  FGSG_E_HOST = 5,             // the query host failed; its message is in the host
  FGSG_E_INTERNAL = 6,         // R900: a compiler bug (vector used as a number, ...)
};

struct FgsgContext;

// Answers a query for fgsg_rt_query: writes *out and returns FGSG_OK, or returns an
// error code. Must not throw.
using FgsgQueryFn = int32_t (*)(void* user, uint32_t kind, uint32_t env, uint32_t extra,
                                const double* args, uint32_t nargs, int32_t line, int32_t col,
                                double* out) noexcept;

struct FgsgContext {
  fgsg::rt::RandomStream* rng = nullptr;  // the shape's stream (Rand)
  FgsgQueryFn query = nullptr;            // the engine's query host
  void* queryUser = nullptr;
  // The first error reported, FGSG_OK while none.
  int32_t errorCode = FGSG_OK;
  int32_t errorLine = 0;
  int32_t errorCol = 0;
};

extern "C" {
#define FGSG_RT_MATH(name, ret, ...)
#define FGSG_RT_FN(name, ret, ...) ret name(__VA_ARGS__) noexcept;
#include "runtime/abi.def"
#undef FGSG_RT_MATH
}
