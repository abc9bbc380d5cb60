// Channels: the four iChannel textures. Images load through OpenImageIO; an
// unset channel is a 1x1 transparent black texture with resolution 0, as on
// Shadertoy, never uninitialised memory.
#pragma once
#include <array>
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

class Channels {
 public:
  static constexpr int kCount = 4;
  using Paths = std::array<std::filesystem::path, kCount>;
  Channels();  // needs a current GL context
  void set(int index, const Image& image);  // sampled right side up, as on Shadertoy
  void clear(int index);                    // back to 1x1 transparent black, resolution 0

  // Shows the scene's default images (#pragma channelN) in the channels the
  // command line left empty, loading only those that changed since the last
  // call. On an unreadable image it sets *error ("iChannel1 'PATH': why"),
  // leaves that channel as it was and returns false.
  bool use_scene_defaults(const Paths& scene_defaults, const Paths& from_command_line, std::string* error);
  GLuint texture(int index) const { return textures_[static_cast<size_t>(index)].get(); }
  glm::vec3 resolution(int index) const { return resolution_[static_cast<size_t>(index)]; }

 private:
  std::array<gl::Texture, kCount> textures_;
  std::array<glm::vec3, kCount> resolution_{};
  Paths scene_defaults_;  // what use_scene_defaults loaded
};

}  // namespace rm
