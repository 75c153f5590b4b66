#include "renders/png_file.h"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <fstream>
#include <new>
#include <stdexcept>
#include <string>

namespace railjoint {

namespace {

// What libpng writes into, all of it the caller's: after libpng's longjmp
// the C standard leaves a local changed since setjmp indeterminate. The
// message sits in a fixed buffer: nothing called from libpng may throw.
struct PngOutput {
  std::vector<std::uint8_t> bytes;
  char error[160] = {};
};

[[noreturn]] void on_png_error(png_structp png, png_const_charp message) {
  std::snprintf(static_cast<PngOutput*>(png_get_error_ptr(png))->error, sizeof(PngOutput::error), "%s", message);
  png_longjmp(png, 1);
}
void on_png_warning(png_structp, png_const_charp) {}

void append_bytes(png_structp png, png_bytep data, png_size_t size) {
  bool stored = true;  // a failed allocation goes back by libpng's error path, from outside the handler
  try {
    auto& bytes = static_cast<PngOutput*>(png_get_io_ptr(png))->bytes;
    bytes.insert(bytes.end(), data, data + size);
  } catch (const std::bad_alloc&) {
    stored = false;
  }
  if (!stored) png_error(png, "out of memory for the encoded frame");
}
void flush_nothing(png_structp) {}

// false when libpng fails. Nothing with a destructor lives here, so the jump skips no clean-up.
bool write_png_stream(const RgbImage& image, PngOutput* out) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, out, on_png_error, on_png_warning);
  if (png == nullptr) return false;
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    return false;
  }
  if (setjmp(png_jmpbuf(png)) != 0) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, out, append_bytes, flush_nothing);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width_px), static_cast<png_uint_32>(image.height_px), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
  png_set_compression_level(png, 1);
  png_set_compression_mem_level(png, 6);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_write_info(png, info);
  for (int row = 0; row < image.height_px; ++row) {
    png_write_row(png, image.pixel(0, row));
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

std::vector<std::uint8_t> encode_png(const RgbImage& image) {
  if (image.width_px <= 0 || image.height_px <= 0 ||
      image.rgb.size() != static_cast<std::size_t>(image.width_px) * static_cast<std::size_t>(image.height_px) * 3) {
    throw std::invalid_argument("encode_png: image size does not match its pixel data");
  }
  PngOutput out;
  out.bytes.reserve(image.rgb.size() / 16);  // a rendered frame deflates to a few per cent of its rows
  if (!write_png_stream(image, &out)) {
    throw std::runtime_error(std::string("libpng: ") + (out.error[0] == '\0' ? "out of memory" : out.error));
  }
  return std::move(out.bytes);
}

void write_png(const std::filesystem::path& path, const RgbImage& image) {
  std::vector<std::uint8_t> encoded;
  try {
    encoded = encode_png(image);
  } catch (const std::exception& error) {
    throw std::runtime_error("cannot encode PNG " + path.string() + ": " + error.what());
  }
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (!file) throw std::runtime_error("cannot open " + path.string() + " for writing");
  file.write(reinterpret_cast<const char*>(encoded.data()), static_cast<std::streamsize>(encoded.size()));
  file.close();
  if (!file) throw std::runtime_error("cannot write " + path.string() + " (disk full?)");
}

}  // namespace railjoint
