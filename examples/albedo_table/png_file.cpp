// png_file.cpp - the PNG encoder is stb_image_write (public domain,
// header-only; Debian: libstb-dev), whose implementation lives in this file.
#include "png_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#include "atomic_file.hpp"

namespace albedo {

void write_png(const std::string& path, const std::vector<float>& values, int rows, int columns, int scale)
{
    const int width = columns * scale, height = rows * scale;
    std::vector<std::uint8_t> pixels(std::size_t(width) * height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float v = std::clamp(values[(y / scale) * columns + x / scale], 0.0f, 1.0f);
            pixels[std::size_t(y) * width + x] = static_cast<std::uint8_t>(std::lround(255.0f * v));
        }
    write_atomically(path, [&](const std::string& temporary) {
        return stbi_write_png(temporary.c_str(), width, height, 1, pixels.data(), width) != 0;
    });
}

} // namespace albedo
