// PNG output read back by libpng's own reader (its simplified API), which
// checks every chunk's CRC and the zlib stream's Adler-32: the pixels must
// come back exactly.

#include <png.h>

#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "renders/png_file.h"

namespace railjoint {
namespace {

// A frame like a render's: flat fields, a gradient, a few sharp edges.
RgbImage frame_like(int width_px, int height_px) {
  RgbImage image{width_px, height_px, std::vector<std::uint8_t>(static_cast<std::size_t>(width_px) * height_px * 3)};
  for (int y = 0; y < height_px; ++y) {
    for (int x = 0; x < width_px; ++x) {
      std::uint8_t* p = image.rgb.data() + (static_cast<std::size_t>(y) * width_px + x) * 3;
      const bool wheel = (x - width_px / 2) * (x - width_px / 2) + (y - height_px / 3) * (y - height_px / 3) <
                         (height_px / 4) * (height_px / 4);
      p[0] = wheel ? 40 : static_cast<std::uint8_t>(200 - y * 100 / height_px);
      p[1] = wheel ? 90 : 210;
      p[2] = static_cast<std::uint8_t>(x * 255 / width_px);
    }
  }
  return image;
}

// Every byte random: nothing to compress, so the encoded frame outgrows the
// encoder's first guess (a sixteenth of the rows) and spans several IDAT chunks.
RgbImage noise(int width_px, int height_px) {
  RgbImage image{width_px, height_px, std::vector<std::uint8_t>(static_cast<std::size_t>(width_px) * height_px * 3)};
  std::mt19937 random(20261125u);
  for (auto& byte : image.rgb) byte = static_cast<std::uint8_t>(random() >> 24);
  return image;
}

RgbImage decode(const std::vector<std::uint8_t>& png_bytes) {
  png_image reader{};
  reader.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&reader, png_bytes.data(), png_bytes.size())) {
    throw std::runtime_error(std::string("libpng cannot read it: ") + reader.message);
  }
  reader.format = PNG_FORMAT_RGB;
  RgbImage image{static_cast<int>(reader.width), static_cast<int>(reader.height),
                 std::vector<std::uint8_t>(PNG_IMAGE_SIZE(reader))};
  if (!png_image_finish_read(&reader, nullptr, image.rgb.data(), 0, nullptr)) {
    throw std::runtime_error(std::string("libpng cannot decode it: ") + reader.message);
  }
  return image;
}

void expect_round_trip(const RgbImage& image, const char* what) {
  const RgbImage back = decode(encode_png(image));
  EXPECT_EQ(back.width_px, image.width_px) << what;
  EXPECT_EQ(back.height_px, image.height_px) << what;
  EXPECT_TRUE(back.rgb == image.rgb) << what;
}

TEST(PngFile, GivesBackTheExactPixels) {
  expect_round_trip(frame_like(321, 187), "321 x 187");  // odd sizes: no row is a multiple of 4 bytes
}

TEST(PngFile, AnIncompressibleFrameComesBackWholeAcrossSeveralChunks) {
  // 1280 x 720 random RGB is 2.76 MB that deflate cannot shrink: many IDAT
  // chunks, and the output buffer has to grow several times.
  const RgbImage frame = noise(1280, 720);
  const std::vector<std::uint8_t> bytes = encode_png(frame);
  EXPECT_GT(bytes.size(), frame.rgb.size());  // stored blocks: a little over the rows
  EXPECT_TRUE(decode(bytes).rgb == frame.rgb);
}

TEST(PngFile, ASinglePixelAndASingleRowRoundTrip) {
  expect_round_trip(frame_like(1, 1), "1 x 1");
  expect_round_trip(frame_like(4000, 1), "4000 x 1");
  expect_round_trip(frame_like(1, 300), "1 x 300");
}

TEST(PngFile, RefusesMismatchedSizes) {
  RgbImage short_of_a_byte = frame_like(8, 8);
  short_of_a_byte.rgb.pop_back();
  EXPECT_THROW(encode_png(short_of_a_byte), std::invalid_argument);
}

}  // namespace
}  // namespace railjoint
