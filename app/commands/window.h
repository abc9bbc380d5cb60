// `raymarching [SCENE]`, the default command: the scene in a window, reloaded
// on every save (window/window_app runs it).
#pragma once
#include <CLI/CLI.hpp>
#include <string>

#include "commands/cli_options.h"

namespace rm::cli {

class WindowCommand {
 public:
  explicit WindowCommand(CLI::App& app);  // adds its options to the program's own
  int run() const;

 private:
  std::string scene_, media_, size_ = "800x450", shot_dir_ = ".", shot_format_ = "png", watch_ = "auto";
  int shot_scale_ = 1;
  bool verbose_ = false;
  bool no_ui_ = false;
  bool hud_ = false;
  bool controls_ = false;
  double target_fps_ = 30.0;
  int refine_ = 16;
  double tile_limit_ = 2.0;
  SourceFlags source_;
  ChannelFlags channels_;
};

}  // namespace rm::cli
