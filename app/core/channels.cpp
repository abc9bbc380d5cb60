#include "core/channels.h"

#include <OpenImageIO/imageio.h>

#include "core/files.h"

namespace rm {

std::optional<Image> load_channel_image(const std::filesystem::path& path, std::string* error) {
  // OIIO's own words for these ("could not find a format reader") hide the cause.
  if (auto why = unreadable_because(path)) {
    *error = *why;
    return std::nullopt;
  }
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) {
    std::string why = OIIO::geterror();
    *error = why.empty() ? "cannot open image" : why;
    return std::nullopt;
  }
  const OIIO::ImageSpec& spec = in->spec();
  // The header alone says how much memory reading would take: check it first.
  if (spec.width < 1 || spec.height < 1 || spec.width > kMaxImageSide || spec.height > kMaxImageSide) {
    *error = "is " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + " pixels; a channel image may be 1 to " +
             std::to_string(kMaxImageSide) + " pixels a side";
    return std::nullopt;
  }
  if (spec.depth > 1) {
    *error = "is a volume image; a channel image is 2D";
    return std::nullopt;
  }
  if (spec.nchannels < 1 || spec.nchannels > kMaxImageChannels) {
    *error = "has " + std::to_string(spec.nchannels) + " channels; a channel image may have 1 to " +
             std::to_string(kMaxImageChannels) + " (the first 4 are used)";
    return std::nullopt;
  }
  Image image;
  image.width = spec.width;
  image.height = spec.height;
  const int channels = spec.nchannels;
  std::vector<float> pixels(static_cast<size_t>(spec.width) * spec.height * channels);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data())) {
    *error = in->geterror();
    return std::nullopt;
  }
  // Expand grey, grey+alpha and RGB to RGBA.
  image.rgba.assign(static_cast<size_t>(image.width) * image.height * 4, 1.0f);
  const float* src = pixels.data();
  float* dst = image.rgba.data();
  for (size_t i = 0; i < static_cast<size_t>(image.width) * image.height; ++i, src += channels, dst += 4) {
    if (channels == 1) {
      dst[0] = dst[1] = dst[2] = src[0];
    } else if (channels == 2) {  // grey + alpha
      dst[0] = dst[1] = dst[2] = src[0];
      dst[3] = src[1];
    } else {
      for (int c = 0; c < std::min(channels, 4); ++c) dst[c] = src[c];
    }
  }
  return image;
}

Channels::Channels() {
  for (int i = 0; i < kCount; ++i) clear(i);
}

void Channels::clear(int index) {
  const float black[4] = {0, 0, 0, 0};
  gl::Texture texture = gl::make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(texture.get(), 1, GL_RGBA8, 1, 1);
  glTextureSubImage2D(texture.get(), 0, 0, 0, 1, 1, GL_RGBA, GL_FLOAT, black);
  textures_[static_cast<size_t>(index)] = std::move(texture);
  resolution_[static_cast<size_t>(index)] = glm::vec3(0.0f);
}

bool Channels::use_scene_defaults(const Paths& scene_defaults, const Paths& from_command_line, std::string* error) {
  bool ok = true;
  for (size_t i = 0; i < kCount; ++i) {
    if (!from_command_line[i].empty() || scene_defaults[i] == scene_defaults_[i]) continue;
    if (scene_defaults[i].empty()) {
      clear(static_cast<int>(i));
      scene_defaults_[i].clear();
      continue;
    }
    std::string why;
    auto image = load_channel_image(scene_defaults[i], &why);
    if (!image) {
      *error = "iChannel" + std::to_string(i) + " '" + scene_defaults[i].string() + "': " + why;
      ok = false;
      continue;
    }
    set(static_cast<int>(i), *image);
    scene_defaults_[i] = scene_defaults[i];
  }
  return ok;
}

void Channels::set(int index, const Image& file_image) {
  const Image image = file_image.flipped();  // GL's row 0 is the bottom
  // Shadertoy's defaults: mipmapped, linear filtering, repeat wrap.
  gl::Texture texture = gl::make_texture(GL_TEXTURE_2D);
  int levels = 1;
  for (int size = std::max(image.width, image.height); size > 1; size /= 2) ++levels;
  glTextureStorage2D(texture.get(), levels, GL_RGBA16F, image.width, image.height);
  glTextureSubImage2D(texture.get(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_FLOAT, image.rgba.data());
  glGenerateTextureMipmap(texture.get());
  glTextureParameteri(texture.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(texture.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(texture.get(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(texture.get(), GL_TEXTURE_WRAP_T, GL_REPEAT);
  textures_[static_cast<size_t>(index)] = std::move(texture);
  resolution_[static_cast<size_t>(index)] = glm::vec3(image.width, image.height, 1.0f);
}

}  // namespace rm
