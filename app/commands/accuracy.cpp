#include "commands/accuracy.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "commands/cli_options.h"
#include "core/inputs.h"
#include "headless/accuracy_command.h"

namespace rm::cli {

AccuracyCommand::AccuracyCommand(CLI::App& app)
    : command_(app.add_subcommand("accuracy", "Measure what each shaderlib accuracy knob costs (GPU time, map() calls) "
                                              "and buys (error against a reference)")) {
  CLI::App& c = *command_;
  c.add_option("scene", scene_, "Scene that renders with shaderlib")->required()->type_name("SCENE");
  c.add_option("--size", size_, "Picture size in pixels (default 320x180)")->type_name("WxH");
  c.add_option("--time", time_, "iTime of the measured frame (default 1)")->type_name("T");
  c.add_option("--out", out_, "Directory for accuracy.csv, accuracy.svg, reference.png, steps.png "
                              "(default accuracy-SCENE)")->type_name("DIR");
  source_.add_to(c);
}

int AccuracyCommand::run() const {
  require_readable_file(scene_);
  AccuracyRequest req;
  req.scene = scene_;
  req.source = source_.source();
  req.size = parse_size(size_, "--size");
  if (!std::isfinite(time_)) throw UsageError{"--time '" + std::to_string(time_) + "': not a finite number"};
  // The frame's iFrame is iTime at 60 a second.
  if (auto why = iframe_out_of_range(time_ * 60.0)) {
    char time[32];
    std::snprintf(time, sizeof time, "%g", time_);
    throw UsageError{"--time " + std::string(time) + ": " + *why};
  }
  req.time = time_;
  req.out = out_;
  return accuracy_command(req);
}

}  // namespace rm::cli
