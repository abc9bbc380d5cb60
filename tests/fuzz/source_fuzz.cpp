// libFuzzer target for the preprocessor and include resolver (core/source).
// The input is a small tree of files in memory, so includes, cycles, missing
// files, directories, pragmas and line endings are all fuzzed together:
//
//   scene text...
//   @@ lib.glsl
//   text of lib.glsl...
//   @@ rm/
//   (a name ending in / is a directory)
//
// The first chunk is /fuzz/scene.frag; each "@@ NAME" line starts the file
// /fuzz/NAME. <rm/...> resolves in /fuzz (the shaderlib root), -I is /fuzz/inc.
// Checked: no crash or hang, and every line of the output maps back to a file
// the preprocessor read (or to the host), in the scene and in each glslViewer
// pass it reads (the same file with BUFFER_N, or POSTPROCESSING's scene). The output's numbers are then lifted
// for a twin (core/tweak), which must keep every line where it was and hold
// as many marks as values, never more than the limit. The shader's own
// uniforms are read from it (core/user_uniforms), and each default, written
// as --set spells it, must read back. Built as check_fuzz
// (RM_FUZZ_CHECK), the result also goes through glslang's validation and the
// log mapping, and every diagnostic must print as one line.
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>

#include "core/glslviewer_passes.h"
#include "core/source.h"
#include "core/tweak.h"
#include "core/user_uniforms.h"
#ifdef RM_FUZZ_CHECK
#include "core/check.h"
#endif

namespace {

std::map<std::string, std::string> split_files(const std::string& input) {
  std::map<std::string, std::string> files;
  std::string name = "/fuzz/scene.frag", text;
  size_t pos = 0;
  while (pos <= input.size()) {
    const size_t end = input.find('\n', pos);
    const std::string line = input.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
    if (line.rfind("@@ ", 0) == 0) {
      files[name] = text;
      name = "/fuzz/" + line.substr(3);
      text.clear();
    } else {
      text += line;
      if (end != std::string::npos) text += '\n';
    }
    if (end == std::string::npos) break;
    pos = end + 1;
  }
  files[name] = text;
  return files;
}

// The line map covers every line, and each origin names a file that was read.
void check_line_map(const rm::Source& source) {
  size_t lines = 0;
  for (char c : source.text) lines += c == '\n';
  if (lines != source.line_map.size()) std::abort();
  for (const rm::Origin& o : source.line_map)
    if (o.file >= static_cast<int>(source.files.size())) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto files = split_files(std::string(reinterpret_cast<const char*>(data), size));
  rm::FileSystem memory;
  memory.read = [&files](const std::filesystem::path& path, rm::Diagnostic* why) -> std::optional<std::string> {
    const std::string key = path.lexically_normal().string();
    if (files.count(key + "/") || (!key.empty() && key.back() == '/')) {
      why->message = "is a directory";
      return std::nullopt;
    }
    auto it = files.find(key);
    if (it == files.end()) {
      why->message = "no such file";
      return std::nullopt;
    }
    return it->second;
  };
  memory.exists = [&files](const std::filesystem::path& path) {
    const std::string key = path.lexically_normal().string();
    return files.count(key) > 0 || files.count(key + "/") > 0;
  };
  rm::SourceOptions options;
  options.include_dirs = {"/fuzz/inc"};
  options.shaderlib_dir = "/fuzz";
  options.defines = {{"FUZZ", "1"}};
  const rm::Source source = rm::preprocess("/fuzz/scene.frag", options, memory);
  if (source.ok()) {
    check_line_map(source);
    size_t lines = source.line_map.size();
    for (const rm::ChannelSpec& channel : source.channels)
      if (channel.kind == rm::ChannelSpec::Kind::Pass && rm::glslviewer_pass_of(channel.path))
        if (const rm::Source pass = rm::preprocess(channel.path, options, memory); pass.ok()) check_line_map(pass);
    for (const rm::LiftScope scope : {rm::LiftScope::FunctionBodies, rm::LiftScope::WithConstants}) {
      const rm::LiftedLiterals lifted = rm::lift_literals(source, options.shaderlib_dir, scope);
      if (!lifted.ok) continue;
      const std::string& skeleton = lifted.skeleton;
      size_t skeleton_lines = 0, marks = 0;
      for (char c : skeleton) skeleton_lines += c == '\n', marks += c == '\x01';
      if (skeleton_lines != lines || marks != lifted.values.size() || marks > rm::kMaxTweaks) std::abort();
      if (lifted.constants > marks) std::abort();
      for (size_t at : lifted.main_bodies)
        if (at == 0 || at > skeleton.size() || skeleton[at - 1] != '{') std::abort();
      // Each dropped const is the word; moved initialisers begin at '=', in order, apart.
      for (size_t at : lifted.dropped_consts)
        if (skeleton.compare(at, 5, "const") != 0) std::abort();
      size_t after = 0;
      for (const auto& m : lifted.moved) {
        if (m.from < after || m.to < m.from || m.to > skeleton.size() || skeleton[m.from] != '=') std::abort();
        after = m.to;
      }
      const rm::Source twin = rm::twin_source(source, lifted);
      size_t twin_lines = 0;
      for (char c : twin.text) twin_lines += c == '\n';
      if (twin_lines != twin.line_map.size()) std::abort();
    }
    // The shader's own uniforms: each default written as --set spells it reads back.
    const rm::UserUniforms uniforms = rm::find_user_uniforms(source, &source.text);
    for (const rm::UserUniform& u : uniforms.uniforms) {
      if (u.initial.size() != static_cast<size_t>(u.components)) std::abort();
      std::string why;
      const auto back = rm::parse_uniform_value(u, rm::uniform_value_text(u.type, u.initial), &why);
      if (!back || back->size() != u.initial.size()) std::abort();
    }
#ifdef RM_FUZZ_CHECK
    for (const rm::Diagnostic& d : rm::validate(source))
      if (d.str().find('\n') != std::string::npos) std::abort();
#endif
  }
  return 0;
}
