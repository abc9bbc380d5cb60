// `raymarching check SCENE [-E [-P]]`: preprocess and validate with glslang,
// print diagnostics; -E prints what the compiler sees (-P: without line
// markers, as cpp -P). Needs no GL, EGL or GLFW.
#pragma once
#include <CLI/CLI.hpp>
#include <string>

#include "commands/cli_options.h"

namespace rm::cli {

class CheckCommand {
 public:
  explicit CheckCommand(CLI::App& app);  // adds the subcommand and its options
  bool chosen() const { return command_->parsed(); }
  int run() const;

 private:
  CLI::App* command_;
  std::string scene_;
  bool expand_ = false;
  bool no_line_markers_ = false;
  SourceFlags source_;
};

}  // namespace rm::cli
