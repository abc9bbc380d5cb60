#include "core/channels.h"

#include <algorithm>

#include "core/cube_map.h"
#include "core/files.h"
#include "core/image_codecs.h"
#include "core/one_line.h"
#include "core/stderr_shut.h"
#include "core/volume.h"

namespace rm {

namespace {

// Why a channel image with this header is refused before its pixels are read.
std::optional<std::string> refused(const ImageHeader& header) {
  // The header alone says how much memory reading would take: check it first.
  if (header.width < 1 || header.height < 1 || header.width > kMaxImageSide || header.height > kMaxImageSide)
    return "is " + std::to_string(header.width) + "x" + std::to_string(header.height) +
           " pixels; a channel image may be 1 to " + std::to_string(kMaxImageSide) + " pixels a side";
  if (header.depth > 1) return "is a volume image; a channel image is 2D";
  if (header.channels < 1 || header.channels > kMaxImageChannels)
    return "has " + std::to_string(header.channels) + " channels; a channel image may have 1 to " +
           std::to_string(kMaxImageChannels) + " (the first 4 are used)";
  return std::nullopt;
}

// Opens `path`, checks its header, and reads its pixels unless `header_only`.
std::optional<DecodedImage> read_checked(const std::filesystem::path& path, bool header_only, std::string* error) {
  // OIIO's own words for these ("could not find a format reader") hide the cause.
  if (auto why = unreadable_because(path)) {
    *error = *why;
    return std::nullopt;
  }
  const auto codecs = image_codecs();
  if (auto why = codecs->unavailable()) {
    *error = *why;
    return std::nullopt;
  }
  std::optional<DecodedImage> image;
  {
    const StderrShut quiet;
    image = codecs->read(path, refused, header_only, error);
  }
  if (!image) {
    const std::string why = one_line(*error);
    *error = why.empty() ? "cannot open image" : why;
  }
  return image;
}

}  // namespace

bool check_channel_image(const std::filesystem::path& path, std::string* error) {
  return read_checked(path, true, error).has_value();
}

namespace {

std::optional<Image> decode_channel_image(const std::filesystem::path& path, std::string* error) {
  const auto decoded = read_checked(path, false, error);
  if (!decoded) return std::nullopt;
  Image image;
  image.width = decoded->header.width;
  image.height = decoded->header.height;
  const int channels = decoded->header.channels;
  // Expand grey, grey+alpha and RGB to RGBA.
  image.rgba.assign(static_cast<size_t>(image.width) * image.height * 4, 1.0f);
  const float* src = decoded->pixels.data();
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

}  // namespace

// An image within the size limit may still be more than the memory there is
// (16384x16384 is 4 GiB as floats): one line, not an abort.
std::optional<Image> load_channel_image(const std::filesystem::path& path, std::string* error) {
  try {
    return decode_channel_image(path, error);
  } catch (const std::bad_alloc&) {
    *error = "not enough memory to read its pixels";
    return std::nullopt;
  }
}

namespace {

int mip_levels(int width, int height) {
  int levels = 1;
  for (int size = std::max(width, height); size > 1; size /= 2) ++levels;
  return levels;
}

std::optional<ImageTextures::Entry> flat_texture(const ChannelSpec& spec, std::string* error) {
  auto file_image = load_channel_image(spec.path, error);
  if (!file_image) return std::nullopt;
  // GL's row 0 is the bottom: a file read right side up is flipped for it.
  const Image image = spec.sampler.vflip ? file_image->flipped() : std::move(*file_image);
  ImageTextures::Entry entry;
  entry.texture = gl::make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(entry.texture.get(), mip_levels(image.width, image.height), GL_RGBA16F, image.width, image.height);
  glTextureSubImage2D(entry.texture.get(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_FLOAT, image.rgba.data());
  glGenerateTextureMipmap(entry.texture.get());
  entry.resolution = glm::vec3(image.width, image.height, 1.0f);
  return entry;
}

std::optional<ImageTextures::Entry> cube_texture(const ChannelSpec& spec, std::string* error) {
  auto cube = load_cube_map(spec.path, error);
  if (!cube) return std::nullopt;
  ImageTextures::Entry entry;
  entry.target = GL_TEXTURE_CUBE_MAP;
  entry.texture = gl::make_texture(GL_TEXTURE_CUBE_MAP);
  glTextureStorage2D(entry.texture.get(), mip_levels(cube->size, cube->size), GL_RGBA16F, cube->size, cube->size);
  for (int f = 0; f < 6; ++f)  // faces upload unflipped: their first row is GL's t = 0
    glTextureSubImage3D(entry.texture.get(), 0, 0, 0, f, cube->size, cube->size, 1, GL_RGBA, GL_FLOAT,
                        cube->faces[static_cast<size_t>(f)].rgba.data());
  glGenerateTextureMipmap(entry.texture.get());
  entry.resolution = glm::vec3(cube->size, cube->size, 1.0f);
  return entry;
}

std::optional<ImageTextures::Entry> volume_texture(const ChannelSpec& spec, std::string* error) {
  auto volume = load_volume(spec.path, error);
  if (!volume) return std::nullopt;
  const glm::ivec3 n = volume->size;
  ImageTextures::Entry entry;
  entry.target = GL_TEXTURE_3D;
  entry.texture = gl::make_texture(GL_TEXTURE_3D);
  int levels = 1;
  for (int size = std::max({n.x, n.y, n.z}); size > 1; size /= 2) ++levels;
  glTextureStorage3D(entry.texture.get(), levels, GL_RGBA16F, n.x, n.y, n.z);
  glTextureSubImage3D(entry.texture.get(), 0, 0, 0, 0, n.x, n.y, n.z, GL_RGBA, GL_FLOAT, volume->rgba.data());
  glGenerateTextureMipmap(entry.texture.get());
  entry.resolution = glm::vec3(n);
  return entry;
}

// When the file (or each face file of a cube map) was last written.
std::vector<std::filesystem::file_time_type> stamps_of(const ChannelSpec& spec) {
  std::vector<std::filesystem::path> files{spec.path};
  if (spec.shape == ChannelSpec::Shape::Cube) {
    auto faces = cube_face_files(spec.path, exists_on_disk);
    if (!faces.empty()) files = std::move(faces);
  }
  std::vector<std::filesystem::file_time_type> stamps;
  for (const auto& file : files) {
    std::error_code ec;
    stamps.push_back(std::filesystem::last_write_time(file, ec));
  }
  return stamps;
}

}  // namespace

ImageTextures::Key ImageTextures::key_of(const ChannelSpec& spec) {
  return {spec.path, spec.shape, spec.shape == ChannelSpec::Shape::Flat && spec.sampler.vflip};
}

ImageTextures::Entry ImageTextures::read(const ChannelSpec& spec) {
  std::vector<std::filesystem::file_time_type> stamps = stamps_of(spec);  // before reading: a later write is seen
  std::string error;
  std::optional<Entry> entry = spec.shape == ChannelSpec::Shape::Cube     ? cube_texture(spec, &error)
                               : spec.shape == ChannelSpec::Shape::Volume ? volume_texture(spec, &error)
                                                                          : flat_texture(spec, &error);
  if (!entry) entry.emplace().error = std::move(error);
  entry->stamps = std::move(stamps);
  return std::move(*entry);
}

const ImageTextures::Entry* ImageTextures::get(const ChannelSpec& spec, std::string* error, bool* reread) {
  const Key key = key_of(spec);
  const std::vector<std::filesystem::file_time_type> stamps = stamps_of(spec);
  auto it = entries_.find(key);
  if (it != entries_.end() && it->second.stamps == stamps) return &it->second;
  const auto ready = handed_over_.find(key);
  Entry entry = ready != handed_over_.end() && ready->second.stamps == stamps ? std::move(ready->second) : read(spec);
  handed_over_.erase(key);
  if (!entry.texture) {
    *error = std::move(entry.error);
    return it != entries_.end() ? &it->second : nullptr;  // a bad save keeps the last good image
  }
  if (reread) *reread = true;
  entries_.insert_or_assign(key, std::move(entry));
  return &entries_.at(key);
}

bool ImageTextures::stale(const ChannelSpec& spec, const HeldImages& held) {
  const auto it = held.find(key_of(spec));
  return it == held.end() || it->second.stamps != stamps_of(spec);
}

ImageTextures::HeldImages ImageTextures::held() const {
  HeldImages out;
  for (const auto& [key, entry] : entries_) out[key] = {entry.stamps, glm::ivec3(entry.resolution)};
  return out;
}

void ImageTextures::hand_over(std::vector<std::pair<ChannelSpec, Entry>> read) {
  for (auto& [spec, entry] : read) handed_over_.insert_or_assign(key_of(spec), std::move(entry));
}

const ImageTextures::Entry* ImageTextures::find(const ChannelSpec& spec) const {
  auto it = entries_.find(key_of(spec));
  return it == entries_.end() ? nullptr : &it->second;
}

void ImageTextures::keep_only(const std::vector<ChannelSpec>& used) {
  handed_over_.clear();  // read for a graph that is not the one bound
  std::vector<Key> keys;
  for (const ChannelSpec& spec : used) keys.push_back(key_of(spec));
  for (auto it = entries_.begin(); it != entries_.end();)
    it = std::find(keys.begin(), keys.end(), it->first) == keys.end() ? entries_.erase(it) : std::next(it);
}

}  // namespace rm
