#include "heightmap_image_util.hpp"

#include <png.h>
#include <tiffio.h>

#include <unistd.h>

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace mechsim::physics::test {

ScratchDir::ScratchDir(const std::string& name)
    : path_(std::filesystem::temp_directory_path() / ("mechsim_terrain_" + name + "_" + std::to_string(::getpid()))) {
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

ScratchDir::~ScratchDir() {
  std::error_code ignored;  // a destructor must not throw; a leftover folder is not a test failure
  std::filesystem::remove_all(path_, ignored);
}

void write_gray_png(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                    int bits, const std::vector<std::uint16_t>& values) {
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  image.width = width;
  image.height = height;
  // The simplified API writes linear 16-bit and sRGB 8-bit samples unchanged.
  image.format = bits == 16 ? PNG_FORMAT_LINEAR_Y : PNG_FORMAT_GRAY;
  int ok = 0;
  if (bits == 16) {
    ok = png_image_write_to_file(&image, path.c_str(), 0, values.data(), 0, nullptr);
  } else {
    std::vector<std::uint8_t> bytes(values.begin(), values.end());
    ok = png_image_write_to_file(&image, path.c_str(), 0, bytes.data(), 0, nullptr);
  }
  if (ok == 0) throw std::runtime_error("test PNG write failed: " + std::string(image.message));
}

namespace {

// libpng's classic writer reports errors by longjmp; this function owns nothing with a
// destructor, so the jump skips no cleanup.
bool write_low_depth(std::FILE* file, std::uint32_t width, std::uint32_t height, int bits,
                     png_bytepp rows) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png != nullptr ? png_create_info_struct(png) : nullptr;
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, file);
  png_set_IHDR(png, info, width, height, bits, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

void write_low_depth_png(const std::filesystem::path& path, std::uint32_t width,
                         std::uint32_t height, int bits) {
  std::vector<png_byte> bytes(std::size_t{width} * height, 0);  // a byte per row is plenty
  std::vector<png_bytep> rows(height);
  for (std::uint32_t r = 0; r < height; ++r) rows[r] = bytes.data() + std::size_t{r} * width;
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr) throw std::runtime_error("test PNG open failed");
  const bool ok = write_low_depth(file, width, height, bits, rows.data());
  std::fclose(file);
  if (!ok) throw std::runtime_error("test PNG write failed");
}

void write_rgb_png(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height) {
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  image.width = width;
  image.height = height;
  image.format = PNG_FORMAT_RGB;
  std::vector<std::uint8_t> bytes(std::size_t{width} * height * 3, 100);
  if (png_image_write_to_file(&image, path.c_str(), 0, bytes.data(), 0, nullptr) == 0) {
    throw std::runtime_error("test PNG write failed: " + std::string(image.message));
  }
}

namespace {

void put(std::vector<unsigned char>& out, std::size_t index, const TiffSpec& spec, double v) {
  unsigned char* p = out.data() + index * (spec.bits / 8);
  if (spec.sample_format == 3 && spec.bits == 32) {
    const auto f = static_cast<float>(v);
    std::memcpy(p, &f, 4);
  } else if (spec.sample_format == 3 && spec.bits == 64) {
    std::memcpy(p, &v, 8);
  } else if (spec.bits == 16) {
    const auto u = static_cast<std::uint16_t>(static_cast<std::int64_t>(v) & 0xffff);
    std::memcpy(p, &u, 2);
  } else {
    *p = static_cast<unsigned char>(static_cast<std::int64_t>(v) & 0xff);
  }
}

}  // namespace

void write_tiff(const std::filesystem::path& path, const TiffSpec& spec,
                const std::vector<double>& values) {
  TIFF* tif = TIFFOpen(path.c_str(), "w");
  if (tif == nullptr) throw std::runtime_error("test TIFF open failed");
  static const TIFFFieldInfo kFields[] = {
      {33550, -1, -1, TIFF_DOUBLE, FIELD_CUSTOM, 1, 1, const_cast<char*>("ModelPixelScaleTag")},
      {34735, -1, -1, TIFF_SHORT, FIELD_CUSTOM, 1, 1, const_cast<char*>("GeoKeyDirectoryTag")},
  };
  TIFFMergeFieldInfo(tif, kFields, 2);
  TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, spec.width);
  TIFFSetField(tif, TIFFTAG_IMAGELENGTH, spec.height);
  TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, spec.bits);
  TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, spec.channels);
  TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, spec.sample_format);
  TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, spec.channels == 3 ? PHOTOMETRIC_RGB : PHOTOMETRIC_MINISBLACK);
  TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
  if (spec.pixel_scale) {
    TIFFSetField(tif, 33550, static_cast<int>(spec.pixel_scale->size()), spec.pixel_scale->data());
  }
  if (spec.pixel_is_point) {
    // Header (version 1, revision 1.0, one key), then GTRasterTypeGeoKey = RasterPixelIsPoint.
    static const std::uint16_t kKeys[8] = {1, 1, 0, 1, 1025, 0, 1, 2};
    TIFFSetField(tif, 34735, 8, kKeys);
  }
  const std::size_t bytes = spec.bits / 8;
  if (spec.tiled) {
    const std::uint32_t t = 16;
    TIFFSetField(tif, TIFFTAG_TILEWIDTH, t);
    TIFFSetField(tif, TIFFTAG_TILELENGTH, t);
    std::vector<unsigned char> tile(std::size_t{t} * t * bytes * spec.channels);
    for (std::uint32_t y0 = 0; y0 < spec.height; y0 += t) {
      for (std::uint32_t x0 = 0; x0 < spec.width; x0 += t) {
        std::fill(tile.begin(), tile.end(), 0);
        for (std::uint32_t y = y0; y < std::min(spec.height, y0 + t); ++y) {
          for (std::uint32_t x = x0; x < std::min(spec.width, x0 + t); ++x) {
            put(tile, std::size_t{y - y0} * t + (x - x0), spec, values[std::size_t{y} * spec.width + x]);
          }
        }
        TIFFWriteTile(tif, tile.data(), x0, y0, 0, 0);
      }
    }
  } else {
    TIFFSetField(tif, TIFFTAG_ROWSPERSTRIP, 2);
    std::vector<unsigned char> line(std::size_t{spec.width} * bytes * spec.channels);
    for (std::uint32_t y = 0; y < spec.height; ++y) {
      for (std::uint32_t x = 0; x < spec.width * spec.channels; ++x) {
        put(line, x, spec, values[(std::size_t{y} * spec.width + x / spec.channels)]);
      }
      TIFFWriteScanline(tif, line.data(), y, 0);
    }
  }
  TIFFClose(tif);
}

}  // namespace mechsim::physics::test
