// Channel images: decoded through OpenImageIO, checked before a pixel is
// read, and kept as textures by path.
#pragma once
#include <map>
#include <filesystem>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "core/channel_spec.h"
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
// The same checks on the file and its header, reading no pixel: for the
// command line, before any GL work.
bool check_channel_image(const std::filesystem::path& path, std::string* error);

// The textures of channel files, by path and what they are read as: each
// is read once and shared by every pass that names it the same way. Flat
// images are mipmapped (Shadertoy's default filter needs the levels) and
// right side up unless vflip=false; cube maps come from core/cube_map.h and
// volumes from core/volume.h.
class ImageTextures {
 public:
  struct Entry {
    GLenum target = GL_TEXTURE_2D;
    gl::Texture texture;
    glm::vec3 resolution{0.0f};  // a cube map's face size, a volume's depth in z
    std::vector<std::filesystem::file_time_type> stamps;  // of its file (or six face files) when read
    std::string error;  // why not, where the file could not be read: then no texture
  };
  // The texture of `spec` (an Image spec), read now if it was not before or
  // if its file changed since (*reread is then set); nullptr with *error
  // ("why") if the file cannot be read as that.
  const Entry* get(const ChannelSpec& spec, std::string* error, bool* reread = nullptr);
  const Entry* find(const ChannelSpec& spec) const;  // nullptr if not read
  // Frees the textures of every spec not in `used`, and what was handed
  // over and not used.
  void keep_only(const std::vector<ChannelSpec>& used);

  // Reading on another thread, one whose GL context shares this one's
  // objects (the window's builder: a 4096x4096 noise PNG held the window
  // for 1.2 s). held() is what the textures were read from, and their
  // sizes; stale() says whether get() would read the file of `spec` now,
  // safe on any thread with a copy of held(); read() reads one as get()
  // would, and hand_over() gives what it read to the next get()s, which
  // take it where the files have not changed again: a texture, or why
  // there is none (a broken file is not read again on the graph's thread).
  using Key = std::tuple<std::filesystem::path, ChannelSpec::Shape, bool>;  // specs read as one texture
  static Key key_of(const ChannelSpec& spec);
  struct Held {
    std::vector<std::filesystem::file_time_type> stamps;
    glm::ivec3 size{0};  // as Entry::resolution
  };
  using HeldImages = std::map<Key, Held>;
  HeldImages held() const;
  static bool stale(const ChannelSpec& spec, const HeldImages& held);
  static Entry read(const ChannelSpec& spec);
  void hand_over(std::vector<std::pair<ChannelSpec, Entry>> read);

 private:
  std::map<Key, Entry> entries_;
  std::map<Key, Entry> handed_over_;
};

}  // namespace rm
