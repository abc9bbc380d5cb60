// glslViewer's buffer passes, drawn from one file as glslViewer draws them.
// A shader that declares `uniform sampler2D u_buffer0;` and reads it is
// drawn once more, with BUFFER_0 defined, into a buffer that u_buffer0
// reads; `u_doubleBuffer1` likewise with DOUBLE_BUFFER_1 (every buffer of
// the graph is a ping-pong pair, so the two differ only in the name). Each
// such pass is a pass of the graph (core/project.h) under a path of its
// own, the file's with the define after a '#': "scene.frag#BUFFER_0".
// preprocess() reads that path as the file with the define added.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace rm {

// The pass that draws `file` with `define` ("BUFFER_0").
std::filesystem::path glslviewer_pass(const std::filesystem::path& file, std::string_view define);

struct GlslViewerPass {
  std::filesystem::path file;  // the shader file
  std::string define;          // what the pass defines: BUFFER_N or DOUBLE_BUFFER_N
};
// What glslviewer_pass() made `pass` of; nullopt for any other path.
std::optional<GlslViewerPass> glslviewer_pass_of(const std::filesystem::path& pass);

// The define of the pass a glslViewer buffer sampler reads: "u_buffer0" ->
// "BUFFER_0", "u_doubleBuffer1" -> "DOUBLE_BUFFER_1"; "" for any other name.
std::string glslviewer_buffer_define(std::string_view sampler);

}  // namespace rm
