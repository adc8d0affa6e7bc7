// A long string whose every rule is a fixed successor is rewritten in chunks on all
// cores (backend/engine/parallel_rewriter.cpp: rewriteTemplates, from 2^18 modules), a
// shorter one on the calling thread, both counted first and then written (TemplateStep).
// Both must give the general one-thread loop's result, on any number of threads.
// scripts/tsan.sh runs this under ThreadSanitizer (issue 52).
#include "derive_helpers.h"

#include "backend/engine/parallel_string.h"
#include "backend/engine/string_storage_pool.h"
#include "runtime/mesh_array.h"

#include <catch2/catch.hpp>
#include <tbb/global_control.h>

#include <cmath>

using namespace fgsg;
using fgsg::test::deriveText;

namespace {

// 3^n A's after n steps, each with kept, parameterized F's and bracketed turns beside it:
// 3^n + 9 (3^n - 1) / 2 modules, 324 765 before the last of 11 steps, which is rewritten
// in 10 chunks (the steps before it on the calling thread).
const char* kTemplates = R"(
  derive parallel 11;
  turtle angle 25 width 0.01;
  axiom: A;
  A -> F(0.5) [ + A ] [ - F(0.25) A ] F(0.75) A;
)";

// The same grammar and one more symbol, never reached, whose guarded rule is no fixed
// successor: the whole derivation takes the one-thread loop.
std::string oneThreadLoop() { return std::string(kTemplates) + "  Q(x) : x > 0 -> Q(x - 1);\n"; }

rt::DeriveResult onThreads(int threads, const std::string& grammar) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  return deriveText(grammar);
}

}  // namespace

TEST_CASE("A long string rewritten in chunks on many threads is the one-thread rewrite", "[lsystem][parallel]") {
  const rt::DeriveResult loop = onThreads(1, oneThreadLoop());
  REQUIRE(loop.ok);
  REQUIRE(loop.stats.stringLength == 974304);
  REQUIRE(loop.instances.instances.size() == 265719);  // 3 F's per rewrite, (3^11 - 1) / 2 rewrites
  for (int threads : {1, 2, 4}) {
    INFO(threads << " threads");
    const rt::DeriveResult chunks = onThreads(threads, kTemplates);
    REQUIRE(chunks.ok);
    CHECK(chunks.stats.stringLength == loop.stats.stringLength);
    CHECK(chunks.stats.rewrites == loop.stats.rewrites);
    REQUIRE(chunks.instances.instances.size() == loop.instances.instances.size());
    size_t differ = 0;
    for (size_t i = 0; i < loop.instances.instances.size(); ++i)
      differ += chunks.instances.instances[i].transform != loop.instances.instances[i].transform;
    CHECK(differ == 0);
  }
}

// String buffers from 64 KiB on are kept for the next derivation: a block given back is
// handed out again, whole, for any request it holds, the smallest that fits first; four
// at most (a fifth replaces the smallest), and none past the 128 MiB cap.
TEST_CASE("String storage is kept between derivations, four blocks within 128 MiB", "[lsystem][parallel]") {
  constexpr size_t KiB = size_t(1) << 10, MiB = size_t(1) << 20;
  backend::StringStoragePool pool;
  size_t granted = 0;
  void* a = pool.take(MiB, granted);
  CHECK(granted == MiB);
  void* b = pool.take(8 * MiB, granted);
  void* c = pool.take(20 * MiB, granted);
  void* d = pool.take(2 * MiB, granted);
  pool.giveBack(a, MiB);
  pool.giveBack(b, 8 * MiB);
  pool.giveBack(c, 20 * MiB);
  pool.giveBack(d, 2 * MiB);
  CHECK(pool.take(5 * MiB, granted) == b);  // the smallest kept block that fits
  CHECK(granted == 8 * MiB);
  CHECK(pool.take(64 * KiB, granted) == a);  // 64 KiB is asked of the pool too
  CHECK(granted == MiB);
  CHECK(pool.take(2 * MiB, granted) == d);
  CHECK(pool.take(10 * MiB, granted) == c);
  CHECK(granted == 20 * MiB);
  void* e = pool.take(10 * MiB, granted);  // none kept now
  CHECK(e != a);
  CHECK(e != b);
  CHECK(e != c);
  CHECK(e != d);
  CHECK(granted == 10 * MiB);
  pool.giveBack(a, MiB);
  pool.giveBack(b, 8 * MiB);
  pool.giveBack(c, 20 * MiB);
  pool.giveBack(d, 2 * MiB);
  pool.giveBack(e, 10 * MiB);  // a fifth: replaces the 1 MiB block, the smallest
  CHECK(pool.take(9 * MiB, granted) == e);
  CHECK(pool.take(512 * KiB, granted) == d);
  CHECK(granted == 2 * MiB);
  pool.giveBack(d, 2 * MiB);
  pool.giveBack(e, 10 * MiB);
  void* huge = pool.take(120 * MiB, granted);  // 40 - 2 + 120 MiB would pass the cap
  pool.giveBack(huge, 120 * MiB);
  void* notKept = pool.take(100 * MiB, granted);
  CHECK(granted == 100 * MiB);  // not the 120 MiB block
  pool.giveBack(notKept, 100 * MiB);
}

