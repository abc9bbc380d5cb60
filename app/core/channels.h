// Channel images: decoded through OpenImageIO, checked before a pixel is
// read, and kept as textures by path.
#pragma once
#include <map>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/gl.h"
#include "core/image.h"

namespace rm {

// The largest channel image read, checked in its header before any pixel is:
// the largest texture llvmpipe takes, and more channels than any format uses.
constexpr int kMaxImageSide = 16384;
constexpr int kMaxImageChannels = 64;

// Decodes an image file (a regular file) into RGBA; returns nullopt and sets
// *error on failure. No GL needed.
std::optional<Image> load_channel_image(const std::filesystem::path& path, std::string* error);

// The textures of channel images, by path: each file is read once and shared
// by every pass that names it, mipmapped (Shadertoy's default filter needs
// the levels), right side up as on Shadertoy.
class ImageTextures {
 public:
  struct Entry {
    gl::Texture texture;
    glm::vec3 resolution{0.0f};
  };
  // The texture of `path`, read now if it was not before; nullptr with
  // *error ("why") if the file cannot be read as an image.
  const Entry* get(const std::filesystem::path& path, std::string* error);
  const Entry* find(const std::filesystem::path& path) const;  // nullptr if not read
  // Frees the textures of every path not in `used`.
  void keep_only(const std::vector<std::filesystem::path>& used);

 private:
  std::map<std::filesystem::path, Entry> entries_;
};

}  // namespace rm
