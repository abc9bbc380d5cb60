// raymarching-images: the module the host loads on the first picture it
// reads or writes (core/image_codecs.h says why it is not linked in). Only
// OpenImageIO's calls live here; what the host checks and how it words its
// errors stay in the core.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <map>
#include <mutex>
#include <string>

#include "core/files.h"
#include "core/image_codecs.h"

namespace rm {

namespace {

namespace fs = std::filesystem;

class OiioCodecs final : public ImageCodecs {
 public:
  std::optional<DecodedImage> read(const fs::path& path, const HeaderCheck& accept, bool header_only,
                                   std::string* error) const override {
    auto in = OIIO::ImageInput::open(path.string());
    if (!in) {
      *error = OIIO::geterror();
      return std::nullopt;
    }
    const OIIO::ImageSpec& spec = in->spec();
    DecodedImage image;
    image.header = {spec.width, spec.height, spec.depth, spec.nchannels};
    if (auto refused = accept(image.header)) {
      *error = *refused;
      return std::nullopt;
    }
    if (header_only) return image;
    image.pixels.resize(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data())) {
      *error = in->geterror();
      return std::nullopt;
    }
    return image;
  }

  bool can_encode(const fs::path& path) const override {
    auto out = OIIO::ImageOutput::create(path.string());
    const bool yes = out && out->supports("ioproxy") && reads_back(path);  // the host encodes in memory
    if (!out) OIIO::geterror();  // clear the pending message
    return yes;
  }

  // Whether a small picture written in `path`'s format reads back. Debian
  // 12's OpenImageIO writes JPEG 2000 files of 77 bytes, whatever the
  // picture, that neither it nor any other reader can open ("Expected a SOC
  // marker"; oiiotool's own are the same): such a format is not offered.
  bool reads_back(const fs::path& path) const {
    // Once per extension: a sequence asks before each of its frames.
    static std::mutex mutex;
    static std::map<std::string, bool> known;
    const std::lock_guard<std::mutex> lock(mutex);
    auto [it, fresh] = known.try_emplace(lowercase_extension(path), false);
    if (fresh) it->second = probe_reads_back(path);
    return it->second;
  }

  bool probe_reads_back(const fs::path& path) const {
    const unsigned char rgba[2 * 2 * 4] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
    std::vector<unsigned char> bytes;
    std::string error;
    if (!encode(path, {2, 2, rgba, false}, {}, &bytes, &error)) return false;
    OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
    auto in = OIIO::ImageInput::open(path.string(), nullptr, &memory);
    float pixels[2 * 2 * 4];
    const bool ok = in && in->spec().width == 2 && in->spec().height == 2 && in->spec().nchannels >= 3 &&
                    in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, pixels);
    OIIO::geterror();
    return ok;
  }

  std::vector<std::string> encodable_extensions() const override {
    static const std::vector<std::string> list = find_encodable_extensions();  // a writer made per format: once
    return list;
  }

  std::vector<std::string> find_encodable_extensions() const {
    // OIIO's "format:ext,ext;format:ext" list.
    std::vector<std::string> out;
    const std::string formats = OIIO::get_string_attribute("extension_list");
    for (size_t at = 0; at < formats.size();) {
      size_t end = formats.find(';', at);
      if (end == std::string::npos) end = formats.size();
      const std::string entry = formats.substr(at, end - at);
      at = end + 1;
      const size_t colon = entry.find(':');
      if (colon == std::string::npos) continue;
      const std::string format = entry.substr(0, colon), ext = entry.substr(colon + 1, entry.find(',', colon) - colon - 1);
      if (format == "null" || ext.empty()) continue;  // OIIO's writer that writes nothing
      auto writer = OIIO::ImageOutput::create(format);
      if (writer && writer->supports("ioproxy") && reads_back("probe." + ext)) out.push_back(ext);
    }
    OIIO::geterror();  // the formats without a writer leave a message behind
    return out;
  }

  bool encode(const fs::path& path, const PixelsToEncode& pixels, const Metadata& metadata,
              std::vector<unsigned char>* bytes, std::string* error) const override {
    const OIIO::TypeDesc type = pixels.floats ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
    OIIO::Filesystem::IOVecOutput memory(*bytes);
    auto out = OIIO::ImageOutput::create(path.string());
    // A format without alpha (HDR, PNM) refuses four channels: it gets each
    // pixel's first three.
    const int channels = out && !out->supports("alpha") ? 3 : 4;
    OIIO::ImageSpec spec(pixels.width, pixels.height, channels, type);
    for (const auto& [key, value] : metadata) spec.attribute(key, value);
    bool ok = out && out->set_ioproxy(&memory) && out->open(path.string(), spec);
    if (ok) {
      ok = out->write_image(type, pixels.data, static_cast<OIIO::stride_t>(4 * type.size()));
      ok = out->close() && ok;
    }
    if (!ok) *error = out ? out->geterror() : OIIO::geterror();
    return ok;
  }

  Metadata metadata(const fs::path& path) const override {
    Metadata out;
    auto in = OIIO::ImageInput::open(path.string());
    if (!in) {
      OIIO::geterror();
      return out;
    }
    for (const auto& p : in->spec().extra_attribs)
      if (p.type() == OIIO::TypeDesc::STRING) out.emplace_back(p.name().string(), p.get_string());
    return out;
  }
};

}  // namespace

}  // namespace rm

// The module's one entry point, found by name (core/image_codecs.cpp).
extern "C" __attribute__((visibility("default"))) const rm::ImageCodecs* rm_image_codecs() {
  static const rm::OiioCodecs codecs;
  return &codecs;
}