// A string buffer asked for more than half the address space in bytes (--max-shapes 2^63
// reserved 2^63 - 1 modules: 16 times that wrapped, and rounding it up to huge pages
// wrapped to 0) is out of memory, std::bad_alloc (R020), and keeps what it held; before,
// a tiny block was taken for a huge one and written past.
TEST_CASE("A string buffer too large for the address space is out of memory and unchanged", "[lsystem][parallel]") {
  backend::StringBuffer<backend::StringModule> buffer;
  buffer.push_back({7, 0, 42});
  const size_t capacity = buffer.capacity();
  const size_t wraps[] = {size_t(INT64_MAX),          // the crash: 2^63 - 1 modules
                          SIZE_MAX / 16,              // bytes SIZE_MAX - 15: rounding up wrapped
                          SIZE_MAX / 16 + 2,          // bytes wrap to 16
                          SIZE_MAX / 2 / 16 + 1};     // the first count refused
  for (size_t modules : wraps) {
    CHECK_THROWS_AS(buffer.reserve(modules), std::bad_alloc);
    CHECK_THROWS_AS(buffer.resizeForOverwrite(modules), std::bad_alloc);
    CHECK_THROWS_AS(buffer.extend(modules), std::bad_alloc);
    CHECK(buffer.size() == 1);
    CHECK(buffer.capacity() == capacity);
    CHECK(buffer[0].op == 7);
    CHECK(buffer[0].key == 42);
  }
  CHECK_THROWS_AS(rt::allocateMeshStorage(SIZE_MAX - 15), std::bad_alloc);
  buffer.reserve(1000);  // a sane size still grows it, keeping the module
  CHECK(buffer.capacity() >= 1000);
  CHECK(buffer[0].key == 42);
}

// A derivation run again after another (reusing its storage, not cleared) gives the
// same string and drawing.
TEST_CASE("A template L-system derived again on kept string storage is the same", "[lsystem][parallel]") {
  const rt::DeriveResult first = deriveText(kTemplates);
  const rt::DeriveResult other = deriveText(oneThreadLoop());
  const rt::DeriveResult again = deriveText(kTemplates);
  REQUIRE(first.ok);
  REQUIRE(again.ok);
  CHECK(again.stats.stringLength == 974304);
  CHECK(again.stats.rewrites == first.stats.rewrites);
  REQUIRE(again.instances.instances.size() == first.instances.instances.size());
  size_t differ = 0;
  for (size_t i = 0; i < first.instances.instances.size(); ++i)
    differ += again.instances.instances[i].transform != first.instances.instances[i].transform ||
              again.instances.instances[i].transform != other.instances.instances[i].transform;
  CHECK(differ == 0);
}

