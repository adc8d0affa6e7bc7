// A long string whose every rule is a fixed successor is rewritten in chunks on all
// cores (backend/engine/parallel_rewriter.cpp: rewriteTemplates, from 2^18 modules), a
// shorter one on the calling thread, both counted first and then written (TemplateStep).
// Both must give the general one-thread loop's result, on any number of threads.
// scripts/tsan.sh runs this under ThreadSanitizer (issue 52).
#include "derive_helpers.h"

#include "backend/engine/string_storage_pool.h"

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

// Large string buffers are kept for the next derivation: a block given back is handed out
// again for any request it holds, the smallest that fits first; small blocks and blocks
// past the 128 MiB cap are not kept.
TEST_CASE("String storage is kept between derivations, two large blocks within 128 MiB", "[lsystem][parallel]") {
  constexpr size_t MiB = size_t(1) << 20;
  backend::StringStoragePool pool;
  size_t granted = 0;
  void* small = pool.take(MiB, granted);
  CHECK(granted == MiB);
  pool.giveBack(small, MiB);
  void* a = pool.take(8 * MiB, granted);
  void* b = pool.take(20 * MiB, granted);
  CHECK(granted == 20 * MiB);
  pool.giveBack(a, 8 * MiB);
  pool.giveBack(b, 20 * MiB);
  void* again = pool.take(5 * MiB, granted);  // the smaller kept block fits
  CHECK(again == a);
  CHECK(granted == 8 * MiB);
  void* big = pool.take(10 * MiB, granted);
  CHECK(big == b);
  CHECK(granted == 20 * MiB);
  void* fresh = pool.take(10 * MiB, granted);  // none kept now
  CHECK(fresh != a);
  CHECK(fresh != b);
  CHECK(granted == 10 * MiB);
  pool.giveBack(again, 8 * MiB);
  pool.giveBack(big, 20 * MiB);
  pool.giveBack(fresh, 10 * MiB);  // replaces the 8 MiB block, the smaller one
  CHECK(pool.take(9 * MiB, granted) == fresh);
  CHECK(granted == 10 * MiB);
  pool.giveBack(fresh, 10 * MiB);
  void* huge = pool.take(120 * MiB, granted);  // 20 + 120 MiB would pass the cap
  pool.giveBack(huge, 120 * MiB);
  void* notKept = pool.take(100 * MiB, granted);
  CHECK(granted == 100 * MiB);  // not the 120 MiB block
  pool.giveBack(notKept, 100 * MiB);
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
