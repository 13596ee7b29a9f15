// libpng reports errors by longjmp: the setjmp sits in a function that owns no object with a
// destructor, so the jump skips no C++ cleanup.
#include "physics/image_png.hpp"

#include <png.h>

#include <cstdio>
#include <stdexcept>
#include <string>

namespace mechsim::physics {
namespace {

struct Job {
  std::FILE* file = nullptr;
  png_structp png = nullptr;
  png_infop info = nullptr;
  char message[256] = {};
};

void on_error(png_structp png, png_const_charp msg) {
  auto* job = static_cast<Job*>(png_get_error_ptr(png));
  std::snprintf(job->message, sizeof job->message, "%s", msg);
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

bool write(Job& job, png_uint_32 width, png_uint_32 height, png_bytepp rows) {
  if (setjmp(png_jmpbuf(job.png))) return false;
  png_init_io(job.png, job.file);
  png_set_IHDR(job.png, job.info, width, height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(job.png, 3);  // frames are many and large: speed over size
  png_write_info(job.png, job.info);
  png_write_image(job.png, rows);
  png_write_end(job.png, nullptr);
  return true;
}

}  // namespace

void save_rgb_png(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& rgb) {
  if (width <= 0 || height <= 0 || rgb.size() != static_cast<std::size_t>(width) * height * 3)
    throw std::invalid_argument(path.string() + ": an RGB picture needs width * height * 3 bytes");
  Job job;
  job.file = std::fopen(path.c_str(), "wb");
  if (job.file == nullptr) throw std::runtime_error(path.string() + ": cannot be written");
  job.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &job, on_error, on_warning);
  job.info = job.png != nullptr ? png_create_info_struct(job.png) : nullptr;
  std::vector<png_bytep> rows(static_cast<std::size_t>(height));
  for (int r = 0; r < height; ++r)
    rows[static_cast<std::size_t>(r)] = const_cast<png_bytep>(rgb.data() + static_cast<std::size_t>(r) * width * 3);
  const bool ok = job.info != nullptr && write(job, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), rows.data());
  png_destroy_write_struct(&job.png, &job.info);
  const bool closed = std::fclose(job.file) == 0;
  if (!ok || !closed)
    throw std::runtime_error(path.string() + ": writing the PNG failed" + (job.message[0] ? std::string(": ") + job.message : ""));
}

}  // namespace mechsim::physics
