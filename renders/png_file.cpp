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

// libpng's message, kept in a fixed buffer: nothing called from inside
// libpng may allocate and throw.
struct PngErrorText {
  char text[160] = {};
};

// libpng's own error path: keep the message, jump back to write_png_stream's setjmp.
[[noreturn]] void on_png_error(png_structp png, png_const_charp message) {
  std::snprintf(static_cast<PngErrorText*>(png_get_error_ptr(png))->text, sizeof(PngErrorText::text), "%s", message);
  png_longjmp(png, 1);
}
void on_png_warning(png_structp, png_const_charp) {}

void append_bytes(png_structp png, png_bytep data, png_size_t size) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
  // No C++ exception may unwind through libpng's C frames: a failed
  // allocation goes back by libpng's own error path, from outside the handler.
  bool stored = true;
  try {
    out->insert(out->end(), data, data + size);
  } catch (const std::bad_alloc&) {
    stored = false;
  }
  if (!stored) png_error(png, "out of memory for the encoded frame");
}
void flush_nothing(png_structp) {}

// The whole file appended to `*out`; false when libpng fails, its message in
// `*error`. Everything libpng writes into lives in the caller: the C standard
// leaves a local changed between setjmp and longjmp indeterminate, and here
// only `png` and `info` are locals, set before setjmp and never after.
bool write_png_stream(const RgbImage& image, std::vector<std::uint8_t>* out, PngErrorText* error) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, error, on_png_error, on_png_warning);
  if (png == nullptr) return false;
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    return false;
  }
  // Nothing with a destructor is created below, so the jump skips no clean-up.
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
  const std::size_t row_bytes = static_cast<std::size_t>(image.width_px) * 3;
  for (int row = 0; row < image.height_px; ++row) {
    png_write_row(png, image.rgb.data() + static_cast<std::size_t>(row) * row_bytes);
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
  std::vector<std::uint8_t> encoded;
  encoded.reserve(image.rgb.size() / 16);  // a rendered frame deflates to a few per cent of its rows
  PngErrorText error;
  if (!write_png_stream(image, &encoded, &error)) {
    throw std::runtime_error(std::string("libpng: ") + (error.text[0] == '\0' ? "out of memory" : error.text));
  }
  return encoded;
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
