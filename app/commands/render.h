// `raymarching render SCENE -o OUT`: a still, a frame sequence or a video,
// headless through EGL (headless/render_command does the rendering).
#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "commands/cli_options.h"

namespace rm {
struct RenderRequest;
}  // namespace rm

namespace rm::cli {

class RenderCommand {
 public:
  explicit RenderCommand(CLI::App& app);  // adds the subcommand and its options
  bool chosen() const { return command_->parsed(); }
  int run() const;

 private:
  void take_into(RenderRequest& req) const;

  CLI::App* command_;
  std::string scene_, out_, size_ = "640x360", time_ = "0", mouse_, date_, view_;
  std::vector<std::string> sets_;  // --set NAME=VALUE
  int frame_ = -1, frames_ = 0, samples_ = 1;
  double fps_ = 60.0;
  double duration_ = 0;  // --duration: seconds of frames at fps_
  std::string codec_;    // --codec
  std::string frame_range_;  // --frame-range FIRST:LAST
  int crf_ = -1;         // --crf; -1: the codec's default
  double shutter_ = -1;  // --shutter; -1: 0.5 with --motion-samples, else none
  int motion_samples_ = 1;
  double timeout_ = 0;
  bool skip_existing_ = false;
  SourceFlags source_;
  ChannelFlags channels_;
  std::string media_;
  std::string take_;  // --take
};

}  // namespace rm::cli
