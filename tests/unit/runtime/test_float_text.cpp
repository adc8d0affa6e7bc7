// putShortestFloat (runtime/io/float_text.h) writes exactly what std::to_chars(float)
// writes: the OBJ writer's bytes did not change when it took over.
#include "runtime/io/float_text.h"

#include <catch2/catch.hpp>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

namespace {

std::string ours(float v) {
  char text[32];
  return std::string(text, fgsg::rt::io::putShortestFloat(text, v));
}

std::string standard(float v) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, v).ptr);
}

}  // namespace

TEST_CASE("shortest float text: the layouts, as std::to_chars writes them") {
  CHECK(ours(0.0f) == "0");
  CHECK(ours(-0.0f) == "-0");
  CHECK(ours(1.5f) == "1.5");
  CHECK(ours(-0.1f) == "-0.1");
  CHECK(ours(1e-5f) == "1e-05");          // shorter than 0.00001
  CHECK(ours(0.0001f) == "1e-04");        // a tie would be fixed; this is no tie
  CHECK(ours(0.001f) == "0.001");
  CHECK(ours(100000.0f) == "1e+05");
  CHECK(ours(123456792.0f) == "123456792");
  CHECK(ours(67110072.0f) == "67110072");  // whole: every digit exact, not 67110070
  CHECK(ours(3.4028235e38f) == "3.4028235e+38");
  CHECK(ours(1e-45f) == "1e-45");          // the smallest subnormal
  CHECK(ours(-1.1754944e-38f) == "-1.1754944e-38");
}

TEST_CASE("shortest float text: the same bytes as std::to_chars across the float range") {
  // Every 4099th bit pattern (about a million floats, all exponents, both signs), and
  // the neighbours of every power of ten.
  size_t compared = 0;
  for (uint64_t bits = 0; bits < (uint64_t(1) << 32); bits += 4099) {
    float v;
    const uint32_t b = uint32_t(bits);
    std::memcpy(&v, &b, sizeof v);
    if (!std::isfinite(v)) continue;
    if (ours(v) != standard(v)) FAIL("bits " << b << ": " << ours(v) << " vs " << standard(v));
    ++compared;
  }
  CHECK(compared > 1000000);
  for (int e = -45; e <= 38; ++e) {
    const float p = std::pow(10.0f, float(e));
    for (float v : {p, std::nextafter(p, 0.0f), std::nextafter(p, std::numeric_limits<float>::infinity())})
      if (std::isfinite(v) && ours(v) != standard(v)) FAIL("10^" << e << ": " << ours(v) << " vs " << standard(v));
  }
}
