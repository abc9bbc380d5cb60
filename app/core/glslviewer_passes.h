// glslViewer's passes, drawn from one file as glslViewer draws them.
// - A shader that declares `uniform sampler2D u_buffer0;` and reads it is
//   drawn once more, with BUFFER_0 defined, into a buffer that u_buffer0
//   reads; `u_doubleBuffer1` likewise with DOUBLE_BUFFER_1 (every buffer of
//   the graph is a ping-pong pair, so the two differ only in the name).
// - A shader with a POSTPROCESSING branch (`#ifdef POSTPROCESSING`) is
//   drawn on screen with POSTPROCESSING defined, and its `u_scene` reads the
//   scene pass: the file drawn with neither define, into a buffer.
// Each such pass is a pass of the graph (core/project.h) under a path of its
// own, the file's with the pass's name after a '#': "scene.frag#BUFFER_0",
// "scene.frag#SCENE". preprocess() reads that path as the file with the
// pass's define.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace rm {

// The pass named `name` ("BUFFER_0", "SCENE") of `file`.
std::filesystem::path glslviewer_pass(const std::filesystem::path& file, std::string_view name);

struct GlslViewerPass {
  std::filesystem::path file;  // the shader file
  std::string name;            // BUFFER_N, DOUBLE_BUFFER_N or SCENE
  std::string define;          // what the pass defines: its name, but none for SCENE
};
// What glslviewer_pass() made `pass` of; nullopt for any other path.
std::optional<GlslViewerPass> glslviewer_pass_of(const std::filesystem::path& pass);

// The name of the pass a glslViewer sampler reads: "u_buffer0" -> "BUFFER_0",
// "u_doubleBuffer1" -> "DOUBLE_BUFFER_1", "u_scene" -> "SCENE"; "" for any other.
std::string glslviewer_pass_read_by(std::string_view sampler);

// What the image pass of a glslViewer shader defines: POSTPROCESSING.
inline constexpr char kPostprocessing[] = "POSTPROCESSING";

}  // namespace rm
