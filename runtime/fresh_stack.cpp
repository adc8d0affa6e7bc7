#include "runtime/fresh_stack.h"

#include <cstring>
#include <exception>
#include <pthread.h>
#include <stdexcept>
#include <string>

namespace fgsg::rt {

namespace {

struct Continuation {
  const std::function<void()>* fn;
  std::exception_ptr thrown;
};

void* runContinuation(void* arg) {
  auto* c = static_cast<Continuation*>(arg);
  try {
    (*c->fn)();
  } catch (...) {
    c->thrown = std::current_exception();
  }
  return nullptr;
}

}  // namespace

void runOnFreshStack(const std::function<void()>& fn, size_t bytes) {
  Continuation c{&fn, nullptr};
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  pthread_attr_setstacksize(&attr, bytes);
  pthread_t thread;
  const int err = pthread_create(&thread, &attr, runContinuation, &c);
  pthread_attr_destroy(&attr);
  if (err != 0)
    throw std::runtime_error("cannot start a thread to continue a deep recursion: " +
                             std::string(std::strerror(err)));
  pthread_join(thread, nullptr);
  if (c.thrown) std::rethrow_exception(c.thrown);
}

}  // namespace fgsg::rt
