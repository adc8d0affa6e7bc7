#include "march_fixtures.h"

#include "runtime/marching/atlas_preview.h"
#include "tests/unit/runtime/scratch_files.h"

#include <set>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

using namespace fgsg::rt;
using namespace fgsg::rt::marching;
using namespace fgsg::rt::marching::testing;

TEST_CASE("the atlas preview shows charts, indirection texels and pointers", "[marching][preview]") {
  const auto s = prepared(chartedCube(8, 256));
  const PreviewImage img = renderAtlasPreview(*s);
  REQUIRE(img.width == 256);
  REQUIRE(img.height == 256);
  const GeometryImage& gi = s->image();
  // Picture rows run top to bottom, image rows bottom to top.
  auto pixel = [&](int x, int y) { return img.at(x, 255 - y); };
  CHECK(pixel(0, 0) == kPreviewBackground);
  std::set<Rgb> colours;
  for (int chart = 0; chart < 6; ++chart) colours.insert(chartColour(chart));
  CHECK(colours.size() == 6u);
  int inner = 0, indirection = 0, lines = 0;
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) {
      const Rgb c = pixel(x, y);
      const int t = gi.index(x, y);
      if (c == kPreviewPointer) {
        ++lines;
        continue;
      }
      if (gi.kind(t) == TexelKind::Inner) {
        REQUIRE(c == chartColour(gi.chart(t)));
        ++inner;
      } else if (gi.kind(t) == TexelKind::Indirection) {
        REQUIRE(c == kPreviewIndirection);
        ++indirection;
      } else {
        REQUIRE(c == kPreviewBackground);
      }
    }
  // Every kind shows where no pointer line crosses it; the lines cover a minority.
  CHECK(inner > 10000);
  CHECK(indirection > 300);
  CHECK(lines > 100);
  CHECK(lines < inner);
}

TEST_CASE("an open surface's border shows in the boundary colour", "[marching][preview]") {
  const auto s = prepared(flatSquare(20, 2.0, 64, 4));
  const PreviewImage img = renderAtlasPreview(*s);
  CHECK(img.at(3, 63 - 30) == kPreviewBoundary);  // the ring x = 3 around the chart [4, 60]
  CHECK(img.at(30, 63 - 30) == chartColour(0));
}

TEST_CASE("the atlas preview is written as the PNG of the picture", "[marching][preview]") {
  const auto s = prepared(chartedCube(4, 128));
  const auto dir = fgsg::test::scratchDir("marching-preview", "png");
  const std::string path = (dir / "atlas.png").string();
  std::string error;
  REQUIRE(writeAtlasPreview(*s, path, error));
  const std::string png = fgsg::test::readFile(path);
  int w = 0, h = 0, channels = 0;
  unsigned char* decoded = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(png.data()), int(png.size()),
                                                 &w, &h, &channels, 3);
  REQUIRE(decoded);
  const PreviewImage expected = renderAtlasPreview(*s);
  CHECK(w == expected.width);
  CHECK(h == expected.height);
  CHECK(std::equal(expected.rgb.begin(), expected.rgb.end(), decoded));
  stbi_image_free(decoded);

  CHECK_FALSE(writeAtlasPreview(*s, (dir / "no-such-folder" / "atlas.png").string(), error));
  CHECK_FALSE(error.empty());
}
