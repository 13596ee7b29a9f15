// PNG heightmaps through libpng. libpng reports errors by longjmp: every setjmp below sits in
// a function that owns no object with a destructor, so the jump skips no C++ cleanup; buffers
// are sized by the callers between the phases.

#include <png.h>

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "physics/heightmap_io.hpp"
#include "physics/heightmap_raster.hpp"
#include "physics/heightmap_sample.hpp"

namespace mechsim::physics {
namespace {

// Keys of the text chunks save_heightmap_png writes; values are decimal numbers.
constexpr const char* kTextKeys[4] = {"mechsim.size_x", "mechsim.size_y", "mechsim.z_min",
                                      "mechsim.z_max"};

struct PngJob {
  std::FILE* file = nullptr;
  png_structp png = nullptr;
  png_infop info = nullptr;
  char message[256] = {};
  png_uint_32 width = 0, height = 0;
  int bit_depth = 0, color_type = 0;
  double text_value[4] = {};
  bool has_text[4] = {};
};

void on_png_error(png_structp png, png_const_charp msg) {
  auto* job = static_cast<PngJob*>(png_get_error_ptr(png));
  std::snprintf(job->message, sizeof job->message, "%s", msg);
  png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}

bool read_header(PngJob& job) {
  if (setjmp(png_jmpbuf(job.png))) return false;
  png_init_io(job.png, job.file);
  png_read_info(job.png, job.info);
  int interlace = 0, compression = 0, filter = 0;
  png_get_IHDR(job.png, job.info, &job.width, &job.height, &job.bit_depth, &job.color_type,
               &interlace, &compression, &filter);
  return true;
}

bool read_pixels(PngJob& job, png_bytepp rows) {
  if (setjmp(png_jmpbuf(job.png))) return false;
  png_read_image(job.png, rows);
  png_read_end(job.png, job.info);  // collects text chunks placed after the image data too
  png_textp text = nullptr;
  int count = 0;
  png_get_text(job.png, job.info, &text, &count);
  for (int i = 0; i < count; ++i) {
    for (int k = 0; k < 4; ++k) {
      if (text[i].key != nullptr && text[i].text != nullptr &&
          std::strcmp(text[i].key, kTextKeys[k]) == 0) {
        char* end = nullptr;
        const double v = std::strtod(text[i].text, &end);
        if (end != text[i].text && std::isfinite(v)) {
          job.text_value[k] = v;
          job.has_text[k] = true;
        }
      }
    }
  }
  return true;
}

struct PngReadCleanup {
  PngJob& job;
  ~PngReadCleanup() {
    if (job.png != nullptr) png_destroy_read_struct(&job.png, &job.info, nullptr);
    if (job.file != nullptr) std::fclose(job.file);
  }
};

std::string color_name(int color_type) {
  switch (color_type) {
    case PNG_COLOR_TYPE_GRAY_ALPHA: return "grayscale with alpha";
    case PNG_COLOR_TYPE_RGB: return "RGB";
    case PNG_COLOR_TYPE_RGB_ALPHA: return "RGBA";
    case PNG_COLOR_TYPE_PALETTE: return "palette (indexed colour)";
    default: return "colour type " + std::to_string(color_type);
  }
}

}  // namespace

namespace detail {

Raster read_png_raster(const std::filesystem::path& path) {
  const std::string where = path.string();
  PngJob job;
  PngReadCleanup cleanup{job};
  job.file = std::fopen(where.c_str(), "rb");
  if (job.file == nullptr) throw HeightmapError(where + ": cannot open file");
  job.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &job, on_png_error, on_png_warning);
  if (job.png == nullptr) throw HeightmapError(where + ": cannot start the PNG reader");
  job.info = png_create_info_struct(job.png);
  if (job.info == nullptr) throw HeightmapError(where + ": cannot start the PNG reader");
  if (!read_header(job)) {
    throw HeightmapError(where + ": not a readable PNG (corrupt or truncated header): " + job.message);
  }

  if (job.color_type != PNG_COLOR_TYPE_GRAY) {
    throw HeightmapError(where + ": PNG is " + color_name(job.color_type) +
                         "; a heightmap must be single-channel grayscale (8 or 16 bit)");
  }
  if (job.bit_depth != 8 && job.bit_depth != 16) {
    throw HeightmapError(where + ": unsupported bit depth " + std::to_string(job.bit_depth) +
                         " of a grayscale PNG; use 8 or 16 bit");
  }
  const std::size_t width = job.width, height = job.height;
  if (width * height > kMaxSamples) {
    throw HeightmapError(where + ": image of " + std::to_string(width) + " x " +
                         std::to_string(height) + " samples is too large");
  }
  const std::size_t bytes_per_sample = job.bit_depth == 16 ? 2 : 1;
  std::vector<png_byte> bytes(width * height * bytes_per_sample);
  std::vector<png_bytep> rows(height);
  for (std::size_t r = 0; r < height; ++r) rows[r] = bytes.data() + r * width * bytes_per_sample;
  if (!read_pixels(job, rows.data())) {
    throw HeightmapError(where + ": corrupt PNG data: " + job.message);
  }

