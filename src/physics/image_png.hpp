#pragma once
// 8-bit RGB pictures as PNG (camera frames, contact sheets): libpng lives in physics/, the one
// layer that links it.

#include <cstdint>
#include <filesystem>
#include <vector>

namespace mechsim::physics {

// Writes width x height RGB pixels (rows from the top, 3 bytes each). Throws std::runtime_error
// naming the file when it cannot be written, std::invalid_argument for a wrong buffer size.
void save_rgb_png(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& rgb);

}  // namespace mechsim::physics
