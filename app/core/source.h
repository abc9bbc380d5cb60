// Source: turns a scene file into one GLSL string the driver accepts, and
// remembers where every line of that string came from.
//
// Preprocessing resolves #include (relative to the including file, then -I
// dirs, <rm/...> from the bundled shaderlib), includes each file once, strips
// a UTF-8 byte-order mark, and wraps the three kinds of shader we accept
// (Shadertoy mainImage, complete #version+main, glslViewer-style legacy GLSL)
// so that they run unmodified on an OpenGL 4.5 core context. The host's own
// lines are tracked in the line map too, so they never shift user lines.
#pragma once
#include <array>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/channel_spec.h"
#include "core/diagnostics.h"

namespace rm {

namespace fs = std::filesystem;

enum class ShaderKind {
  Shadertoy,  // defines mainImage(out vec4, in vec2); the host adds main()
  Complete,   // has its own modern #version and main()
  Legacy,     // glslViewer / Book of Shaders: no or old #version, gl_FragColor
};
const char* to_string(ShaderKind kind);

// Where one line of the final source came from. file < 0 marks host lines:
// kCommandLineFile those of the -D options (line: the option's number).
inline constexpr int kHostFile = -1;
inline constexpr int kCommandLineFile = -2;
struct Origin {
  int file = kHostFile;
  int line = 0;
};

struct Define {
  std::string name;
  std::string value;  // empty means "1", as -DNAME does in a compiler
  bool operator==(const Define&) const = default;
};
// Why `d` cannot be a -D ("'1X' is not a macro name", "its value is not one
// line"); nullopt when it can. A take's defines are checked as the command
// line's are.
std::optional<std::string> define_problem(const Define& d);

struct SourceOptions {
  std::vector<fs::path> include_dirs;  // -I, searched after the including file's dir
  fs::path shaderlib_dir;              // root that holds rm/, for <rm/...>
  std::vector<Define> defines;         // -D, placed right after #version
  // Macros the shader's files may not define: their #define lines are read
  // as blank lines. Every -D's name is one of them as well, so that the
  // command line (and a control of the window) wins over a scene's own
  // #define, where GLSL would report a redefinition.
  std::vector<std::string> undefines;
  // Included before the scene's first line, as a compiler's -include: the
  // scene's own lines keep their numbers (a Shadertoy JSON's Common).
  std::vector<std::string> forced_includes;
};

// File access, injectable so tests and fuzzers can use an in-memory tree.
// The disk's reads only regular files of at most kMaxShaderBytes (core/files.h).
struct FileSystem {
  // The file's bytes, or nullopt with why->message set ("no such file", "is
  // a directory", ...). why->path is set only where the cause lies in another
  // file, with its place: a pass of a Shadertoy JSON that does not parse.
  // why->unchecked is set where the machine failed, not the file (no
  // descriptor left).
  std::function<std::optional<std::string>(const fs::path&, Diagnostic* why)> read;
  std::function<bool(const fs::path&)> exists;
  // What the files themselves warn about, read anew at each build (a JSON's
  // stand-ins and left-out inputs); empty, or unset, for the disk.
  std::function<Diagnostics()> warnings;
};
FileSystem disk_file_system();

// The #version line the host gives a shader that names none, or an old one.
inline constexpr char kHostVersionLine[] = "#version 450 core";

inline constexpr char kMissingIncludeMark[] = "rm_missing_include_";

struct Source {
  std::string text;                // the final GLSL handed to glslang and the driver
  std::vector<fs::path> files;     // every file read (index = Origin::file); [0] is the scene
  std::vector<fs::path> watch;     // files whose change should reload, incl. missing includes
  std::vector<Origin> line_map;    // one entry per line of text (0-based index)
  ShaderKind kind = ShaderKind::Shadertoy;
  // A Shadertoy Cube A pass: it defines mainCubemap instead of mainImage and
  // is drawn once per cube face (rm_CubeFace says which).
  bool cubemap = false;
  // Whether the host moves gl_FragCoord (by a tile's origin, a supersample's
  // offset): false only for a shader that redeclares gl_FragCoord itself.
  bool movable_frag_coord = true;
  std::string version_line;        // the #version line the final text starts with
  // Words 4.50 core reserves that the code, written for an older dialect,
  // uses as names: the compiler sees each as rm_<word> (core/dialect_names.h).
  std::vector<std::string> renamed;
  // What iChannel0..3 read, named in the shader by #pragma channelN
  // (core/channel_spec.h; a file is relative to the file that names it);
  // Kind::None where nothing is named. A --channelN wins.
  std::array<ChannelSpec, 4> channels;
  Diagnostics errors;              // preprocessing errors; text is unusable if any
  // Includes in an #if branch that are not found or cannot be read (a FIFO,
  // a directory, NUL bytes): the text holds `#error rm_missing_include_N`
  // there (kMissingIncludeMark), for the Nth of these, which the compiler
  // says only if it takes that branch.
  Diagnostics missing_includes;

  bool ok() const { return errors.empty(); }
  // Maps a 1-based line of text to the user's file and line.
  std::pair<std::string, int> locate(int final_line) const;
  // The final source's line (1-based), or "" when out of range.
  std::string final_line_text(int final_line) const;

  // The scene's file: where a message with no line of the user's is said.
  std::string scene_path() const { return files.empty() ? std::string() : files.front().string(); }
};

Source preprocess(const fs::path& scene, const SourceOptions& options,
                  const FileSystem& fs = disk_file_system());

// One warning per channel that the shader's own code reads while nothing is
// bound to it (`bound[c]` false): it would read transparent black without a
// word. Each names the first line that reads it (glslViewer's u_texN, which
// the code declares itself, its declaration). Also one per sampler the code
// declares and reads that no channel binds (glslViewer's u_buffer0, a
// sampler of its own), at its declaration: the host binds it to no texture.
// `active`, glslang's preprocessor output of source.text line for line
// (core/check.h), says which lines read: not an #if branch the compiler
// drops, and a read through a macro. Empty: every line of the code.
Diagnostics unbound_channel_reads(const Source& source, const std::array<bool, 4>& bound,
                                  std::string_view active = {});

}  // namespace rm
