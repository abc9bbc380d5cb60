// Video files through ffmpeg. Frames go raw (8-bit RGBA, as a PNG stores
// them) down a pipe to an ffmpeg process, which encodes them into a hidden
// file beside the output; finish() renames that file to the output's name.
// So an ffmpeg that is missing, fails or is killed leaves nothing under the
// output's name, and no PNGs are written on the way.
#pragma once
#include <sys/types.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "core/image.h"

namespace rm {

struct VideoSettings {
  glm::ivec2 size{640, 360};
  double fps = 60.0;
  std::string codec;       // an ffmpeg encoder; empty: the container's default
  std::optional<int> crf;  // quality, lower is better; empty: the codec's default here
};

// Whether `path` names a video container raymarching writes (.mp4, .mov,
// .webm, .gif), by its extension.
bool is_video_path(const std::filesystem::path& path);

// The extensions of the containers, as ".mp4, .mov, ...".
std::string video_extensions();

// Returns an error message, or nullopt when `path` can be written as a video
// with `settings`. Cheap (it starts no ffmpeg): call it before rendering.
std::optional<std::string> check_video(const std::filesystem::path& path, const VideoSettings& settings);

class VideoEncoder {
 public:
  // Starts ffmpeg writing `path`'s hidden sibling; nullptr with *error if it
  // cannot (no ffmpeg on PATH, say).
  static std::unique_ptr<VideoEncoder> start(const std::filesystem::path& path, const VideoSettings& settings,
                                             std::string* error);
  ~VideoEncoder();  // abandons an encode that did not finish
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  // Sends one frame (settings.size, top row first). False with *error if
  // ffmpeg is gone; the caller then abandons the video.
  bool add(const Image& frame, std::string* error);
  // Ends the stream, waits for ffmpeg and renames its file to the output's
  // name. False with *error (ffmpeg's own last words) if ffmpeg failed.
  bool finish(std::string* error);
  // Stops ffmpeg at once and removes its file. Safe from another thread
  // (render --timeout's watch) and more than once.
  void abandon();

 private:
  VideoEncoder(std::filesystem::path path, std::filesystem::path temp, pid_t pid, int input, int log);
  std::string ffmpeg_said() const;  // the last line ffmpeg wrote to stderr
  int end_input_and_wait();         // closes ffmpeg's input and returns its wait status

  std::filesystem::path path_, temp_;
  pid_t pid_;
  int input_;  // the pipe to ffmpeg's stdin; -1 once closed
  int log_;    // an unlinked file holding ffmpeg's stderr
  bool done_ = false;
};

}  // namespace rm
