#include "renders/png_file.h"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace railjoint {

namespace {

// libpng reports a failure by longjmp: its message goes into the caller's
// fixed buffer (nothing called from libpng may throw).
struct PngError {
  char text[160] = {};
};

[[noreturn]] void on_png_error(png_structp png, png_const_charp message) {
  std::snprintf(static_cast<PngError*>(png_get_error_ptr(png))->text, sizeof(PngError::text), "%s", message);
  png_longjmp(png, 1);
}
void on_png_warning(png_structp, png_const_charp) {}

// false when libpng fails (its fwrite coming up short included). Nothing with
// a destructor lives here, so the jump skips no clean-up.
bool write_png_stream(const RgbImage& image, std::FILE* file, PngError* error) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, error, on_png_error, on_png_warning);
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
  png_init_io(png, file);
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

void write_png(const std::filesystem::path& path, const RgbImage& image) {
  if (image.width_px <= 0 || image.height_px <= 0 ||
      image.rgb.size() != static_cast<std::size_t>(image.width_px) * static_cast<std::size_t>(image.height_px) * 3) {
    throw std::invalid_argument("write_png: image size does not match its pixel data");
  }
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr) throw std::runtime_error("cannot open " + path.string() + " for writing");
  PngError error;
  const bool written = write_png_stream(image, file, &error);
  if (std::fclose(file) != 0 || !written) {
    throw std::runtime_error("cannot write " + path.string() + " (" +
                             (error.text[0] == '\0' ? "out of memory or disk full" : "libpng: " + std::string(error.text)) + ")");
  }
}

}  // namespace railjoint
