// PNG output read back by libpng's own reader (its simplified API), which
// checks every chunk's CRC and the zlib stream's Adler-32: the pixels must
// come back exactly.

#include <png.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "renders/png_file.h"
#include "tests/support/scratch_dir.h"

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

// Every byte random: nothing to compress, so the encoded frame spans several IDAT chunks.
RgbImage noise(int width_px, int height_px) {
  RgbImage image{width_px, height_px, std::vector<std::uint8_t>(static_cast<std::size_t>(width_px) * height_px * 3)};
  std::mt19937 random(20261125u);
  for (auto& byte : image.rgb) byte = static_cast<std::uint8_t>(random() >> 24);
  return image;
}

// Writes the image and reads the file back.
RgbImage write_and_decode(const RgbImage& written, std::uintmax_t* file_bytes = nullptr) {
  const std::filesystem::path path = testing_support::scratch_path("png") / "frame.png";
  std::filesystem::create_directories(path.parent_path());
  write_png(path, written);
  if (file_bytes != nullptr) *file_bytes = std::filesystem::file_size(path);
  png_image reader{};
  reader.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&reader, path.c_str())) {
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
  const RgbImage back = write_and_decode(image);
  EXPECT_EQ(back.width_px, image.width_px) << what;
  EXPECT_EQ(back.height_px, image.height_px) << what;
  EXPECT_TRUE(back.rgb == image.rgb) << what;
}

TEST(PngFile, GivesBackTheExactPixels) {
  expect_round_trip(frame_like(321, 187), "321 x 187");  // odd sizes: no row is a multiple of 4 bytes
}

TEST(PngFile, AnIncompressibleFrameComesBackWholeAcrossSeveralChunks) {
  // 1280 x 720 random RGB is 2.76 MB that deflate cannot shrink: many IDAT chunks.
  const RgbImage frame = noise(1280, 720);
  std::uintmax_t bytes = 0;
  EXPECT_TRUE(write_and_decode(frame, &bytes).rgb == frame.rgb);
  EXPECT_GT(bytes, frame.rgb.size());  // stored blocks: a little over the rows
}

TEST(PngFile, ASinglePixelAndASingleRowRoundTrip) {
  expect_round_trip(frame_like(1, 1), "1 x 1");
  expect_round_trip(frame_like(4000, 1), "4000 x 1");
  expect_round_trip(frame_like(1, 300), "1 x 300");
}

TEST(PngFile, RefusesMismatchedSizes) {
  RgbImage short_of_a_byte = frame_like(8, 8);
  short_of_a_byte.rgb.pop_back();
  EXPECT_THROW(write_png(testing_support::scratch_path("mismatch") / "frame.png", short_of_a_byte), std::invalid_argument);
}

TEST(PngFile, AFileThatCannotBeWrittenIsNamed) {
  // A regular file where the folder should be: no file can be opened below it.
  const std::filesystem::path base = testing_support::scratch_path("blocked");
  std::filesystem::create_directories(base);
  std::FILE* blocker = std::fopen((base / "not_a_folder").c_str(), "wb");
  ASSERT_NE(blocker, nullptr);
  std::fclose(blocker);
  const std::filesystem::path path = base / "not_a_folder" / "frame.png";
  try {
    write_png(path, frame_like(8, 8));
    FAIL() << "expected an error for " << path;
  } catch (const std::runtime_error& error) {
    std::cout << "  " << error.what() << "\n";
    EXPECT_NE(std::string(error.what()).find(path.string()), std::string::npos);
  }
}

TEST(PngFile, AFullDiskIsAnError) {
  // /dev/full refuses every write: a frame larger than stdio's buffer fails in
  // libpng's own fwrite, a small one when the file is closed.
  for (const RgbImage& image : {noise(64, 64), frame_like(4, 4)}) {
    EXPECT_THROW(write_png("/dev/full", image), std::runtime_error) << image.width_px << " x " << image.height_px;
  }
}

}  // namespace
}  // namespace railjoint
