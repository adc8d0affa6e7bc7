// The context of one compiled block while it runs (runtime/abi.h's FgsgContext, extended):
// the runtime entry points (native_bridge.cpp) find the engine and the successor's state
// through it. What the engine throws is caught there and kept here until the block has
// returned, so no exception unwinds through generated frames.
#pragma once

#include "backend/engine/parallel_string.h"
#include "backend/engine/successor.h"
#include "backend/interp/eval.h"
#include "runtime/abi.h"

#include <exception>

namespace fgsg::backend {

class Derivation;

// Thrown when direct derivation gives up; run() ends and deriveCompiled starts again.
struct InexactDirect {};

struct NativeCall : FgsgContext {
  Derivation* engine = nullptr;
  State* st = nullptr;  // sequential: the successor's scope and stack
  Exec* ex = nullptr;
  Frame* f = nullptr;
  StringTarget* string = nullptr;  // parallel: where modules are appended
  std::exception_ptr thrown;

  template <class Fn>
  void guard(Fn&& fn) noexcept {
    try {
      fn();
      if (ex && ex->culled) stop = 1;
    } catch (...) {
      thrown = std::current_exception();
      stop = 1;
    }
  }
};

}  // namespace fgsg::backend
