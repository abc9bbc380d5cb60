#include "core/volume.h"

#include <cstring>

#include "core/channels.h"
#include "core/files.h"

namespace rm {

namespace {

uint32_t le32(const std::string& b, size_t at) {
  return static_cast<uint32_t>(static_cast<unsigned char>(b[at])) |
         static_cast<uint32_t>(static_cast<unsigned char>(b[at + 1])) << 8 |
         static_cast<uint32_t>(static_cast<unsigned char>(b[at + 2])) << 16 |
         static_cast<uint32_t>(static_cast<unsigned char>(b[at + 3])) << 24;
}

}  // namespace

std::optional<Volume> parse_shadertoy_volume(const std::string& bytes, std::string* error) {
  constexpr size_t kHeader = 20;
  if (bytes.size() < kHeader) {
    *error = "is too short for a volume's header";
    return std::nullopt;
  }
  const glm::uvec3 size(le32(bytes, 4), le32(bytes, 8), le32(bytes, 12));
  const int channels = static_cast<unsigned char>(bytes[16]);
  const int format = static_cast<unsigned char>(bytes[18]) | static_cast<unsigned char>(bytes[19]) << 8;
  if (size.x < 1 || size.y < 1 || size.z < 1 || size.x > 2048 || size.y > 2048 || size.z > 2048 || channels < 1 ||
      channels > 4 || (format != 0 && format != 10)) {
    *error = "has a volume header that does not fit (" + std::to_string(size.x) + "x" + std::to_string(size.y) + "x" +
             std::to_string(size.z) + ", " + std::to_string(channels) + " channels, format " + std::to_string(format) +
             ")";
    return std::nullopt;
  }
  const size_t texels = static_cast<size_t>(size.x) * size.y * size.z;
  const size_t bytes_per = format == 0 ? 1 : 4;
  if (bytes.size() != kHeader + texels * channels * bytes_per) {
    *error = "holds " + std::to_string(bytes.size()) + " bytes; its header asks for " +
             std::to_string(kHeader + texels * channels * bytes_per);
    return std::nullopt;
  }
  Volume v;
  v.size = glm::ivec3(size);
  v.rgba.assign(texels * 4, 1.0f);
  const char* data = bytes.data() + kHeader;
  for (size_t i = 0; i < texels; ++i) {
    for (int c = 0; c < channels; ++c) {
      const size_t at = (i * channels + static_cast<size_t>(c)) * bytes_per;
      float value;
      if (format == 0) {
        value = static_cast<unsigned char>(data[at]) / 255.0f;
      } else {
        std::memcpy(&value, data + at, 4);
      }
      v.rgba[i * 4 + static_cast<size_t>(c)] = value;
    }
    if (channels == 1) v.rgba[i * 4 + 1] = v.rgba[i * 4 + 2] = v.rgba[i * 4];
  }
  return v;
}

std::optional<Volume> load_volume(const std::filesystem::path& path, std::string* error) {
  if (path.extension() == ".bin") {
    auto bytes = read_regular_file(path, kMaxVolumeBytes, "volumes", error);
    if (!bytes) return std::nullopt;
    return parse_shadertoy_volume(*bytes, error);
  }
  auto image = load_channel_image(path, error);
  if (!image) return std::nullopt;
  if (image->height % image->width != 0) {
    *error = "is " + std::to_string(image->width) + "x" + std::to_string(image->height) +
             "; a volume image stacks square slices top to bottom, so its height is a multiple of its width";
    return std::nullopt;
  }
  Volume v;
  v.size = glm::ivec3(image->width, image->width, image->height / image->width);
  v.rgba = std::move(image->rgba);  // slice after slice, each top row first
  return v;
}

}  // namespace rm
