// The PGM/PPM reader against Netpbm's format: binary samples of one byte when the maxval
// is below 256, else two bytes, most significant first; maxval between 1 and 65535.
// Samples above the maxval are clamped to it (pnm_reader.h).
#include "runtime/io/pnm_reader.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace fgsg::rt::io;

namespace {

// A file's samples; none, and the reader's message in `error`, when it cannot be read.
std::vector<uint16_t> pnmSamples(const std::string& bytes, std::string& error) {
  PnmHeader header;
  std::vector<uint16_t> samples;
  error.clear();
  if (!readPnmHeader(bytes, header, error) || !readPnmSamples(bytes, header, samples, error)) return {};
  return samples;
}

}  // namespace

TEST_CASE("PGM: 16-bit samples are big-endian", "[pnm]") {
  std::string error;
  // 0x01 0x02 -> 1 * 256 + 2; 0xff 0x00 -> 65280 (little-endian would give 513 and 255).
  CHECK(pnmSamples(std::string("P5 2 1 65535\n") + '\x01' + '\x02' + '\xff' + '\0', error) ==
        std::vector<uint16_t>{258, 65280});
  CHECK(error.empty());
}

TEST_CASE("PGM: maxval 255 takes one byte a sample, 256 two", "[pnm]") {
  std::string error;
  PnmHeader header;
  REQUIRE(readPnmHeader("P5 1 1 255\n\x07", header, error));
  CHECK(header.rasterBytes() == 1);
  CHECK(pnmSamples("P5 1 1 255\n\x07", error) == std::vector<uint16_t>{7});
  CHECK(pnmSamples(std::string("P5 1 1 256\n") + '\0' + '\x07', error) == std::vector<uint16_t>{7});
  CHECK(error.empty());
}

TEST_CASE("PGM: binary samples above the maxval are clamped to it", "[pnm]") {
  std::string error;
  // One byte: 200 above maxval 100, 99 below it.
  CHECK(pnmSamples("P5 2 1 100\n\xc8\x63", error) == std::vector<uint16_t>{100, 99});
  // Two bytes: 0x1388 = 5000 above maxval 4095, 0x0fff = 4095 at it.
  CHECK(pnmSamples("P5 2 1 4095\n\x13\x88\x0f\xff", error) == std::vector<uint16_t>{4095, 4095});
  CHECK(error.empty());
}

TEST_CASE("PGM: maxval 0 and above 65535 are errors", "[pnm]") {
  std::string error;
  PnmHeader header;
  CHECK_FALSE(readPnmHeader(std::string("P5 1 1 0\n") + '\0', header, error));
  CHECK(error == "the PGM/PPM maxval is 0, not between 1 and 65535");
  CHECK_FALSE(readPnmHeader("P2 1 1 0\n0\n", header, error));
  CHECK(error == "the PGM/PPM maxval is 0, not between 1 and 65535");
  CHECK_FALSE(readPnmHeader("P5 1 1 65536\n\x01\x02", header, error));
  CHECK(error == "the PGM/PPM maxval is 65536, not between 1 and 65535");
}
