// What the diagnostic boundaries call "out of memory" rather than "internal error".
#include "runtime/out_of_resources.h"

#include <catch2/catch.hpp>

#include <new>
#include <stdexcept>
#include <system_error>

using fgsg::rt::outOfResources;

TEST_CASE("memory and threads the system could not give are out of resources") {
  CHECK(outOfResources(std::bad_alloc()) == "no memory left");
  CHECK(outOfResources(std::bad_array_new_length()) == "no memory left");
  CHECK(outOfResources(std::system_error(std::make_error_code(std::errc::resource_unavailable_try_again),
                                         "thread")) .rfind("cannot start a thread: thread", 0) == 0);
  CHECK_FALSE(outOfResources(std::system_error(std::make_error_code(std::errc::not_enough_memory))).empty());
  // TBB's words when a worker thread cannot be started.
  CHECK(outOfResources(std::runtime_error("pthread_create has failed: Resource temporarily unavailable")) ==
        "cannot start a worker thread: pthread_create has failed: Resource temporarily unavailable");
}

TEST_CASE("other exceptions are not out of resources") {
  CHECK(outOfResources(std::runtime_error("a bug")).empty());
  CHECK(outOfResources(std::runtime_error("failed: pthread_create has failed")).empty());
  CHECK(outOfResources(std::logic_error("pthread_create has failed")).empty());
  CHECK(outOfResources(std::system_error(std::make_error_code(std::errc::invalid_argument))).empty());
}
