#include "renders/png_file.h"

#include <isa-l/igzip_lib.h>
#include <png.h>

#include <algorithm>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
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
  // allocation goes back by libpng's own error path (on_png_error), which
  // jumps from outside the handler.
  bool stored = true;
  try {
    out->insert(out->end(), data, data + size);
  } catch (const std::bad_alloc&) {
    stored = false;
  }
  if (!stored) png_error(png, "out of memory for the encoded frame");
}
void flush_nothing(png_structp) {}

// ISA-L's working memory for each level (its own recommended sizes).
std::size_t isal_level_buffer_bytes(int level) {
  switch (level) {
    case 0: return 0;  // level 0 needs none
    case 1: return ISAL_DEF_LVL1_DEFAULT;
    case 2: return ISAL_DEF_LVL2_DEFAULT;
    default: return ISAL_DEF_LVL3_DEFAULT;
  }
}

// The image's rows as PNG's IDAT data wants them before compression (a
// filter-type byte, 0 = none, ahead of each row), deflated by ISA-L into a
// zlib stream. One call over all rows: feeding ISA-L row by row cost half as
// much again as copying the rows into one buffer first.
std::vector<std::uint8_t> deflate_rows_isal(const RgbImage& image, int level) {
  const std::size_t row_bytes = static_cast<std::size_t>(image.width_px) * 3;
  const std::size_t height = static_cast<std::size_t>(image.height_px);
  std::vector<std::uint8_t> rows(height * (row_bytes + 1));
  if (rows.size() > std::numeric_limits<std::uint32_t>::max()) {
    throw std::invalid_argument("encode_png: the image is too large for one ISA-L call (4 GiB)");
  }
  for (std::size_t row = 0; row < height; ++row) {
    rows[row * (row_bytes + 1)] = 0;
    std::memcpy(rows.data() + row * (row_bytes + 1) + 1, image.rgb.data() + row * row_bytes, row_bytes);
  }
  std::vector<std::uint8_t> level_buffer(isal_level_buffer_bytes(level));
  isal_zstream stream;
  isal_deflate_init(&stream);
  stream.gzip_flag = IGZIP_ZLIB;  // PNG's IDAT holds a zlib stream
  stream.level = static_cast<std::uint32_t>(level);
  stream.level_buf = level_buffer.empty() ? nullptr : level_buffer.data();
  stream.level_buf_size = static_cast<std::uint32_t>(level_buffer.size());
  stream.end_of_stream = 1;
  stream.flush = NO_FLUSH;
  stream.next_in = rows.data();
  stream.avail_in = static_cast<std::uint32_t>(rows.size());
  // A rendered frame deflates to a few per cent of its rows; the buffer grows
  // when a noisy one does not.
  std::vector<std::uint8_t> out(rows.size() / 8 + 4096);
  for (;;) {
    stream.next_out = out.data() + stream.total_out;
    stream.avail_out = static_cast<std::uint32_t>(out.size() - stream.total_out);
    const int status = isal_deflate(&stream);
    if (status != COMP_OK) throw std::runtime_error("ISA-L deflate failed with status " + std::to_string(status));
    if (stream.internal_state.state == ZSTATE_END) break;
    const std::size_t grown = std::min<std::size_t>(2 * out.size(), std::numeric_limits<std::uint32_t>::max());
    if (grown == out.size()) throw std::runtime_error("ISA-L deflate: the encoded frame exceeds 4 GiB");
    out.resize(grown);
  }
  out.resize(stream.total_out);
  return out;
}

// libpng's part: the container round `idat` (ISA-L's deflated rows), or the
// whole file through zlib when `idat` is empty, appended to `*out`. False when
// libpng fails, its message in `*error`. Everything libpng writes into lives
// in the caller: the C standard leaves the value of a local object changed
// between setjmp and longjmp indeterminate, and here only `png` and `info`
// are locals, set before setjmp and never after.
bool write_png_stream(const RgbImage& image, const PngSpeed& speed, const std::vector<std::uint8_t>& idat,
                      std::vector<std::uint8_t>* out, PngErrorText* error) {
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
  if (speed.deflate == PngSpeed::Deflate::isal) {
    png_write_info(png, info);  // signature and IHDR
    // IDAT chunks of at most 1 MiB (any size up to 2^31 - 1 is valid; readers
    // are used to small ones), then IEND; libpng adds each chunk's CRC.
    constexpr std::size_t kIdatChunkBytes = std::size_t{1} << 20;
    for (std::size_t at = 0; at < idat.size(); at += kIdatChunkBytes) {
      png_write_chunk(png, reinterpret_cast<png_const_bytep>("IDAT"), idat.data() + at,
                      std::min(kIdatChunkBytes, idat.size() - at));
    }
    png_write_chunk(png, reinterpret_cast<png_const_bytep>("IEND"), nullptr, 0);
  } else {
    png_set_compression_level(png, speed.level);
    png_set_compression_mem_level(png, 6);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
    png_write_info(png, info);
    const std::size_t row_bytes = static_cast<std::size_t>(image.width_px) * 3;
    for (int row = 0; row < image.height_px; ++row) {
      png_write_row(png, image.rgb.data() + static_cast<std::size_t>(row) * row_bytes);
    }
    png_write_end(png, nullptr);
  }
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

std::vector<std::uint8_t> encode_png(const RgbImage& image, const PngSpeed& speed) {
  if (image.width_px <= 0 || image.height_px <= 0 ||
      image.rgb.size() != static_cast<std::size_t>(image.width_px) * static_cast<std::size_t>(image.height_px) * 3) {
    throw std::invalid_argument("encode_png: image size does not match its pixel data");
  }
  const bool isal = speed.deflate == PngSpeed::Deflate::isal;
  const int max_level = isal ? ISAL_DEF_MAX_LEVEL : 9;
  if (speed.level < 0 || speed.level > max_level) {
    throw std::invalid_argument("encode_png: " + std::string(isal ? "ISA-L" : "zlib") + " level must be in [0, " +
                                std::to_string(max_level) + "], got " + std::to_string(speed.level));
  }
  // Deflated before libpng starts: nothing may throw through libpng's frames.
  const std::vector<std::uint8_t> idat = isal ? deflate_rows_isal(image, speed.level) : std::vector<std::uint8_t>{};
  std::vector<std::uint8_t> encoded;
  encoded.reserve(isal ? idat.size() + 1024 : image.rgb.size() / 16);
  PngErrorText error;
  if (!write_png_stream(image, speed, idat, &encoded, &error)) {
    throw std::runtime_error(std::string("libpng: ") + (error.text[0] == '\0' ? "out of memory" : error.text));
  }
  return encoded;
}

void write_png(const std::filesystem::path& path, const RgbImage& image, const PngSpeed& speed) {
  std::vector<std::uint8_t> encoded;
  try {
    encoded = encode_png(image, speed);
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
