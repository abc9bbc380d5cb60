#include "core/channels.h"

#include <OpenImageIO/imageio.h>

namespace rm {

std::optional<ChannelImage> load_channel_image(const std::filesystem::path& path, std::string* error) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) {
    std::string why = OIIO::geterror();
    *error = why.empty() ? "cannot open image" : why;
    return std::nullopt;
  }
  const OIIO::ImageSpec& spec = in->spec();
  ChannelImage image;
  image.width = spec.width;
  image.height = spec.height;
  const int channels = spec.nchannels;
  std::vector<float> pixels(static_cast<size_t>(spec.width) * spec.height * channels);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data())) {
    *error = in->geterror();
    return std::nullopt;
  }
  // Expand to RGBA and flip so that row 0 is the bottom, as Shadertoy samples it.
  image.rgba.assign(static_cast<size_t>(image.width) * image.height * 4, 1.0f);
  for (int y = 0; y < image.height; ++y) {
    const float* src = &pixels[static_cast<size_t>(image.height - 1 - y) * image.width * channels];
    float* dst = &image.rgba[static_cast<size_t>(y) * image.width * 4];
    for (int x = 0; x < image.width; ++x, src += channels, dst += 4) {
      if (channels == 1) {
        dst[0] = dst[1] = dst[2] = src[0];
      } else if (channels == 2) {  // grey + alpha
        dst[0] = dst[1] = dst[2] = src[0];
        dst[3] = src[1];
      } else {
        for (int c = 0; c < std::min(channels, 4); ++c) dst[c] = src[c];
      }
    }
  }
  return image;
}

Channels::Channels() {
  const float black[4] = {0, 0, 0, 0};
  for (auto& texture : textures_) {
    texture = gl::make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(texture.get(), 1, GL_RGBA8, 1, 1);
    glTextureSubImage2D(texture.get(), 0, 0, 0, 1, 1, GL_RGBA, GL_FLOAT, black);
  }
}

void Channels::set(int index, const ChannelImage& image) {
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
