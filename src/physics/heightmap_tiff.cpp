// TIFF heightmaps through libtiff. Errors and warnings go to per-file handlers (TIFFOpenExt),
// never to libtiff's process-global ones. GeoTIFF tags are read as libtiff's anonymous fields.

#include <tiffio.h>

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "physics/heightmap_io.hpp"
#include "physics/heightmap_raster.hpp"
#include "physics/heightmap_sample.hpp"

namespace mechsim::physics {
namespace {

constexpr ttag_t kModelPixelScaleTag = 33550;  // GeoTIFF: (scale x, scale y, scale z)
constexpr ttag_t kModelTiepointTag = 33922;    // GeoTIFF: (i, j, k, x, y, z) per tie point
constexpr ttag_t kGeoKeyDirectoryTag = 34735;  // GeoTIFF: key directory (SHORT array)
constexpr ttag_t kGdalNoDataTag = 42113;       // GDAL: no-data value as ASCII
constexpr std::uint16_t kGTRasterTypeGeoKey = 1025;
constexpr std::uint16_t kRasterPixelIsPoint = 2;

int on_tiff_error(TIFF*, void* user, const char* module, const char* fmt, va_list ap) {
  auto* message = static_cast<std::string*>(user);
  char text[512];
  std::vsnprintf(text, sizeof text, fmt, ap);
  if (!message->empty()) *message += "; ";
  if (module != nullptr && *module != '\0') *message += std::string(module) + ": ";
  *message += text;
  return 1;  // handled: libtiff's global handler stays silent
}

int on_tiff_warning(TIFF*, void*, const char*, const char*, va_list) { return 1; }

// Opens with per-handle handlers collecting errors into *message.
TIFF* open_tiff(const std::string& path, const char* mode, std::string* message) {
  TIFFOpenOptions* options = TIFFOpenOptionsAlloc();
  TIFFOpenOptionsSetErrorHandlerExtR(options, on_tiff_error, message);
  TIFFOpenOptionsSetWarningHandlerExtR(options, on_tiff_warning, nullptr);
  TIFF* tif = TIFFOpenExt(path.c_str(), mode, options);
  TIFFOpenOptionsFree(options);
  return tif;
}

struct TiffCloser {
  TIFF* tif;
  ~TiffCloser() {
    if (tif != nullptr) TIFFClose(tif);
  }
};

// Values of a custom (counted) tag of the given TIFF type, empty when absent or of another type.
template <typename T>
std::vector<T> get_array(TIFF* tif, ttag_t tag, TIFFDataType type) {
  const TIFFField* field = TIFFFindField(tif, tag, TIFF_ANY);
  if (field == nullptr || TIFFFieldDataType(field) != type || !TIFFFieldPassCount(field)) {
    return {};
  }
  T* data = nullptr;
  std::uint32_t count = 0;
  if (TIFFFieldReadCount(field) == TIFF_VARIABLE2) {
    if (TIFFGetField(tif, tag, &count, &data) != 1) return {};
  } else {
    std::uint16_t count16 = 0;
    if (TIFFGetField(tif, tag, &count16, &data) != 1) return {};
    count = count16;
  }
  if (data == nullptr) return {};
  return std::vector<T>(data, data + count);
}

std::string sample_kind(std::uint16_t format, std::uint16_t bits) {
  const char* name = format == SAMPLEFORMAT_IEEEFP ? "float"
                     : format == SAMPLEFORMAT_INT  ? "signed integer"
                     : format == SAMPLEFORMAT_UINT ? "unsigned integer"
                                                   : "complex or unknown";
  return std::to_string(bits) + "-bit " + name;
}

double decode(const unsigned char* p, std::uint16_t format, std::uint16_t bits) {
  if (format == SAMPLEFORMAT_IEEEFP && bits == 32) {
    float f;
    std::memcpy(&f, p, sizeof f);
    return f;
  }
  if (format == SAMPLEFORMAT_IEEEFP && bits == 64) {
    double d;
    std::memcpy(&d, p, sizeof d);
    return d;
  }
  if (bits == 16) {
    std::uint16_t v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  return *p;
}

}  // namespace

namespace detail {

Raster read_tiff_raster(const std::filesystem::path& path) {
  const std::string where = path.string();
  std::string message;
  TIFF* tif = open_tiff(where, "r", &message);
  if (tif == nullptr) throw HeightmapError(where + ": not a readable TIFF: " + message);
  TiffCloser closer{tif};
  auto fail = [&](const std::string& what) -> HeightmapError {
    return HeightmapError(where + ": " + what + (message.empty() ? "" : " (" + message + ")"));
  };

  std::uint32_t width = 0, height = 0;
  std::uint16_t bits = 0, channels = 0, format = 0, planar = 0;
  TIFFGetField(tif, TIFFTAG_IMAGEWIDTH, &width);
  TIFFGetField(tif, TIFFTAG_IMAGELENGTH, &height);
  TIFFGetFieldDefaulted(tif, TIFFTAG_BITSPERSAMPLE, &bits);
  TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLESPERPIXEL, &channels);
  TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLEFORMAT, &format);
  TIFFGetFieldDefaulted(tif, TIFFTAG_PLANARCONFIG, &planar);
  if (channels != 1) {
    throw fail("TIFF has " + std::to_string(channels) +
               " samples per pixel; a heightmap must be single-channel");
  }
  const bool is_float = format == SAMPLEFORMAT_IEEEFP && (bits == 32 || bits == 64);
  const bool is_uint = format == SAMPLEFORMAT_UINT && (bits == 8 || bits == 16);
  if (!is_float && !is_uint) {
    throw fail("unsupported TIFF sample format " + sample_kind(format, bits) +
               "; use 32/64-bit float or 8/16-bit unsigned integer");
  }
  if (std::size_t{width} * height > kMaxSamples) {
    throw fail("image of " + std::to_string(width) + " x " + std::to_string(height) +
               " samples is too large");
  }

