// Volumes on the CPU: what a sampler3D channel reads. Two layouts:
//  - shadertoy.com's .bin volumes: a 20-byte header (4 signature bytes, then
//    width, height and depth as little-endian uint32, channels as a byte,
//    a layout byte, and a uint16 format: 0 for 8-bit, 10 for 32-bit float),
//    then the texels, x fastest;
//  - any image OpenImageIO reads holding square slices stacked top to
//    bottom (a 32x1024 PNG is 32 slices of 32x32), slice 0 first.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace rm {

constexpr std::uintmax_t kMaxVolumeBytes = 256u << 20;

struct Volume {
  glm::ivec3 size{0};
  std::vector<float> rgba;  // x fastest, then y, then z
};

// A .bin file's bytes as a volume; nullopt with *error on anything else.
std::optional<Volume> parse_shadertoy_volume(const std::string& bytes, std::string* error);
std::optional<Volume> load_volume(const std::filesystem::path& path, std::string* error);

}  // namespace rm
