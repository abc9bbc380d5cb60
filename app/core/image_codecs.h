// ImageCodecs: what the host asks of OpenImageIO, behind one seam. Debian's
// OpenImageIO links about 240 libraries (GDAL, OpenCV, DCMTK, FFmpeg, ...),
// and loading them cost every process 0.4 s before main() on this machine:
// `check`, `--version` and a window that reads no image paid it too. So the
// code that calls OpenImageIO is a module of its own (app/image_codecs/),
// loaded the first time a picture is read or written.
#pragma once
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rm {

// Attributes stored in the file, e.g. {"raymarching:iTime", "1.5"}.
using Metadata = std::vector<std::pair<std::string, std::string>>;

// An image file's header: what decoding it would take.
struct ImageHeader {
  int width = 0, height = 0, depth = 1, channels = 0;
};

// A decoded image: header.channels floats a pixel, top row first.
struct DecodedImage {
  ImageHeader header;
  std::vector<float> pixels;
};

// RGBA pixels to encode, top row first: 4 floats or 4 bytes a pixel.
struct PixelsToEncode {
  int width = 0, height = 0;
  const void* data = nullptr;
  bool floats = false;
};

class ImageCodecs {
 public:
  virtual ~ImageCodecs() = default;
  // Opens `path` and shows its header to `accept`, whose message refuses
  // the image before a pixel is read; then, unless `header_only`, reads
  // every channel as floats. nullopt with *error (the library's own words,
  // possibly several lines) on failure.
  using HeaderCheck = std::function<std::optional<std::string>(const ImageHeader&)>;
  virtual std::optional<DecodedImage> read(const std::filesystem::path& path, const HeaderCheck& accept,
                                           bool header_only, std::string* error) const = 0;
  // Whether a format with `path`'s extension can be encoded into memory.
  virtual bool can_encode(const std::filesystem::path& path) const = 0;
  // The first extension of every format can_encode takes, without the dot.
  virtual std::vector<std::string> encodable_extensions() const = 0;
  // Encodes `pixels` in the format `path` names, with `metadata` in order,
  // into *bytes; false with *error (the library's words) on failure.
  virtual bool encode(const std::filesystem::path& path, const PixelsToEncode& pixels, const Metadata& metadata,
                      std::vector<unsigned char>* bytes, std::string* error) const = 0;
  // The string attributes of an image file; none if it cannot be read.
  virtual Metadata metadata(const std::filesystem::path& path) const = 0;
  // Why none of the above can work here, if they cannot (the module did not load).
  virtual std::optional<std::string> unavailable() const { return std::nullopt; }
};

// The codecs, loaded on first use (any thread). If the module cannot be
// loaded, they are stand-ins whose unavailable() says why ("cannot load
// ...", or that a thread could not be started) and whose every call fails
// with that; the next call tries again.
std::shared_ptr<const ImageCodecs> image_codecs();

}  // namespace rm