  Raster raster;
  raster.width = width;
  raster.height = height;
  raster.max_value = job.bit_depth == 16 ? 65535.0 : 255.0;
  raster.format = std::to_string(job.bit_depth) + "-bit grayscale PNG";
  raster.samples.resize(width * height);
  for (std::size_t i = 0; i < width * height; ++i) {
    raster.samples[i] = bytes_per_sample == 2
                            ? static_cast<double>((bytes[2 * i] << 8) | bytes[2 * i + 1])
                            : static_cast<double>(bytes[i]);
  }
  if (job.has_text[0]) raster.size_x = job.text_value[0];
  if (job.has_text[1]) raster.size_y = job.text_value[1];
  if (job.has_text[2]) raster.z_min = job.text_value[2];
  if (job.has_text[3]) raster.z_max = job.text_value[3];
  return raster;
}

}  // namespace detail

namespace {

struct PngWriteJob {
  std::FILE* file = nullptr;
  png_structp png = nullptr;
  png_infop info = nullptr;
  char message[256] = {};
};

void on_png_write_error(png_structp png, png_const_charp msg) {
  auto* job = static_cast<PngWriteJob*>(png_get_error_ptr(png));
  std::snprintf(job->message, sizeof job->message, "%s", msg);
  png_longjmp(png, 1);
}

bool write_png(PngWriteJob& job, png_uint_32 width, png_uint_32 height, png_bytepp rows,
               png_textp text, int text_count) {
  if (setjmp(png_jmpbuf(job.png))) return false;
  png_init_io(job.png, job.file);
  png_set_IHDR(job.png, job.info, width, height, 16, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_text(job.png, job.info, text, text_count);
  png_write_info(job.png, job.info);
  png_write_image(job.png, rows);
  png_write_end(job.png, nullptr);
  return true;
}

}  // namespace

HeightRange save_heightmap_png(const Heightmap& map, const std::filesystem::path& path) {
  const std::string where = path.string();
  validate_heightmap(map, where);
  const auto [lo, hi] = std::minmax_element(map.heights.begin(), map.heights.end());
  HeightRange range{*lo, *hi};
  if (!(range.z_max > range.z_min)) range.z_max = range.z_min + 1.0;
  const double span = range.z_max - range.z_min;

  // Big-endian 16-bit samples, image row 0 = north edge = last Heightmap row.
  std::vector<png_byte> bytes(map.rows * map.cols * 2);
  std::vector<png_bytep> rows(map.rows);
  for (std::size_t r = 0; r < map.rows; ++r) {
    png_bytep out = bytes.data() + r * map.cols * 2;
    rows[r] = out;
    const std::size_t src_row = map.rows - 1 - r;
    for (std::size_t c = 0; c < map.cols; ++c) {
      const double q = std::round((map.at(src_row, c) - range.z_min) / span * 65535.0);
      const auto v = static_cast<unsigned>(std::clamp(q, 0.0, 65535.0));
      out[2 * c] = static_cast<png_byte>(v >> 8);
      out[2 * c + 1] = static_cast<png_byte>(v & 0xffu);
    }
  }
  char values[4][32];
  const double numbers[4] = {map.size_x, map.size_y, range.z_min, range.z_max};
  png_text text[4] = {};
  for (int k = 0; k < 4; ++k) {
    std::snprintf(values[k], sizeof values[k], "%.17g", numbers[k]);
    text[k].compression = PNG_TEXT_COMPRESSION_NONE;
    text[k].key = const_cast<char*>(kTextKeys[k]);
    text[k].text = values[k];
  }

  PngWriteJob job;
  job.file = std::fopen(where.c_str(), "wb");
  if (job.file == nullptr) throw HeightmapError(where + ": cannot open file for writing");
  job.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &job, on_png_write_error,
                                    on_png_warning);
  if (job.png != nullptr) job.info = png_create_info_struct(job.png);
  const bool ok = job.info != nullptr &&
                  write_png(job, static_cast<png_uint_32>(map.cols),
                            static_cast<png_uint_32>(map.rows), rows.data(), text, 4);
  png_destroy_write_struct(&job.png, &job.info);
  const bool closed = std::fclose(job.file) == 0;
  if (!ok) throw HeightmapError(where + ": cannot write PNG: " + job.message);
  if (!closed) throw HeightmapError(where + ": cannot write PNG: error closing the file");
  return range;
}

}  // namespace mechsim::physics