  Raster raster;
  raster.width = width;
  raster.height = height;
  raster.is_float = is_float;
  raster.max_value = is_uint ? (bits == 16 ? 65535.0 : 255.0) : 0.0;
  raster.format = sample_kind(format, bits) + " TIFF";
  raster.samples.resize(std::size_t{width} * height);
  const std::size_t bytes = bits / 8;

  if (TIFFIsTiled(tif)) {
    std::uint32_t tile_w = 0, tile_h = 0;
    TIFFGetField(tif, TIFFTAG_TILEWIDTH, &tile_w);
    TIFFGetField(tif, TIFFTAG_TILELENGTH, &tile_h);
    const tmsize_t tile_size = TIFFTileSize(tif);
    if (tile_w == 0 || tile_h == 0 || tile_size <= 0) throw fail("corrupt TIFF tile layout");
    std::vector<unsigned char> tile(static_cast<std::size_t>(tile_size));
    for (std::uint32_t y0 = 0; y0 < height; y0 += tile_h) {
      for (std::uint32_t x0 = 0; x0 < width; x0 += tile_w) {
        if (TIFFReadTile(tif, tile.data(), x0, y0, 0, 0) < 0) throw fail("corrupt TIFF tile");
        for (std::uint32_t y = y0; y < std::min(height, y0 + tile_h); ++y) {
          for (std::uint32_t x = x0; x < std::min(width, x0 + tile_w); ++x) {
            const std::size_t at = (std::size_t{y - y0} * tile_w + (x - x0)) * bytes;
            raster.samples[std::size_t{y} * width + x] = decode(&tile[at], format, bits);
          }
        }
      }
    }
  } else {
    const tmsize_t line_size = TIFFScanlineSize(tif);
    if (line_size < static_cast<tmsize_t>(width * bytes)) throw fail("corrupt TIFF row layout");
    std::vector<unsigned char> line(static_cast<std::size_t>(line_size));
    for (std::uint32_t y = 0; y < height; ++y) {
      if (TIFFReadScanline(tif, line.data(), y, 0) < 0) {
        throw fail("corrupt TIFF data in image row " + std::to_string(y));
      }
      for (std::uint32_t x = 0; x < width; ++x) {
        raster.samples[std::size_t{y} * width + x] = decode(&line[x * bytes], format, bits);
      }
    }
  }

