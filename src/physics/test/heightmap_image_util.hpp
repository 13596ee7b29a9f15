#pragma once
// Test helpers: write small heightmap images with libpng/libtiff directly (independent of
// mechsim's own writers) into a per-test temporary folder.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace mechsim::physics::test {

// A fresh empty folder under the system temp dir, unique per test and process (programs of
// several build folders run at once), removed when it goes out of scope.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name);
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  operator const std::filesystem::path&() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};
inline ScratchDir temp_dir(const std::string& name) { return ScratchDir(name); }

// Grayscale PNG, image order (row 0 first); bits 8 or 16 (values must fit).
void write_gray_png(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                    int bits, const std::vector<std::uint16_t>& values);

// Grayscale PNG of 1, 2 or 4 bits per sample, all zero (for the error path).
void write_low_depth_png(const std::filesystem::path& path, std::uint32_t width,
                         std::uint32_t height, int bits);

// RGB 8-bit PNG (for the error path).
void write_rgb_png(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height);

struct TiffSpec {
  std::uint32_t width = 0, height = 0;
  std::uint16_t bits = 32;           // 8, 16, 32 or 64
  std::uint16_t sample_format = 3;   // 1 uint, 2 int, 3 float
  std::uint16_t channels = 1;
  std::optional<std::vector<double>> pixel_scale;  // GeoTIFF tag 33550
  bool pixel_is_point = false;                     // writes a GeoKeyDirectory saying so
  bool tiled = false;                              // 16 x 16 tiles instead of strips
};

// TIFF with `values` in image order, converted to the spec's sample type.
void write_tiff(const std::filesystem::path& path, const TiffSpec& spec,
                const std::vector<double>& values);

}  // namespace mechsim::physics::test
