// The headless renderer behind `render`: a still or a frame sequence through
// EGL (its options are read in commands/render).
#pragma once
#include <array>
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/source.h"
#include "core/take.h"
#include "core/views.h"

namespace rm {

struct RenderRequest {
  std::filesystem::path scene;
  SourceOptions source;
  std::filesystem::path out;  // a video (headless/video.h), or with a %d counter when frames > 0
  glm::ivec2 size{640, 360};
  double time = 0.0;
  std::optional<int> frame;   // default: the frame the time falls in at `fps`
  int frames = 0;             // 0: one picture; N: a sequence of N frames
  std::optional<glm::ivec2> frame_range;  // only frames x to y (included) of the sequence
  bool skip_existing = false;  // a frame whose file is there already is not drawn again
  double fps = 60.0;
  glm::vec4 mouse{0.0f};
  std::array<std::filesystem::path, 4> channels;
  std::filesystem::path media;  // a .json's shadertoy.com media
  std::optional<std::chrono::system_clock::time_point> date;  // default: now
  View view = View::Picture;  // --view: a debug view instead of the picture
  std::vector<std::string> sets;  // --set NAME=VALUE: the shader's own uniforms
  double timeout = 0;  // seconds; 0: none (see headless/run_guard)
  int samples = 1;     // supersamples per pixel (core/supersampling.h)
  double shutter = 0;     // motion blur: the share of the frame interval the shutter is open
  int motion_samples = 1; // motion blur: steps over the open shutter
  std::string codec;        // a video's ffmpeg encoder; empty: the container's default
  std::optional<int> crf;   // a video's quality; empty: the codec's default
  // render --take: the frames' inputs come from a take (core/take.h), whose
  // scene and -I/-D are `scene` and `source` already; `frames` is the
  // replay's count and `fps` its rate. take_fps 0: the take's own frames,
  // as recorded; else its timeline resampled at take_fps.
  std::optional<Take> take;
  double take_fps = 0;
};

int render_command(const RenderRequest& request);

// Expands a printf-style frame counter ("frame_%04d.png"); nullopt if the
// pattern has no single %d conversion.
std::optional<std::filesystem::path> sequence_path(const std::filesystem::path& pattern, int index);

}  // namespace rm
