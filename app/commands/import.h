// `raymarching import PROJECT.json DIR`: writes a Shadertoy JSON export out
// as the files of a project (image.frag, buffer_a.frag ..., common.glsl), so
// it can be edited with hot reload. Needs no GL.
#pragma once
#include <CLI/CLI.hpp>
#include <string>

namespace rm::cli {

class ImportCommand {
 public:
  explicit ImportCommand(CLI::App& app);
  bool chosen() const { return command_->parsed(); }
  int run() const;

 private:
  CLI::App* command_;
  std::string json_, dir_, media_;
  bool force_ = false;
};

}  // namespace rm::cli
