// What a pass names for one of its iChannels, in its own source:
//   #pragma channel0 "rock.png"                 an image (mipmapped, repeat)
//   #pragma channel1 "buffer_a.frag"            a buffer pass (.frag/.glsl)
//   #pragma channel2 self                       this pass's previous frame
//   #pragma channel3 keyboard                   the 256x3 keyboard texture
//   #pragma channel3 black                      nothing, on purpose: transparent black, no warning
//   #pragma channel0 "sky.png" cube             a cube map: six faces, a cross or a panorama
//   #pragma channel0 "cube_a.frag" cube         a Cube A pass (mainCubemap)
//   #pragma channel1 "noise.bin" volume         a volume (sampler3D)
// followed by Shadertoy's sampler settings where the defaults do not fit:
//   filter=nearest|linear|mipmap  wrap=clamp|repeat  vflip=true|false
// and, for a Cube A pass, its face size: size=N (1024, as on Shadertoy);
// for a flat buffer pass (or `self`), a size of its own instead of the
// picture's: size=WxH, or scale=F, a share of the picture's per axis.
// No GL here: the core's graph (core/frame_graph.h) turns specs into textures.
#pragma once
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rm {

struct Sampler {
  enum class Filter { Nearest, Linear, Mipmap };
  enum class Wrap { Clamp, Repeat };
  Filter filter = Filter::Mipmap;
  Wrap wrap = Wrap::Repeat;
  // true: a flat image's first row is the picture's top (false: its
  // bottom). Buffers are read as they were drawn, and cube faces as GL lays
  // them out, whatever it says.
  bool vflip = true;
  bool operator==(const Sampler&) const = default;
};

// A flat buffer pass's size where it is not the picture's: fixed, or a
// share of the picture's per axis. Spelled `size=WxH` or `scale=F` in a
// #pragma channelN, and as glslViewer's comment after a buffer's
// declaration (`uniform sampler2D u_buffer0; // 512x512`, or `// 0.5`).
struct BufferSize {
  static constexpr int kMaxSide = 4096;  // as a cube face's: two RGBA32F targets of 4096x4096 hold 512 MiB
  int width = 0, height = 0;  // > 0: fixed
  double scale = 0;           // else, > 0: this share of the picture's; else the picture's size
  bool given() const { return width > 0 || scale > 0; }
  bool operator==(const BufferSize&) const = default;
};
// Reads `WxH` (each from 1 to kMaxSide) when `fixed`, else a share `F`
// (0 < F <= 1). nullopt with *error set on anything else.
std::optional<BufferSize> parse_buffer_size(std::string_view text, bool fixed, std::string* error);
std::string to_string(const BufferSize& size);  // "size=512x256", "scale=0.5"; "" when not given

struct ChannelSpec {
  enum class Kind { None, Image, Pass, Self, Keyboard, Black };
  // What the shader samples: the prelude declares sampler2D, samplerCube or sampler3D.
  enum class Shape { Flat, Cube, Volume };
  static constexpr int kDefaultCubeSize = 1024;
  Kind kind = Kind::None;
  Shape shape = Shape::Flat;
  std::filesystem::path path;  // Image and Pass: absolute
  Sampler sampler;
  int cube_size = 0;  // a Cube A pass's face size when the pragma gives one; 0: the default
  // A sampler of the shader's own that the channel binds too, besides
  // iChannelN and u_texN: glslViewer's u_buffer0 (core/glslviewer_passes.h).
  std::string sampler_name;
  BufferSize buffer_size;  // a flat pass's own size, when the spec gives one
  bool operator==(const ChannelSpec&) const = default;
};

// Shadertoy's default sampler for each kind of input.
Sampler default_sampler(ChannelSpec::Kind kind, ChannelSpec::Shape shape = ChannelSpec::Shape::Flat);

// N for the samplers channel N binds, iChannelN and glslViewer's u_texN
// (0-3); -1 for any other name.
int channel_of_sampler(std::string_view name);

// Whether a named file is a shader (a buffer pass) rather than an image.
bool is_shader_file(const std::filesystem::path& path);

// Reads what follows "#pragma channelN": a quoted file (relative to
// `relative_to`), `self`, `keyboard` or `black`, then sampler settings. nullopt with
// *error set on anything else.
std::optional<ChannelSpec> parse_channel_spec(std::string_view text, const std::filesystem::path& relative_to,
                                              std::string* error);

// The spelling parse_channel_spec reads, for `import` to write. `file` is
// written as given (relative to the pass that names it).
std::string channel_spec_text(const ChannelSpec& spec, const std::string& file);

// The face files of a cube map named by its first: NAME.ext holds +X and
// NAME_1.ext .. NAME_5.ext the rest, as shadertoy.com names its cube map
// media. Empty if NAME_1.ext does not exist; fewer than six if some are missing.
std::vector<std::filesystem::path> cube_face_files(const std::filesystem::path& first,
                                                   const std::function<bool(const std::filesystem::path&)>& exists);

const char* to_string(ChannelSpec::Kind kind);
const char* glsl_sampler_type(ChannelSpec::Shape shape);  // "sampler2D", "samplerCube", "sampler3D"

}  // namespace rm
