// Capture: writes pictures through OpenImageIO. Files appear whole or not at
// all: the pixels go to a temporary name in the same directory, which is then
// renamed. PNG and other 8-bit formats get the output clamped to [0,1]; EXR
// and HDR keep the raw floats.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/image_codecs.h"
#include "core/renderer.h"
#include "core/source.h"

namespace rm {

namespace fs = std::filesystem;

// The largest picture the host draws and writes, a side: `render --size`,
// the window's --size and a screenshot at --shot-scale. A float picture of
// 16384x16384 already holds 4 GiB.
constexpr int kMaxPictureSide = 16384;

enum class Overwrite { Replace, Never };

// Returns an error message, or nullopt when `path` names a format we can
// write and a directory that exists. Cheap: call it before rendering.
std::optional<std::string> check_output_path(const fs::path& path);

// Returns an error message, or nullopt when the directory `path` would be
// written in exists and is writable.
std::optional<std::string> check_output_directory(const fs::path& path);

// The local time to the millisecond, as screenshots and takes are named
// (20261124-043537-161): two files of one scene never share a name.
std::string file_timestamp();

// A hidden name beside `path`, unique in this process, with path's extension:
// where a file is written before it is renamed to `path`.
fs::path temporary_sibling(const fs::path& path);

// The extensions write_image can write, as ".png, .exr, ..." (from OIIO),
// but those a caller writes otherwise (`render`'s videos: its .gif is one).
std::string writable_image_extensions(bool (*written_otherwise)(const fs::path&) = nullptr);

// Writes `image` to `path`. With Overwrite::Never an existing file is kept
// and "-1", "-2", ... is added before the extension. Returns the path
// written, or nullopt with *error set; on failure no file is left behind.
std::optional<fs::path> write_image(const fs::path& path, const Image& image, const Metadata& metadata,
                                    Overwrite overwrite, std::string* error);

// The bytes of the file write_image would write (its format chosen by
// `path`'s extension), or nullopt with *error set: for pictures that are
// written together with other files (write_whole_files).
std::optional<std::string> encode_image(const fs::path& path, const Image& image, const Metadata& metadata,
                                        std::string* error);

// Writes `bytes` to `path` the way write_image writes a picture: whole or
// not at all, under a hidden name first (same return and error).
std::optional<fs::path> write_whole_file(const fs::path& path, std::string_view bytes, Overwrite overwrite,
                                         std::string* error);

// Writes every file of `files` (path, bytes), replacing what is there, or
// none: each goes under a hidden name first, and only once all are written
// (a full disk fails one) are they renamed into place. False with *error.
bool write_whole_files(const std::vector<std::pair<fs::path, std::string_view>>& files, std::string* error);

// What a picture needs to be reproduced: scene, -I and -D (the accuracy knobs
// and the preset among them), inputs, supersamples and motion blur, and the
// `render` command line that makes it again (stored as ImageDescription).
Metadata frame_metadata(const fs::path& scene, const SourceOptions& source, const FrameInputs& inputs,
                        int samples = 1, const MotionBlur& motion = {});

// Reads metadata attributes back (for tests and for reproducing a shot).
Metadata read_metadata(const fs::path& path);

}  // namespace rm
