// Deep recursion without a deep stack: when a recursive algorithm reaches its thread's
// stack floor (runtime/stack_budget.h) it continues on a new thread with a large stack
// of its own and waits for it, so results never depend on the caller's stack size (a
// host's small pthread stack, `ulimit -s`, a sanitizer's larger frames).
#pragma once

#include <cstddef>
#include <functional>

namespace fgsg::rt {

// The stack each continuation gets: reserved, and touched only as deep as it is used.
constexpr size_t kFreshStackBytes = size_t(256) << 20;

// Runs `fn` on a new thread with a stack of `bytes` and returns when it has; what `fn`
// throws is rethrown here. Throws std::runtime_error if no thread can be started.
void runOnFreshStack(const std::function<void()>& fn, size_t bytes = kFreshStackBytes);

}  // namespace fgsg::rt