  const auto scale = get_array<double>(tif, kModelPixelScaleTag, TIFF_DOUBLE);
  if (scale.size() >= 2) {
    if (!(scale[0] > 0.0 && scale[1] > 0.0 && std::isfinite(scale[0]) &&
          std::isfinite(scale[1]))) {
      throw fail("GeoTIFF pixel scale (tag 33550) " + std::to_string(scale[0]) + ", " +
                 std::to_string(scale[1]) + " is not positive");
    }
    bool pixel_is_point = false;
    const auto keys = get_array<std::uint16_t>(tif, kGeoKeyDirectoryTag, TIFF_SHORT);
    for (std::size_t k = 4; k + 3 < keys.size(); k += 4) {
      if (keys[k] == kGTRasterTypeGeoKey && keys[k + 1] == 0) {
        pixel_is_point = keys[k + 3] == kRasterPixelIsPoint;
      }
    }
    const double nx = pixel_is_point ? width - 1.0 : width;
    const double ny = pixel_is_point ? height - 1.0 : height;
    raster.size_x = scale[0] * nx;
    raster.size_y = scale[1] * ny;
  }
  const TIFFField* nodata_field = TIFFFindField(tif, kGdalNoDataTag, TIFF_ANY);
  if (nodata_field != nullptr && TIFFFieldDataType(nodata_field) == TIFF_ASCII) {
    const char* text = nullptr;
    std::uint32_t count = 0;
    const int got = TIFFFieldPassCount(nodata_field) ? TIFFGetField(tif, kGdalNoDataTag, &count, &text)
                                                     : TIFFGetField(tif, kGdalNoDataTag, &text);
    if (got == 1 && text != nullptr) {
      char* end = nullptr;
      const double v = std::strtod(text, &end);
      if (end != text && std::isfinite(v)) raster.nodata = v;
    }
  }
  return raster;
}

}  // namespace detail

void save_heightmap_tiff(const Heightmap& map, const std::filesystem::path& path) {
  const std::string where = path.string();
  validate_heightmap(map, where);
  std::string message;
  TIFF* tif = open_tiff(where, "w", &message);
  if (tif == nullptr) throw HeightmapError(where + ": cannot open TIFF for writing: " + message);
  static const TIFFFieldInfo kGeoFields[] = {
      {kModelPixelScaleTag, -1, -1, TIFF_DOUBLE, FIELD_CUSTOM, 1, 1,
       const_cast<char*>("ModelPixelScaleTag")},
      {kModelTiepointTag, -1, -1, TIFF_DOUBLE, FIELD_CUSTOM, 1, 1,
       const_cast<char*>("ModelTiepointTag")},
  };
  bool ok = TIFFMergeFieldInfo(tif, kGeoFields, 2) == 0;
  const auto width = static_cast<std::uint32_t>(map.cols);
  const auto height = static_cast<std::uint32_t>(map.rows);
  ok = ok && TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, width) == 1 &&
       TIFFSetField(tif, TIFFTAG_IMAGELENGTH, height) == 1 &&
       TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, 32) == 1 &&
       TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, 1) == 1 &&
       TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, SAMPLEFORMAT_IEEEFP) == 1 &&
       TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK) == 1 &&
       TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG) == 1 &&
       TIFFSetField(tif, TIFFTAG_COMPRESSION, COMPRESSION_NONE) == 1 &&
       TIFFSetField(tif, TIFFTAG_ROWSPERSTRIP, TIFFDefaultStripSize(tif, 0)) == 1;
  // Pixel-is-area scale: each sample stands for size / samples of ground.
  const double scale[3] = {map.size_x / static_cast<double>(map.cols),
                           map.size_y / static_cast<double>(map.rows), 0.0};
  const double tiepoint[6] = {0.0, 0.0, 0.0, -0.5 * map.size_x, 0.5 * map.size_y, 0.0};
  ok = ok && TIFFSetField(tif, kModelPixelScaleTag, 3, scale) == 1 &&
       TIFFSetField(tif, kModelTiepointTag, 6, tiepoint) == 1;
  std::vector<float> line(map.cols);
  for (std::uint32_t y = 0; ok && y < height; ++y) {
    const std::size_t src_row = map.rows - 1 - y;  // image row 0 = north edge
    for (std::size_t c = 0; c < map.cols; ++c) line[c] = map.at(src_row, c);
    ok = TIFFWriteScanline(tif, line.data(), y, 0) == 1;
  }
  TIFFClose(tif);
  if (!ok || !message.empty()) {
    throw HeightmapError(where + ": cannot write TIFF" + (message.empty() ? "" : ": " + message));
  }
}

}  // namespace mechsim::physics
