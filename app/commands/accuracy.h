// `raymarching accuracy SCENE`: what each shaderlib accuracy knob costs and
// buys (headless/accuracy_command does the measuring).
#pragma once
#include <CLI/CLI.hpp>
#include <string>

#include "commands/cli_options.h"

namespace rm::cli {

class AccuracyCommand {
 public:
  explicit AccuracyCommand(CLI::App& app);  // adds the subcommand and its options
  bool chosen() const { return command_->parsed(); }
  int run() const;

 private:
  CLI::App* command_;
  std::string scene_, size_ = "320x180", out_;
  double time_ = 1.0;
  SourceFlags source_;
};

}  // namespace rm::cli
