// libFuzzer target: the one image reader (runtime/io/read_image.h: PNG, JPEG, BMP through
// stb_image, binary PGM/PPM) on arbitrary bytes, as texture contexts, Texture(), image
// fields and synthesis examples read them. The format comes from the content. So that
// mutations get past the PNG check of critical chunks' CRCs and reach stb's decoder, an
// input whose last byte has bit 1 set has its chunks' CRCs recomputed first (a chunk that
// does not fit is left as it is). Oracles: a failure has a message naming the file and
// leaves no picture; checkImage and decodeImage agree (a header that checks decodes, or
// fails with a message, to the same size and channels); a picture is within the limits,
// has width x height x channels samples of its depth, each at most its full scale; the
// same bytes decode to the same samples twice (a decoder reading uninitialised memory, as
// stb's TGA did on a truncated file, is caught where the heap differs between the calls).
#include "runtime/io/read_image.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_image finding: %s\n", what.c_str());
  std::abort();
}

void fixPngCrcs(std::string& b) {
  size_t at = 8;
  while (at + 12 <= b.size()) {
    const uint32_t length = uint32_t(uint8_t(b[at])) << 24 | uint32_t(uint8_t(b[at + 1])) << 16 |
                            uint32_t(uint8_t(b[at + 2])) << 8 | uint32_t(uint8_t(b[at + 3]));
    if (at + 12 + uint64_t(length) > b.size()) return;
    const uint32_t c = fgsg::rt::io::pngChunkCrc(b, at, length);
    for (int k = 0; k < 4; ++k) b[at + 8 + length + size_t(k)] = char(c >> (24 - 8 * k));
    at += 12 + length;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace fgsg::rt::io;
  if (size > 16384) return -1;
  std::string bytes(reinterpret_cast<const char*>(data), size);
  if (size > 0 && (data[size - 1] & 2) && imageFormatOf(bytes) == ImageFormat::Png) fixPngCrcs(bytes);

  const std::string path = "fuzz.png";
  ImageLimits limits;
  limits.maxPixels = int64_t(1) << 22;  // the decoders' time, not the reader's bound, is at stake past this
  Image header, image, again;
  std::string headerError, error, againError;
  const bool checked = checkImage(path, bytes, limits, header, headerError);
  const bool ok = decodeImage(path, bytes, limits, image, error);
  if (!checked) {
    if (ok) finding("an image that fails its check decoded");
    if (headerError.empty() || headerError.rfind(path + ": ", 0) != 0) finding("a check's message: " + headerError);
  }
  if (!ok) {
    if (error.empty() || error.rfind(path + ": ", 0) != 0) finding("a failure's message: " + error);
    if (error.size() > 1024) finding("a message of " + std::to_string(error.size()) + " bytes");
    if (image.width || image.height || !image.samples8.empty() || !image.samples16.empty())
      finding("a failed decode left a picture");
    return 0;
  }
  if (image.format == ImageFormat::Unknown || image.format != header.format) finding("the decoded format differs");
  if (image.width != header.width || image.height != header.height) finding("the decoded size differs from the header's");
  if (image.bits != header.bits || image.fullScale != header.fullScale) finding("the decoded depth differs from the header's");
  if (image.width <= 0 || image.height <= 0 || int64_t(image.width) * image.height > limits.maxPixels)
    finding("a picture of " + std::to_string(image.width) + " x " + std::to_string(image.height));
  if (image.channels < 1 || image.channels > 4) finding("a picture of " + std::to_string(image.channels) + " channels");
  if (image.bits != 8 && image.bits != 16) finding("a picture of " + std::to_string(image.bits) + " bits");
  if (image.fullScale == 0) finding("a full scale of 0");
  const size_t n = size_t(image.width) * size_t(image.height) * size_t(image.channels);
  if ((image.bits == 8 ? image.samples8.size() : image.samples16.size()) != n ||
      (image.bits == 8 ? !image.samples16.empty() : !image.samples8.empty()))
    finding("a picture without width x height x channels samples");
  for (size_t i = 0; i < n; ++i)
    if (image.sample(i) > image.fullScale) finding("sample " + std::to_string(i) + " above the full scale");
  (void)image.sample8(n - 1);
  if (!decodeImage(path, bytes, limits, again, againError)) finding("the second decode failed: " + againError);
  if (again.samples8 != image.samples8 || again.samples16 != image.samples16)
    finding("the same bytes decoded to different samples");
  return 0;
}
