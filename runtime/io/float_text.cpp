#include "runtime/io/float_text.h"

// Header-only: the digits of one float, without a run-time dependency on libfmt.
#define FMT_HEADER_ONLY
#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace fgsg::rt::io {
namespace {

constexpr char kPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

int digitCount(uint32_t n) {
  return 1 + (n >= 10) + (n >= 100) + (n >= 1000) + (n >= 10000) + (n >= 100000) + (n >= 1000000) +
         (n >= 10000000) + (n >= 100000000) + (n >= 1000000000);
}

// The `count` decimal digits of n at p, two at a time from the last.
void putDigits(char* p, uint32_t n, int count) {
  char* end = p + count;
  while (n >= 100) {
    end -= 2;
    std::memcpy(end, kPairs + 2 * (n % 100), 2);
    n /= 100;
  }
  if (n >= 10) {
    std::memcpy(end - 2, kPairs + 2 * n, 2);
  } else {
    end[-1] = char('0' + n);
  }
}

}  // namespace

char* putShortestFloat(char* p, float v) {
  // The sign without a branch: coordinates' signs are as good as random.
  *p = '-';
  p += std::signbit(v);
  v = std::fabs(v);
  if (v == 0.0f) {
    *p++ = '0';
    return p;
  }
  // v = significand x 10^exponent, the shortest digits that read back as v.
  const auto decimal = fmt::detail::dragonbox::to_decimal(v);
  const uint32_t significand = decimal.significand;
  const int exponent = decimal.exponent;
  const int n = digitCount(significand);
  const int scientificExponent = exponent + n - 1;
  const int absExponent = scientificExponent < 0 ? -scientificExponent : scientificExponent;
  const int scientificLength = n + (n > 1) + 2 + (absExponent >= 100 ? 3 : 2);
  const int fixedLength = exponent >= 0 ? n + exponent : (n > -exponent ? n + 1 : 2 - exponent);
  // The digits are written in place (a point moved in after them), no copies: the
  // writer's cost is here.
  if (fixedLength <= scientificLength) {
    // Whole numbers print as printf's %.0f does, every digit exact (to_chars's rule): a
    // float of 14 digits at most here (longer ones are shorter in scientific form).
    if (exponent > 0) return std::to_chars(p, p + kMaxFloatText, uint64_t(v)).ptr;
    if (exponent == 0) {
      putDigits(p, significand, n);
      return p + n;
    }
    const int whole = n + exponent;  // digits before the point
    if (whole > 0) {  // dd.ddd
      putDigits(p + 1, significand, n);
      for (int i = 0; i < whole; ++i) p[i] = p[i + 1];
      p[whole] = '.';
      return p + n + 1;
    }
    p[0] = '0', p[1] = '.';  // 0.000ddd
    for (int i = 0; i < -whole; ++i) p[2 + i] = '0';
    putDigits(p + 2 - whole, significand, n);
    return p + fixedLength;
  }
  putDigits(p + 1, significand, n);  // d.ddde+XX
  p[0] = p[1];
  if (n > 1) p[1] = '.';
  p += n + (n > 1);
  *p++ = 'e';
  *p++ = scientificExponent < 0 ? '-' : '+';
  if (absExponent >= 100) *p++ = char('0' + absExponent / 100);
  std::memcpy(p, kPairs + 2 * (absExponent % 100), 2);
  return p + 2;
}

}  // namespace fgsg::rt::io
