// Image files through OpenImageIO: PNG for 8-bit display images, EXR for linear radiance.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace app {

// RGBA8 top-down; metadata lands in the file's attributes (PNG text chunks, EXR header).
void writeImage8(const std::string& path, int width, int height, const std::vector<uint8_t>& rgba,
                 const std::map<std::string, std::string>& metadata = {});
// RGBA32F top-down, written as half-float EXR.
void writeImageFloat(const std::string& path, int width, int height, const std::vector<float>& rgba,
                     const std::map<std::string, std::string>& metadata = {});
// Reads any image OpenImageIO reads as RGB float in [0,1] (display values); throws on failure.
std::vector<float> readImageRgb(const std::string& path, int& width, int& height);

}  // namespace app