// A template grammar without arguments, decomposition or homomorphism (ABOP's plain
// L-systems) leaves its keys unread and is written as op images (KeylessTemplateImages):
// one pass a step, sizes from the op tally, chunks concurrently from 2^18 modules. E is
// erased (an empty image: runs of them end chunks) and K kept. Expected by hand: 3^n A's
// and 3^n E's after n steps, 10 other modules per rewrite of A, kept: 10 (3^11 - 1) / 2
// + 2 * 3^11 = 1 240 024 modules; 3 F's per rewrite of A, 265 719 segments; rewrites:
// 88 573 of A and (3^11 - 3) / 2 = 88 572 of E. Before the last step 10 (3^10 - 1) / 2 +
// 2 * 3^10 = 413 338 modules: 13 chunks.
TEST_CASE("Template steps without arguments or key readers give the one-thread loop's drawing", "[lsystem][parallel]") {
  const std::string rules = R"(
    derive parallel 11;
    turtle angle 25 width 0.01;
    axiom: A;
    A -> F [ + A ] [ - F K E E E A ] F A;
    E -> epsilon;
  )";
  const rt::DeriveResult loop = onThreads(1, rules + "  Q(x) : x > 0 -> Q(x - 1);\n");
  REQUIRE(loop.ok);
  REQUIRE(loop.stats.stringLength == 1240024);
  REQUIRE(loop.stats.rewrites == 88573 + 88572);
  REQUIRE(loop.instances.instances.size() == 265719);
  for (int threads : {1, 2, 4, 2}) {  // the last one on the storage the others kept
    INFO(threads << " threads");
    const rt::DeriveResult images = onThreads(threads, rules);
    REQUIRE(images.ok);
    CHECK(images.stats.stringLength == loop.stats.stringLength);
    CHECK(images.stats.rewrites == loop.stats.rewrites);
    REQUIRE(images.instances.instances.size() == loop.instances.instances.size());
    size_t differ = 0;
    for (size_t i = 0; i < loop.instances.instances.size(); ++i)
      differ += images.instances.instances[i].transform != loop.instances.instances[i].transform;
    CHECK(differ == 0);
  }
  // --max-shapes reached in a step: the general loop redoes it and stops where it stops.
  rt::DeriveOptions few;
  few.maxShapes = 100000;
  const rt::DeriveResult loopStopped = deriveText(rules + "  Q(x) : x > 0 -> Q(x - 1);\n", few);
  const rt::DeriveResult imagesStopped = deriveText(rules, few);
  REQUIRE(loopStopped.messages.size() == 1);
  REQUIRE(imagesStopped.messages.size() == 1);
  CHECK(imagesStopped.messages[0].message == loopStopped.messages[0].message);
  CHECK(imagesStopped.stats.stringLength == loopStopped.stats.stringLength);
  REQUIRE(imagesStopped.instances.instances.size() == loopStopped.instances.instances.size());
  size_t differ = 0;
  for (size_t i = 0; i < loopStopped.instances.instances.size(); ++i)
    differ += imagesStopped.instances.instances[i].transform != loopStopped.instances.instances[i].transform;
  CHECK(differ == 0);
}

// The template step (TemplateStep: counted, then written chunk by chunk) makes the modules'
// random keys as the general loop does: a stochastic homomorphism draws each B's segment
// length from its key, so any key written differently moves the drawing. Expected values
// by hand: (3^11 - 1) / 2 = 88 573 rewrites of A, three B's each, one segment per B, half
// of them (to 1 %: 265 719 fair draws) 2 long.
TEST_CASE("Template steps give the general loop's random keys, as a stochastic homomorphism shows", "[lsystem][parallel]") {
  const std::string rules = R"(
    derive parallel 11;
    turtle angle 25 width 0.01;
    axiom: A;
    A -> B [ + A ] [ - B A ] B A;
  )";
  const std::string homomorphism = "homomorphism:\nB -> F(1) : 0.5\n  -> F(2) : 0.5;\n";
  const rt::DeriveResult loop = onThreads(1, rules + "  Q(x) : x > 0 -> Q(x - 1);\n" + homomorphism);
  REQUIRE(loop.ok);
  REQUIRE(loop.instances.instances.size() == 265719);
  size_t twoLong = 0;
  for (const rt::Instance& inst : loop.instances.instances) {
    const double length = Eigen::Vector3d(inst.transform[4], inst.transform[5], inst.transform[6]).norm();
    REQUIRE((std::abs(length - 1) < 1e-9 || std::abs(length - 2) < 1e-9));
    twoLong += length > 1.5;
  }
  CHECK(std::abs(double(twoLong) / 265719 - 0.5) < 0.01);
  for (int threads : {1, 2}) {
    INFO(threads << " threads");
    const rt::DeriveResult steps = onThreads(threads, rules + homomorphism);
    REQUIRE(steps.ok);
    CHECK(steps.stats.stringLength == loop.stats.stringLength);
    CHECK(steps.stats.rewrites == loop.stats.rewrites);
    REQUIRE(steps.instances.instances.size() == loop.instances.instances.size());
    size_t differ = 0;
    for (size_t i = 0; i < loop.instances.instances.size(); ++i)
      differ += steps.instances.instances[i].transform != loop.instances.instances[i].transform;
    CHECK(differ == 0);
  }
}
