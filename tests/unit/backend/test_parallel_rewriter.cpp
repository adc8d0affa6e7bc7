// A long string whose every rule is a fixed successor is rewritten in chunks on all
// cores (backend/engine/parallel_rewriter.cpp: rewriteTemplatesConcurrently, from
// 2 x 32 768 modules). The chunks' result must be the one-thread loop's, on any number of
// threads. scripts/tsan.sh runs this under ThreadSanitizer (issue 52).
#include "derive_helpers.h"

#include <catch2/catch.hpp>
#include <tbb/global_control.h>

using namespace fgsg;
using fgsg::test::deriveText;

namespace {

// 3^n A's after n steps, each with kept, parameterized F's and bracketed turns beside it:
// 3^n + 9 (3^n - 1) / 2 modules, 108 252 before the last of 10 steps, which is rewritten
// in 4 chunks.
const char* kTemplates = R"(
  derive parallel 10;
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
  REQUIRE(loop.stats.stringLength == 324765);
  REQUIRE(loop.instances.instances.size() == 88572);  // 3 F's per rewrite
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
