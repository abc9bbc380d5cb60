#include "core/channels.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>

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

const ImageTextures::Entry* ImageTextures::get(const std::filesystem::path& path, std::string* error) {
  if (auto it = entries_.find(path); it != entries_.end()) return &it->second;
  auto file_image = load_channel_image(path, error);
  if (!file_image) return nullptr;
  const Image image = file_image->flipped();  // GL's row 0 is the bottom
  Entry entry;
  entry.texture = gl::make_texture(GL_TEXTURE_2D);
  int levels = 1;
  for (int size = std::max(image.width, image.height); size > 1; size /= 2) ++levels;
  glTextureStorage2D(entry.texture.get(), levels, GL_RGBA16F, image.width, image.height);
  glTextureSubImage2D(entry.texture.get(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_FLOAT, image.rgba.data());
  glGenerateTextureMipmap(entry.texture.get());
  entry.resolution = glm::vec3(image.width, image.height, 1.0f);
  return &entries_.emplace(path, std::move(entry)).first->second;
}

const ImageTextures::Entry* ImageTextures::find(const std::filesystem::path& path) const {
  auto it = entries_.find(path);
  return it == entries_.end() ? nullptr : &it->second;
}

void ImageTextures::keep_only(const std::vector<std::filesystem::path>& used) {
  for (auto it = entries_.begin(); it != entries_.end();)
    it = std::find(used.begin(), used.end(), it->first) == used.end() ? entries_.erase(it) : std::next(it);
}

}  // namespace rm
