// The C ABI between generated code and the runtime: the context every compiled
// function receives, and the prototypes of runtime/abi.def. Generated code sees the
// context only as a pointer; it never reads its fields.
#pragma once

#include "runtime/builtins_math.h"
#include "runtime/random.h"

#include <cstddef>
#include <cstdint>

// Errors generated code can report (fgsg_rt_error) or a query can answer with. The
// engine turns the first one into its DeriveError after the compiled call returns.
enum FgsgErrorCode : int32_t {
  FGSG_OK = 0,
  FGSG_E_VEC_UNAVAILABLE = 1,  // R001: a vector value not available yet (vector queries)
  FGSG_E_FIELD = 2,            // retired (field queries are answered by the host); kept for numbering
  FGSG_E_UNUSED_3 = 3,         // was: texture contexts not supported (ABI 7 and before)
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
  // Nonzero once the running block must return: an error was reported, or the engine
  // culled the rest of the production.
  int32_t stop = 0;
  // Direct derivation (FgsgDirectFn) met what only the engine's own order reports
  // exactly (a limit, an error): the engine derives the grammar again without it.
  int32_t inexact = 0;
  // Direct derivation's counts, added to the engine's statistics afterwards, and its
  // limits: shapes it may still create, the depth at which a shape stays terminal.
  uint64_t shapes = 0;
  uint64_t rewrites = 0;
  uint64_t terminals = 0;
  uint64_t shapeBudget = 0;
  uint32_t depthLimit = 0;
  // 1: the depth limit is the grammar's own (`derive breadthfirst N;`): a shape there
  // stays terminal without a warning, so direct code counts it instead of giving up.
  uint32_t depthLimitQuiet = 0;
  fgsg::rt::RandomStream* rng = nullptr;  // the shape's stream (Rand)
  // Direct derivation: shapes visited so far (each shape's preorder number, which puts
  // the instances it places in the interpreter's order afterwards).
  uint64_t visits = 0;
  // Direct derivation recurses natively: a shape whose frame would start below this
  // address gives up instead (runtime/stack_budget.h), and the engine derives again in
  // its own order without recursion. 0: no floor.
  uint64_t stackFloor = 0;
  FgsgQueryFn query = nullptr;            // the engine's query host
  void* queryUser = nullptr;
  // The first error reported, FGSG_OK while none.
  int32_t errorCode = FGSG_OK;
  int32_t errorLine = 0;
  int32_t errorCol = 0;
};

// Generated code reads and writes these fields at these offsets (program_codegen_internal.h).
static_assert(offsetof(FgsgContext, stop) == 0 && offsetof(FgsgContext, inexact) == 4 &&
                  offsetof(FgsgContext, shapes) == 8 && offsetof(FgsgContext, rewrites) == 16 &&
                  offsetof(FgsgContext, terminals) == 24 && offsetof(FgsgContext, shapeBudget) == 32 &&
                  offsetof(FgsgContext, depthLimit) == 40 && offsetof(FgsgContext, depthLimitQuiet) == 44 &&
                  offsetof(FgsgContext, rng) == 48 &&
                  offsetof(FgsgContext, visits) == 56 && offsetof(FgsgContext, stackFloor) == 64,
              "the context layout generated code assumes");

// Bumped whenever the layout below or an entry point's meaning changes: a compiled
// library refuses to run against a runtime of another version.
#define FGSG_ABI_VERSION 9u

// A compiled grammar as generated code lays it out: one constant in each JIT unit and
// in each compiled library. Block ids, rule and alternative indices are those of
// ir::ProgramLayout (ir/program_layout.h) for the grammar's IR.
//   block(ctx, params, attrs): runs one successor (or split body); params is the rule's
//     parameter block, attrs three slots per attribute.
//   guard / weight(params, attrs, ctx): a rule's guard (null: none), an alternative's
//     probability (null: a constant the engine reads from the IR).
typedef void (*FgsgBlockFn)(FgsgContext* ctx, const double* params, const double* attrs);
typedef double (*FgsgValueFn)(const double* params, const double* attrs, FgsgContext* ctx);
// Derives a shape of a "direct" symbol and everything it creates, at once and in native
// code: a symbol whose rules only move, turn and scale the scope, place plain instances
// and create shapes of direct or ruleless symbols (no splits, collisions or queries).
// Without instances the order its shapes are derived in changes nothing in the result;
// with them, the engine puts the instances in its own order afterwards (by depth and
// preorder), so it uses such symbols only where nothing else can observe the order.
// scope: an rt::Scope (copied).
typedef void (*FgsgDirectFn)(FgsgContext* ctx, const void* scope, const double* slots, uint64_t key,
                             uint32_t depth, const double* attrs);

struct FgsgProgram {
  uint32_t abiVersion;
  uint32_t blockCount;
  const FgsgBlockFn* blocks;
  uint32_t ruleCount;
  const FgsgValueFn* guards;
  uint32_t alternativeCount;
  const FgsgValueFn* weights;
  const char* source;      // the grammar's text (compiled libraries; null in the JIT)
  const char* sourceName;  // its file name as compiled, for diagnostics and relative paths
  uint32_t symbolCount;
  const FgsgDirectFn* direct;  // by symbol: null unless the symbol is direct
  const uint8_t* directPlaces;  // by symbol: 1 when a direct symbol's shapes may place instances
  uint32_t scopeSize;          // sizeof(rt::Scope) the direct code was compiled for
  // `fgsg compile --start-rule Style$Rule`: the start rule (and .cga style) the code was
  // compiled for, which the loader compiles `source` with again; null: the grammar's own.
  const char* startRule;
};

extern "C" {
#define FGSG_RT_MATH(name, ret, ...)
#define FGSG_RT_FN(name, ret, ...) ret name(__VA_ARGS__) noexcept;
#include "runtime/abi.def"
#undef FGSG_RT_MATH
}
