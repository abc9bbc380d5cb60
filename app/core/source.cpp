#include "core/source.h"

#include <algorithm>
#include <array>
#include <climits>
#include <deque>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <unordered_set>

#include "core/channel_spec.h"
#include "core/check.h"
#include "core/dialect_names.h"
#include "core/files.h"
#include "core/glslviewer_passes.h"
#include "core/host_inputs.h"
#include "core/lexing.h"
#include "core/one_line.h"

namespace rm {

std::optional<std::string> define_problem(const Define& d) {
  if (!lexing::is_name(d.name)) return "'" + printable(d.name) + "' is not a macro name";
  // The value follows the name on the #define line the host writes.
  if (d.value.find_first_of("\n\r") != std::string::npos) return "its value is not one line";
  return std::nullopt;
}

namespace {

constexpr int kMaxIncludeDepth = 256;

// Put on the line of a #pragma channelN in an #if branch, for the compiler's
// preprocessor to keep where it takes the branch (bind_channel_pragmas).
constexpr std::string_view kChannelPragmaMark = " rm_channel_pragma_taken";

// A file name the code gave, as an error quotes it: whole, unless it is
// longer than any path can be (PATH_MAX), which only nonsense is.
std::string quoted_path(std::string_view name) { return brief(name, PATH_MAX); }

// The Shadertoy prelude: the host inputs (core/host_inputs.h), then each
// channel as what it is bound to.
std::string shadertoy_prelude(const std::array<ChannelSpec, 4>& channels) {
  std::string out = host_input_declarations();
  out += "uniform vec3 iChannelResolution[4];\n";
  for (int i = 0; i < 4; ++i)
    out += std::string("uniform ") + glsl_sampler_type(channels[static_cast<size_t>(i)].shape) + " iChannel" +
           std::to_string(i) + ";\n";
  out += "out vec4 rm_FragColor;";
  return out;
}

// A Cube A pass draws each face of a cube map in turn. A face's pixel looks
// along the direction that samples it back (GL's cube map layout: the face
// row 0 is its top), from the origin, as on Shadertoy.
const char* const kCubemapMain = R"glsl(void main() {
  vec4 rm_color = vec4(0.0, 0.0, 0.0, 1.0);
  vec2 rm_fragCoord = gl_FragCoord.xy;
  vec2 rm_st = rm_fragCoord / iResolution.xy * 2.0 - 1.0;
  vec3 rm_dir;
  if (rm_CubeFace == 0) rm_dir = vec3(1.0, -rm_st.y, -rm_st.x);
  else if (rm_CubeFace == 1) rm_dir = vec3(-1.0, -rm_st.y, rm_st.x);
  else if (rm_CubeFace == 2) rm_dir = vec3(rm_st.x, 1.0, rm_st.y);
  else if (rm_CubeFace == 3) rm_dir = vec3(rm_st.x, -1.0, -rm_st.y);
  else if (rm_CubeFace == 4) rm_dir = vec3(rm_st.x, -rm_st.y, 1.0);
  else rm_dir = vec3(-rm_st.x, -rm_st.y, -1.0);
  mainCubemap(rm_color, rm_fragCoord, vec3(0.0), normalize(rm_dir));
  rm_FragColor = rm_color;
})glsl";

// Shadertoy leaves fragColor's start value undefined; we start from opaque black.
// With RM_VIEW (render --view, the window's V key) the pixel becomes a debug
// view: nan works for any shader, the others read what shaderlib recorded.
const char* const kShadertoyMain = R"glsl(#ifdef RM_VIEW
vec4 rm_view(vec4 rm_color, vec2 rm_fragCoord) {
  bool rm_bad = any(isnan(rm_color)) || any(isinf(rm_color));
#if RM_VIEW == 4
  float rm_grey = dot(clamp(rm_color.rgb, 0.0, 1.0), vec3(0.2126, 0.7152, 0.0722));
  return rm_bad ? vec4(1.0, 0.0, 1.0, 1.0) : vec4(vec3(0.2 + 0.6 * rm_grey), 1.0);
#elif defined(RM_VIEWS_GLSL)
  return rmView(rm_color, rm_fragCoord, iResolution, rm_bad);
#else
#error "this view needs a scene that marches with shaderlib (rm/march.glsl)"
#endif
}
#endif
void main() {
  vec4 rm_color = vec4(0.0, 0.0, 0.0, 1.0);
  vec2 rm_fragCoord = gl_FragCoord.xy;
  mainImage(rm_color, rm_fragCoord);
#ifdef RM_VIEW
  rm_color = rm_view(rm_color, rm_fragCoord);
#endif
  rm_FragColor = rm_color;
})glsl";

// GLSL 1.10/1.20 and ES 1.00 names mapped onto a 4.50 core profile. The
// sampling functions are functions, not macros onto `texture`: code of those
// dialects may name a sampler `texture`, which is then renamed for the
// compiler (core/dialect_names.h), and a macro's expansion would be renamed
// with it. Their parameters are rm_ names, which no -D can reach.
const char* const kLegacyPrelude = R"glsl(#define varying in
vec4 texture2D(sampler2D rm_s, vec2 rm_p) { return texture(rm_s, rm_p); }
vec4 texture2D(sampler2D rm_s, vec2 rm_p, float rm_bias) { return texture(rm_s, rm_p, rm_bias); }
vec4 texture2DProj(sampler2D rm_s, vec3 rm_p) { return textureProj(rm_s, rm_p); }
vec4 texture2DProj(sampler2D rm_s, vec4 rm_p) { return textureProj(rm_s, rm_p); }
vec4 texture2DProj(sampler2D rm_s, vec3 rm_p, float rm_bias) { return textureProj(rm_s, rm_p, rm_bias); }
vec4 texture2DProj(sampler2D rm_s, vec4 rm_p, float rm_bias) { return textureProj(rm_s, rm_p, rm_bias); }
vec4 texture2DLod(sampler2D rm_s, vec2 rm_p, float rm_lod) { return textureLod(rm_s, rm_p, rm_lod); }
vec4 texture2DProjLod(sampler2D rm_s, vec3 rm_p, float rm_lod) { return textureProjLod(rm_s, rm_p, rm_lod); }
vec4 texture2DProjLod(sampler2D rm_s, vec4 rm_p, float rm_lod) { return textureProjLod(rm_s, rm_p, rm_lod); }
vec4 texture3D(sampler3D rm_s, vec3 rm_p) { return texture(rm_s, rm_p); }
vec4 texture3D(sampler3D rm_s, vec3 rm_p, float rm_bias) { return texture(rm_s, rm_p, rm_bias); }
vec4 texture3DLod(sampler3D rm_s, vec3 rm_p, float rm_lod) { return textureLod(rm_s, rm_p, rm_lod); }
vec4 textureCube(samplerCube rm_s, vec3 rm_p) { return texture(rm_s, rm_p); }
vec4 textureCube(samplerCube rm_s, vec3 rm_p, float rm_bias) { return texture(rm_s, rm_p, rm_bias); }
vec4 textureCubeLod(samplerCube rm_s, vec3 rm_p, float rm_lod) { return textureLod(rm_s, rm_p, rm_lod); })glsl";

// glslViewer's v_texcoord (see take_texcoord_declaration).
const char* const kTexcoord = "uniform vec2 rm_Resolution;\n#define v_texcoord (gl_FragCoord.xy / rm_Resolution)";

// Whether `line` (its comments stripped) is glslViewer's declaration of
// v_texcoord: `varying vec2 v_texcoord;`, or with `in`, or a precision.
bool declares_texcoord(std::string_view line) {
  std::vector<std::string_view> words;
  size_t at = lexing::skip_blanks(line, 0);
  while (at < line.size() && lexing::is_word_start(line[at])) {
    size_t end = at;
    while (end < line.size() && lexing::is_word_char(line[end])) ++end;
    words.push_back(line.substr(at, end - at));
    at = lexing::skip_blanks(line, end);
  }
  if (at >= line.size() || line[at] != ';' || lexing::skip_blanks(line, at + 1) != line.size()) return false;
  if (words.size() == 4 && lexing::is_precision(words[1]))
    words.erase(words.begin() + 1);
  return words.size() == 3 && (words[0] == "varying" || words[0] == "in") && words[1] == "vec2" &&
         words[2] == "v_texcoord";
}

// Every kind of shader reads gl_FragCoord through the host's offset: a tile's
// origin (render_image past the driver's size) plus a supersample's sub-pixel
// jitter (core/supersampling.h). A macro may name itself without recursion.
const char* const kFragCoordOffset = "#define gl_FragCoord (gl_FragCoord + vec4(rm_FragCoordOffset, 0.0, 0.0))";

// Whether the code redeclares gl_FragCoord (`layout(origin_upper_left) in
// vec4 gl_FragCoord;`), which the macro above would break.
bool redeclares_frag_coord(std::string_view code) {
  for (size_t at = code.find("gl_FragCoord"); at != std::string_view::npos; at = code.find("gl_FragCoord", at + 1)) {
    size_t end = at;
    while (end > 0 && lexing::is_space(code[end - 1])) --end;
    if (end >= 4 && code.substr(end - 4, 4) == "vec4") return true;
  }
  return false;
}

// The lines of a text, one at a time, in order (1-based numbers; "\r\n"
// ends a line as "\n" does, and a last "\n" starts no line of its own).
// Views: a text of 10 million lines is not copied.
class LineCursor {
 public:
  explicit LineCursor(std::string_view text) : text_(text) {}
  // Moves to the next line; false past the last.
  bool next() {
    if (next_ >= text_.size()) return false;
    size_t end = text_.find('\n', next_);
    const size_t after = end == std::string_view::npos ? text_.size() : end + 1;
    if (end == std::string_view::npos) end = text_.size();
    const size_t stop = end > next_ && text_[end - 1] == '\r' && end < text_.size() ? end - 1 : end;
    line_ = text_.substr(next_, stop - next_);
    next_ = after;
    ++number_;
    return true;
  }
  std::string_view line() const { return line_; }
  int number() const { return number_; }

 private:
  std::string_view text_;
  std::string_view line_;
  size_t next_ = 0;
  int number_ = 0;
};

// Calls line(text, number) for each line of `text` (as LineCursor reads
// them) until it returns false.
template <typename Line>
void for_each_line(std::string_view text, Line line) {
  for (LineCursor lines(text); lines.next();)
    if (!line(lines.line(), lines.number())) return;
}

// The names that sampler declarations of `code` declare (`uniform
// [precision] samplerXX NAME[, NAME...];` at the start of a line, its names
// perhaps going on over the next lines): the code's own samplers, and
// glslViewer's u_texN and u_bufferN. Each with its line (1-based) and its
// 0-based column. `code` has no comments.
struct DeclaredName {
  std::string_view name;
  int line = 0;
  size_t column = 0;
};
std::vector<DeclaredName> declared_samplers(std::string_view code) {
  // The lines are read in order, one at a time: a declaration's names go on
  // to later lines, never back (a vector of every line cost 10 million lines
  // of blanks a second).
  LineCursor lines(code);
  std::vector<DeclaredName> names;
  while (lines.next()) {
    const std::string_view line = lines.line();
    std::array<std::pair<std::string_view, size_t>, 3> words;  // the first three, with their columns
    size_t found = 0;
    lexing::any_word(line, [&](size_t begin, size_t end) {
      words[found++] = {line.substr(begin, end - begin), begin};
      return found >= words.size();
    });
    if (found < 2 || words[0].first != "uniform" || lexing::skip_blanks(line, 0) != words[0].second) continue;
    const size_t type = lexing::is_precision(words[1].first) ? 2 : 1;
    if (type >= found || words[type].first.find("sampler") > 1) continue;  // sampler2D, isampler3D
    // The declarators: names at the top level, separated by commas, up to
    // ';' (an array's size in brackets is skipped). A word where a comma
    // belongs, anything else a declarator cannot hold, or a directive's line
    // ends them too: a declaration without its ';' takes no names from the
    // code after it. A line the names went on to starts no declaration of its own.
    bool want_name = true, ended = false;
    int brackets = 0;
    size_t at = words[type].second + words[type].first.size();
    for (bool first = true; !ended && (first || lines.next()); first = false, at = 0) {
      const std::string_view text = lines.line();
      const size_t start = lexing::skip_blanks(text, 0);
      if (!first && start < text.size() && text[start] == '#') break;
      for (; at < text.size() && !ended; ++at) {
        const char c = text[at];
        if (c == '[') ++brackets;
        else if (c == ']') brackets -= brackets > 0;
        else if (brackets > 0 || lexing::is_space(c)) continue;
        else if (c == ',') want_name = true;
        else if (!want_name || !lexing::is_word_start(c)) ended = true;  // ';', or what ends a broken one
        else {
          size_t end = at;
          while (end < text.size() && lexing::is_word_char(text[end])) ++end;
          names.push_back({text.substr(at, end - at), lines.number(), at});
          want_name = false;
          at = end - 1;
        }
      }
    }
  }
  return names;
}

int count_word(std::string_view text, std::string_view word) {
  int count = 0;
  lexing::any_word(text, [&](size_t begin, size_t end) {
    count += text.substr(begin, end - begin) == word;
    return false;
  });
  return count;
}

// Whether a directive of `code` (#if, #ifdef, #elif, ...) names `macro`.
bool tests_macro(std::string_view code, std::string_view macro) {
  bool found = false;
  for_each_line(code, [&](std::string_view line, int) {
    const size_t at = lexing::skip_blanks(line, 0);
    found = at < line.size() && line[at] == '#' && line.find("if", at) != std::string_view::npos &&
            lexing::has_word(line, macro);
    return !found;
  });
  return found;
}

struct IncludeDirective {
  bool angled = false;
  std::string target;
  int column = 0;  // 1-based column of the opening quote
};

struct ChannelPragma {
  int channel = -1;
  int column = 0;         // 1-based column of "#"
  std::string_view spec;  // what follows "channelN"
};

// `"FILE"` (or `<FILE>` when angled brackets are allowed) and nothing after
// it but a comment: the file's name, or nullopt.
std::optional<std::string> quoted_name(std::string_view rest, bool allow_angled, bool* angled) {
  if (rest.empty()) return std::nullopt;
  const char close = rest[0] == '"' ? '"' : (allow_angled && rest[0] == '<') ? '>' : '\0';
  if (!close) return std::nullopt;
  const size_t end = rest.find(close, 1);
  if (end == std::string_view::npos || end == 1 || !lexing::nothing_but_comment(rest.substr(end + 1)))
    return std::nullopt;
  *angled = close == '>';
  return std::string(rest.substr(1, end - 1));
}

// `#pragma channelN ...`: what iChannelN reads (core/channel_spec.h). Other
// pragmas are the compiler's. *malformed is set for N outside 0..3.
std::optional<ChannelPragma> parse_channel_pragma(std::string_view line, bool* malformed) {
  *malformed = false;
  auto d = lexing::directive(line);
  constexpr std::string_view kChannel = "channel";
  if (!d || d->name != "pragma" || d->rest.substr(0, kChannel.size()) != kChannel) return std::nullopt;
  size_t digits_end = kChannel.size();
  while (digits_end < d->rest.size() && lexing::is_digit(d->rest[digits_end])) ++digits_end;
  const size_t digits = digits_end - kChannel.size();
  if (digits == 0 || (digits_end < d->rest.size() && lexing::is_word_char(d->rest[digits_end]))) return std::nullopt;
  ChannelPragma pragma;
  pragma.column = static_cast<int>(d->hash) + 1;
  const char n = d->rest[kChannel.size()];
  if (digits != 1 || n > '3') {
    *malformed = true;
    return pragma;
  }
  pragma.channel = n - '0';
  pragma.spec = d->rest.substr(digits_end);
  return pragma;
}

std::optional<IncludeDirective> parse_include(std::string_view line, bool* malformed) {
  *malformed = false;
  auto d = lexing::directive(line);
  if (!d || d->name != "include") return std::nullopt;
  IncludeDirective inc;
  inc.column = static_cast<int>(d->rest_at) + 1;
  auto target = quoted_name(d->rest, /*allow_angled*/ true, &inc.angled);
  if (!target) {
    *malformed = true;
    inc.target = std::string(d->rest);
    return inc;
  }
  inc.target = *target;
  return inc;
}

// The line of `code` (comments blanked) whose `#ifndef NAME` opens an include
// guard: it is the first directive, and `#define NAME` the next. 0: none.
int include_guard_line(std::string_view code) {
  int guard_line = 0;
  std::string_view guard;
  for_each_line(code, [&](std::string_view line, int number) {
    const auto d = lexing::directive(line);
    if (!d) return true;
    if (guard.empty()) {
      const std::string_view name = d->rest.substr(0, d->rest.find_first_of(" \t\r\\"));
      if (d->name != "ifndef" || !lexing::is_name(name)) return false;
      guard = name, guard_line = number;
      return true;
    }
    if (d->name != "define" || lexing::defined_macro(line) != guard) guard_line = 0;
    return false;
  });
  return guard.empty() ? 0 : guard_line;
}

struct VersionInfo {
  int number = 0;
  std::string profile;  // "core", "es", "compatibility" or ""
  bool modern() const { return number >= 130 && number != 100; }
  bool es() const { return profile == "es"; }
};

std::optional<VersionInfo> parse_version(std::string_view line) {
  auto d = lexing::directive(line);
  if (!d || d->name != "version") return std::nullopt;
  // At most 9 digits: every version fits an int (a longer one is left for
  // glslang to reject at its line).
  const std::string_view rest = d->rest;
  size_t at = 0;
  while (at < rest.size() && lexing::is_digit(rest[at])) ++at;
  if (at == 0 || at > 9) return std::nullopt;
  VersionInfo version{std::stoi(std::string(rest.substr(0, at))), ""};
  at = lexing::skip_blanks(rest, at);
  const size_t profile_at = at;
  while (at < rest.size() && rest[at] >= 'a' && rest[at] <= 'z') ++at;
  version.profile = std::string(rest.substr(profile_at, at - profile_at));
  if (!lexing::nothing_but_comment(rest.substr(at))) return std::nullopt;
  return version;
}

class Preprocessor {
 public:
  Preprocessor(const SourceOptions& options, const FileSystem& files)
      : options_(options),
        fs_(files),
        shaderlib_dir_(options.shaderlib_dir.empty() ? fs::path() : fs::absolute(options.shaderlib_dir).lexically_normal()) {}

  Source run(const fs::path& scene) {
    fs::path first = fs::absolute(scene).lexically_normal();
    if (std::optional<GlslViewerPass> pass = glslviewer_pass_of(first)) {
      first = pass->file;
      pass_define_ = pass->define;
      glslviewer_pass_ = true;
    }
    out_.watch.push_back(first);
    include_file(first, /*from*/ -1, 0, 0);
    if (!out_.ok()) return std::move(out_);
    assemble();
    return std::move(out_);
  }

 private:
  void error(int file, int line, int column, std::string message) {
    out_.errors.push_back(diagnostic(file, line, column, std::move(message)));
  }
  Diagnostic diagnostic(int file, int line, int column, std::string message) const {
    Diagnostic d;
    d.path = file >= 0 ? out_.files[static_cast<size_t>(file)].string() : std::string();
    d.line = line;
    d.column = column;
    d.message = std::move(message);
    return d;
  }

  std::optional<fs::path> resolve(const IncludeDirective& inc, const fs::path& including_dir,
                                  fs::path* first_candidate) {
    std::vector<fs::path> candidates;
    if (!inc.angled) candidates.push_back(including_dir / inc.target);
    for (const auto& dir : options_.include_dirs) candidates.push_back(dir / inc.target);
    if (!options_.shaderlib_dir.empty()) candidates.push_back(options_.shaderlib_dir / inc.target);
    if (candidates.empty()) return std::nullopt;
    *first_candidate = fs::absolute(candidates.front()).lexically_normal();
    for (const auto& c : candidates)
      if (fs_.exists(c)) return fs::absolute(c).lexically_normal();
    return std::nullopt;
  }

  // A file's text as the compiler reads it, and the same with its comments
  // blanked, line for line and column for column (a directive inside a /* */
  // comment is no directive). Read once, however often it is included.
  struct FileText {
    std::string text, code;
    std::uintmax_t bytes = 0;  // on disk
    bool has_nul = false;      // not a text file
    // The line of the `#ifndef NAME` of an include guard (`#define NAME`
    // next), which is taken at the file's first include: the includes inside
    // it are not in an #if branch of the includer's. 0: no guard.
    int guard_line = 0;
  };

  // Reads one file and appends its lines, expanding includes in place.
  void include_file(const fs::path& path, int from_file, int from_line, int from_col) {
    Diagnostic why;
    const FileText* read = file_text(path, &why);
    const std::uintmax_t bytes = read ? read->bytes : 0;
    if (read && total_bytes_ + bytes > kMaxShaderBytes) {
      why = {};
      why.message = "the scene with its includes would be " + over_the_limit(total_bytes_ + bytes).substr(3);
      read = nullptr;
    }
    if (!read) {
      const int file = from_file < 0 ? add_file(path) : -1;
      if (!why.path.empty()) {
        out_.errors.push_back(std::move(why));  // where the cause is: the JSON's line
      } else if (from_file < 0) {
        out_.errors.push_back(scene_unreadable(out_.files[static_cast<size_t>(file)].string(), why.message));
      } else {
        // Missing, or not a file, it is the shader's error; a machine's
        // failure (no descriptor left) leaves the shader unchecked.
        Diagnostic cannot =
            diagnostic(from_file, from_line, from_col, "cannot read include '" + path.string() + "': " + why.message);
        cannot.unchecked = why.unchecked;
        if (in_branch() && !why.unchecked) error_where_taken(std::move(cannot), Origin{from_file, from_line});
        else out_.errors.push_back(std::move(cannot));
      }
      return;
    }
    total_bytes_ += bytes;
    const std::string& text = read->text;
    if (read->has_nul) {
      Diagnostic binary = diagnostic(add_file(path), 0, 0, "not a text file (it contains NUL bytes)");
      if (from_file >= 0 && in_branch()) error_where_taken(std::move(binary), Origin{from_file, from_line});
      else out_.errors.push_back(std::move(binary));
      return;
    }

    int file = add_file(path);
    stack_.push_back(file);
    if (from_file < 0)
      for (const std::string& name : options_.forced_includes)
        if (!include(path, file, 0, IncludeDirective{false, name, 0})) break;
    for_each_line(text, [&](std::string_view line, int line_no) {
      const std::string_view code_line(read->code.data() + (line.data() - text.data()), line.size());
      return take_line(path, file, line, code_line, line_no, line_no == read->guard_line);
    });
    in_dropped_define_ = false;  // a file's last line does not continue into the next file
    stack_.pop_back();
  }

  const FileText* file_text(const fs::path& path, Diagnostic* why) {
    if (auto known = texts_.find(path.string()); known != texts_.end()) return &known->second;
    std::optional<std::string> bytes = fs_.read(path, why);
    if (!bytes) return nullptr;
    FileText read{std::move(*bytes), {}, 0};
    std::string& text = read.text;
    read.bytes = text.size();
    read.has_nul = text.find('\0') != std::string::npos;
    if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);
    // GLSL counts form feed and vertical tab as blanks, but glslang rejects
    // them: they become spaces, so lines and columns stay where they were.
    std::replace_if(text.begin(), text.end(), [](char c) { return c == '\f' || c == '\v'; }, ' ');
    // GLSL ends a line at a carriage return alone too (old Mac files), but
    // glslang reads such a file as one line: each becomes a newline.
    for (size_t at = text.find('\r'); at != std::string::npos; at = text.find('\r', at + 1))
      if (at + 1 == text.size() || text[at + 1] != '\n') text[at] = '\n';
    read.code = lexing::strip_comments(text);
    read.guard_line = include_guard_line(read.code);
    return &texts_.emplace(path.string(), std::move(read)).first->second;
  }

  bool defined_on_command_line(std::string_view name) const {
    return std::any_of(options_.defines.begin(), options_.defines.end(), [&](const Define& d) { return d.name == name; });
  }

  // Shadertoy's HW_PERFORMANCE: 1, as on a desktop, unless a -D sets it (0 is
  // what a phone gets; shaders use it to choose their antialiasing). The
  // window gives a renderer on the CPU 0 by a -D (core/hw_performance.h).
  std::string hw_performance_define() const {
    return defined_on_command_line("HW_PERFORMANCE") ? std::string() : "#define HW_PERFORMANCE 1\n";
  }

  // Whether `line` of `file` is a #define of a macro the options set (a -D)
  // or forbid (a -U). A -U reaches the scene's own files only: shaderlib's
  // defaults (#ifndef RM_MAX_STEPS ...) then hold, as without the scene's #define.
  bool defines_overridden_macro(std::string_view line, int file) const {
    const std::optional<std::string_view> name = lexing::defined_macro(line);
    if (!name) return false;
    if (defined_on_command_line(*name)) return true;
    return std::find(options_.undefines.begin(), options_.undefines.end(), *name) != options_.undefines.end() &&
           !is_under(out_.files[static_cast<size_t>(file)], shaderlib_dir_);
  }

  // One line of `file`: kept for the body, or a directive the host handles.
  // false stops reading the file (after an error).
  // `code` is `line` with its comments blanked; `guard` says it opens the file's include guard.
  bool take_line(const fs::path& path, int file, std::string_view line, std::string_view code, int line_no,
                 bool guard) {
    if (!out_.ok()) return false;
    // A #define the command line overrides is read as a blank line, with
    // the lines its backslashes continue it onto: lines keep their numbers.
    if (in_dropped_define_ || defines_overridden_macro(line, file)) {
      in_dropped_define_ = !line.empty() && line.back() == '\\';
      add_body_line("", Origin{file, line_no});
      return true;
    }
    const std::optional<lexing::Directive> directive = lexing::directive(code);
    if (!directive) {  // code, or a line of a comment
      add_body_line(line, Origin{file, line_no});
      return true;
    }
    count_conditional(directive->name, guard);
    if (file == 0 && !version_ && (version_ = parse_version(line))) {
      version_origin_ = Origin{file, line_no};
      return true;  // re-emitted at the top by assemble()
    }
    bool malformed = false;
    if (auto pragma = parse_channel_pragma(line, &malformed)) {
      ChannelPragmaLine seen{body_map_.size(), in_branch(), pragma->channel, std::nullopt, {}};
      std::string why;
      seen.spec = malformed ? std::nullopt : parse_channel_spec(pragma->spec, path.parent_path(), &why);
      if (!seen.spec) {
        seen.problem = diagnostic(file, line_no, pragma->column,
                                  "#pragma channelN " + (malformed ? std::string("expects N in 0..3") : why));
      } else if (const fs::path& named = seen.spec->path; !named.empty()) {
        out_.watch.push_back(named);
        if (seen.spec->kind == ChannelSpec::Kind::Image && seen.spec->shape == ChannelSpec::Shape::Cube)
          for (const fs::path& face : cube_face_files(named, fs_.exists))
            if (face != named) out_.watch.push_back(face);
        if (!fs_.exists(named)) {
          const char* what = seen.spec->kind == ChannelSpec::Kind::Pass ? "buffer pass" : "channel image";
          seen.problem = diagnostic(file, line_no, pragma->column,
                                    std::string("cannot find ") + what + " '" +
                                        quoted_path(named.lexically_relative(path.parent_path()).string()) + "'");
          seen.spec.reset();
        }
      }
      if (!seen.spec && !seen.in_branch) {
        out_.errors.push_back(std::move(seen.problem));
        return false;
      }
      add_body_line("", Origin{file, line_no});  // the driver never sees it; lines keep their numbers
      channel_pragmas_.push_back(std::move(seen));
      return true;
    }
    auto inc = parse_include(line, &malformed);
    if (!inc) {
      add_body_line(line, Origin{file, line_no});
      return true;
    }
    if (malformed) {
      error(file, line_no, inc->column, "#include expects \"FILE\" or <FILE>");
      return false;
    }
    return include(path, file, line_no, *inc);
  }

  // Expands `inc`, met at `line_no` of `file` (at `path`). false after an error.
  bool include(const fs::path& path, int file, int line_no, const IncludeDirective& inc) {
    if (stack_.size() >= kMaxIncludeDepth) {
      error(file, line_no, inc.column,
            "#include nested too deeply (more than " + std::to_string(kMaxIncludeDepth) + " levels)");
      return false;
    }
    fs::path first_candidate;
    auto target = resolve(inc, path.parent_path(), &first_candidate);
    const bool conditional = in_branch();
    if (!target) {
      if (!first_candidate.empty()) out_.watch.push_back(first_candidate);
      const std::string missing = "cannot find include '" + quoted_path(inc.target) + "'";
      if (!conditional) {
        error(file, line_no, inc.column, missing);
        return false;
      }
      error_where_taken(diagnostic(file, line_no, inc.column, missing), Origin{file, line_no});
      return true;
    }
    auto existing = file_index_.find(target->string());
    if (existing != file_index_.end()) {
      for (size_t s = 0; s < stack_.size(); ++s) {
        if (stack_[s] != existing->second) continue;
        std::string chain;
        for (size_t k = s; k < stack_.size(); ++k)
          chain += out_.files[static_cast<size_t>(stack_[k])].filename().string() + " -> ";
        error(file, line_no, inc.column, "#include cycle: " + chain + target->filename().string());
        return false;
      }
      if (included_for_certain_.count(existing->second)) return true;  // once in a compile: nothing to add
    } else {
      out_.watch.push_back(*target);
    }
    auto included_for_certain = [&] {
      if (auto known = file_index_.find(target->string()); known != file_index_.end())
        included_for_certain_.insert(known->second);
    };
    if (!conditional && existing == file_index_.end()) {
      include_file(*target, file, line_no, inc.column);
      included_for_certain();
      return true;
    }
    // Included in an #if branch, or after one: the compiler's first include
    // of it that it takes holds the text, the rest are skipped.
    const std::string guard = "RM_INCLUDED_" + std::to_string(add_file(*target));
    add_body_line("#ifndef " + guard, Origin{file, line_no});
    add_body_line("#define " + guard, Origin{file, line_no});
    open_conditionals_.push_back(true);
    include_file(*target, file, line_no, inc.column);
    if (!open_conditionals_.empty()) open_conditionals_.pop_back();  // as the #endif below does
    add_body_line("#endif", Origin{file, line_no});
    if (!conditional) included_for_certain();
    return true;
  }

  // Follows the #if blocks open where a line is, across the files, as the
  // compiler reads the text. An include guard's is open but no branch.
  void count_conditional(std::string_view directive, bool guard) {
    if (directive == "if" || directive == "ifdef" || directive == "ifndef") open_conditionals_.push_back(!guard);
    else if (directive == "endif" && !open_conditionals_.empty()) open_conditionals_.pop_back();
  }
  // An include's `problem` in an #if branch, which the compiler may not
  // take: an #error in its place, at `at`, that the compiler meets only if
  // it does, and names `problem` then (check.cpp's missing_include()).
  void error_where_taken(Diagnostic problem, Origin at) {
    add_body_line("#error " + std::string(kMissingIncludeMark) + std::to_string(out_.missing_includes.size()), at);
    out_.missing_includes.push_back(std::move(problem));
  }

  // Whether the line being read is in an #if branch the compiler may not take.
  bool in_branch() const {
    return std::find(open_conditionals_.begin(), open_conditionals_.end(), true) != open_conditionals_.end();
  }

  // The index of `path` in out_.files, which lists each file once.
  int add_file(const fs::path& path) {
    if (auto known = file_index_.find(path.string()); known != file_index_.end()) return known->second;
    out_.files.push_back(path);
    const int index = static_cast<int>(out_.files.size()) - 1;
    file_index_.emplace(path.string(), index);
    return index;
  }

  void add_body_line(std::string_view text, Origin origin) {
    body_ += text;
    body_ += '\n';
    body_map_.push_back(origin);
  }

  void emit(std::string_view text, Origin origin) {
    out_.text += text;
    out_.text += '\n';
    out_.line_map.push_back(origin);
  }

  void emit_host(std::string_view block) {
    for_each_line(block, [&](std::string_view line, int) {
      emit(line, Origin{kHostFile, ++host_lines_});
      return true;
    });
  }

  // GLSL wants each #extension before the code's first token that is not
  // the preprocessor's, and the host's declarations come first in the final
  // text: the #extension lines that open the code, outside any #if, are
  // taken from the body (each leaves a blank line) to follow the #version.
  // `code` is the body, its comments stripped.
  std::vector<std::pair<std::string, Origin>> take_leading_extensions(std::string_view code) {
    std::vector<size_t> taken;  // line indices
    int depth = 0;              // of #if blocks
    for_each_line(code, [&](std::string_view line, int number) {
      if (const auto d = lexing::directive(line)) {
        if (d->name == "if" || d->name == "ifdef" || d->name == "ifndef") ++depth;
        else if (d->name == "endif") --depth;
        else if (d->name == "extension" && depth == 0) taken.push_back(static_cast<size_t>(number - 1));
        return true;
      }
      return lexing::skip_blanks(line, 0) == line.size();  // stop at the code's first token
    });
    return take_body_lines(taken);
  }

  // The body's lines at `indices` (ascending), each left blank in its place.
  std::vector<std::pair<std::string, Origin>> take_body_lines(const std::vector<size_t>& indices) {
    std::vector<std::pair<std::string, Origin>> out;
    if (indices.empty()) return out;
    std::string body;
    body.reserve(body_.size());
    size_t next = 0;
    for_each_line(body_, [&](std::string_view line, int number) {
      const bool take = next < indices.size() && indices[next] == static_cast<size_t>(number - 1);
      if (take) out.emplace_back(std::string(line), body_map_[indices[next++]]);
      body += take ? std::string_view() : line;
      body += '\n';
      return true;
    });
    body_ = std::move(body);
    return out;
  }

  // glslViewer's vertex shader hands its fragment shader v_texcoord, the
  // pixel's place in the picture from 0 to 1. The host draws with no
  // vertex attributes: the declaration (`varying vec2 v_texcoord;`) is
  // taken out, and the name reads gl_FragCoord, which tiles and supersamples
  // move; so does v_texcoord with it. Whether `body_code` (the body, its
  // comments stripped; lines taken since are no declarations) declared it.
  bool take_texcoord_declaration(std::string_view body_code) {
    std::vector<size_t> found;
    for_each_line(body_code, [&](std::string_view line, int number) {
      if (declares_texcoord(line)) found.push_back(static_cast<size_t>(number - 1));
      return found.empty();
    });
    take_body_lines(found);
    return !found.empty();
  }

  // Binds the channels the #pragma channelN lines name, in the order of the
  // text. One in an #if branch binds only where the compiler takes that
  // branch (and its missing file is an error only there): the compiler's
  // preprocessor keeps the mark compiler_input() puts on its line where it
  // takes it. false after an error.
  bool bind_channel_pragmas() {
    std::vector<bool> taken(channel_pragmas_.size(), true);
    if (std::any_of(channel_pragmas_.begin(), channel_pragmas_.end(), [](const auto& p) { return p.in_branch; })) {
      const std::optional<std::string>& active = preprocessed(compiler_input());
      // The compiler's lines keep their places: the body's line n is the
      // active text's line n after those of the defines.
      LineCursor lines(active ? std::string_view(*active) : std::string_view());
      const std::string defines = defines_text();
      const int skipped = static_cast<int>(std::count(defines.begin(), defines.end(), '\n'));
      bool more = true;
      for (size_t i = 0; i < channel_pragmas_.size(); ++i) {
        if (!channel_pragmas_[i].in_branch) continue;
        const int wanted = skipped + static_cast<int>(channel_pragmas_[i].body_line) + 1;
        while (more && lines.number() < wanted) more = lines.next();
        // A branch the compiler does not take (or its preprocessor fails, and says why).
        taken[i] = more && lines.line().find(kChannelPragmaMark) != std::string_view::npos;
      }
    }
    for (size_t i = 0; i < channel_pragmas_.size(); ++i) {
      const ChannelPragmaLine& pragma = channel_pragmas_[i];
      if (!taken[i]) continue;
      if (!pragma.spec) {
        out_.errors.push_back(pragma.problem);
        return false;
      }
      out_.channels[static_cast<size_t>(pragma.channel)] = *pragma.spec;
    }
    return true;
  }

  // What the compiler's preprocessor is asked to read: defines_text(), then
  // the body, with a mark on the line of each #pragma channelN in an #if
  // branch (a word alone on a line that is blank otherwise, which nothing
  // the host looks for reads).
  std::string compiler_input() {
    std::string text = defines_text();
    text.reserve(text.size() + body_.size() + kChannelPragmaMark.size() * channel_pragmas_.size());
    auto pragma = channel_pragmas_.begin();
    for_each_line(body_, [&](std::string_view line, int number) {
      text += line;
      if (pragma != channel_pragmas_.end() && pragma->body_line == static_cast<size_t>(number - 1)) {
        if (pragma->in_branch) text += kChannelPragmaMark;
        ++pragma;
      }
      text += '\n';
      return true;
    });
    return text;
  }

  // active_code() of `input`, asked of glslang's worker once for the same
  // text: the channel pragmas, the kind and glslViewer's samplers may each
  // need it, and each ask is a round trip to the worker. The answers stay
  // where they are until the source is assembled.
  const std::optional<std::string>& preprocessed(std::string input) {
    for (const auto& [asked, active] : preprocessed_)
      if (asked == input) return active;
    std::optional<std::string> active = active_code(input, kHostVersionLine);
    return preprocessed_.emplace_back(std::move(input), std::move(active)).second;
  }

  void assemble() {
    if (!bind_channel_pragmas()) return;
    // The body's code, line for line: what the host looks for is read here.
    const std::string body_code = lexing::strip_comments(body_);
    std::string_view code = body_code;  // or the preprocessor's text, where that decides the kind
    bool has_main = lexing::has_call(code, "main", "void");
    bool has_main_image = lexing::has_call(code, "mainImage");
    const bool has_main_cubemap = lexing::has_call(code, "mainCubemap");
    const bool modern = version_ && version_->modern();
    // Real Shadertoy shaders carry a main() for other hosts in an inactive
    // #ifdef: with both, the kind is decided on what the compiler would see.
    if (has_main && has_main_image) {
      if (const std::optional<std::string>& text = preprocessed(compiler_input())) {
        code = *text;
        has_main = lexing::has_call(code, "main", "void");
        has_main_image = lexing::has_call(code, "mainImage");
      }
    }

    if (has_main_cubemap && !has_main_image && !has_main) {
      out_.kind = ShaderKind::Shadertoy;
      out_.cubemap = true;
      // A cube pass that reads itself reads a cube map.
      for (ChannelSpec& c : out_.channels)
        if (c.kind == ChannelSpec::Kind::Self) c.shape = ChannelSpec::Shape::Cube;
    } else if (has_main_image && !has_main) {
      out_.kind = ShaderKind::Shadertoy;
    } else if (has_main && modern) {
      out_.kind = ShaderKind::Complete;
    } else if (has_main) {
      out_.kind = ShaderKind::Legacy;
    } else {
      error(0, 0, 0, "defines neither mainImage(out vec4, in vec2) nor main() (nor mainCubemap, for a cube pass)");
      return;
    }

    // glslViewer draws a shader with a POSTPROCESSING branch so on screen,
    // over its scene pass (core/glslviewer_passes.h).
    postprocessed_ = out_.kind != ShaderKind::Shadertoy && tests_macro(body_code, kPostprocessing);
    if (postprocessed_ && !glslviewer_pass_) pass_define_ = kPostprocessing;

    out_.text.reserve(body_.size() + 4096);
    out_.line_map.reserve(body_map_.size() + 128);
    const bool keep_version = modern;
    out_.version_line = keep_version
        ? "#version " + std::to_string(version_->number) + (version_->profile.empty() ? "" : " " + version_->profile)
        : kHostVersionLine;
    emit(out_.version_line, keep_version ? version_origin_ : Origin{kHostFile, ++host_lines_});
    for (const auto& [line, origin] : take_leading_extensions(body_code)) emit(line, origin);
    if (const std::string line = hw_performance_define(); !line.empty()) emit_host(line);
    int define_index = 0;
    for (const auto& d : options_.defines)
      emit("#define " + d.name + " " + (d.value.empty() ? "1" : d.value), Origin{kCommandLineFile, ++define_index});
    if (!pass_define_.empty()) emit_host("#define " + pass_define_);
    if (keep_version && version_->es()) emit_host("precision highp float;\nprecision highp int;");

    if (out_.kind == ShaderKind::Shadertoy) {
      emit_host(shadertoy_prelude(out_.channels));
      emit_host(kFragCoordOffset);
    } else {
      bool texcoord = false;
      if (out_.kind == ShaderKind::Legacy) {
        emit_host(kLegacyPrelude);
        if (lexing::has_word(code, "gl_FragColor")) emit_host("#define gl_FragColor rm_FragColor\nout vec4 rm_FragColor;");
        if ((texcoord = take_texcoord_declaration(body_code))) emit_host(kTexcoord);
      }
      out_.movable_frag_coord = !redeclares_frag_coord(code);
      if ((texcoord || lexing::has_word(code, "gl_FragCoord")) && out_.movable_frag_coord)
        emit_host(std::string("uniform vec2 rm_FragCoordOffset;\n") + kFragCoordOffset);
    }
    if (out_.kind != ShaderKind::Complete) {
      out_.renamed =
          names_core_reserves(code, out_.kind == ShaderKind::Shadertoy ? Dialect::EsSl300 : Dialect::Glsl110);
      for (const std::string& word : out_.renamed) emit_host("#define " + word + " " + compiler_name(word));
    }
    out_.text += body_;
    out_.line_map.insert(out_.line_map.end(), body_map_.begin(), body_map_.end());
    if (out_.kind == ShaderKind::Shadertoy) emit_host(out_.cubemap ? kCubemapMain : kShadertoyMain);
    else bind_glslviewer_passes(body_code);
  }

  // The lines the compiler's text starts with, before the body: what decides
  // its #if branches.
  std::string defines_text() const {
    std::string text = std::string(kHostVersionLine) + "\n" + hw_performance_define();
    for (const auto& d : options_.defines) text += "#define " + d.name + " " + (d.value.empty() ? "1" : d.value) + "\n";
    if (!pass_define_.empty()) text += "#define " + pass_define_ + "\n";
    return text;
  }

  // glslViewer's passes (core/glslviewer_passes.h): each of their samplers
  // that this pass's code reads, in the #if branches its defines take, is
  // bound on a channel the code leaves free (from 3 down) to the pass that
  // draws the file with that sampler's define (u_scene: with none, and only
  // in a file with a POSTPROCESSING branch, as glslViewer binds it).
  void bind_glslviewer_passes(std::string_view body_code) {
    struct Declared {
      std::string name;
      Origin at;       // its declaration's line
      int column = 0;  // 1-based
      BufferSize size;
    };
    std::vector<Declared> declared;
    for (const DeclaredName& d : declared_samplers(body_code)) {
      if (glslviewer_pass_read_by(d.name).empty() || (d.name == "u_scene" && !postprocessed_)) continue;
      const Origin at = body_map_[static_cast<size_t>(d.line - 1)];
      declared.push_back({std::string(d.name), at, static_cast<int>(d.column) + 1, {}});
      if (d.name != "u_scene") declared.back().size = size_after(d, at);
    }
    if (declared.empty()) return;
    const std::optional<std::string>& active = preprocessed(compiler_input());
    const std::string_view reads = active ? std::string_view(*active) : body_code;
    auto free_channel = [&]() -> int {
      for (int c = 3; c >= 0; --c)
        if (out_.channels[static_cast<size_t>(c)].kind == ChannelSpec::Kind::None &&
            !lexing::has_word(body_code, "u_tex" + std::to_string(c)) &&
            !lexing::has_word(body_code, "iChannel" + std::to_string(c)))
          return c;
      return -1;
    };
    const fs::path file = out_.files.front();
    for (const Declared& d : declared) {
      if (count_word(reads, d.name) < 2) continue;  // declared, and not read here
      const int channel = free_channel();
      if (channel < 0) {
        error(d.at.file, d.at.line, d.column,
              "'" + d.name + "' is read, and glslViewer's " + glslviewer_pass_read_by(d.name) +
                  " pass it reads needs a channel of its own, but the code takes all four (iChannel0-3, u_tex0-3 "
                  "and #pragma channelN)");
        continue;
      }
      out_.channels[static_cast<size_t>(channel)] =
          ChannelSpec{ChannelSpec::Kind::Pass, ChannelSpec::Shape::Flat,
                      glslviewer_pass(file, glslviewer_pass_read_by(d.name)),
                      Sampler{Sampler::Filter::Linear, Sampler::Wrap::Clamp, false}, 0, d.name, d.size};
    }
  }

  // glslViewer's size of a buffer, in a comment after its declaration:
  // `uniform sampler2D u_buffer0; // 512x512` (fixed) or `// 0.5` (a share
  // of the picture's). A comment that starts with a number is read as one.
  BufferSize size_after(const DeclaredName& d, Origin at) {
    std::string_view line;
    for_each_line(body_, [&](std::string_view text, int number) {
      if (number == d.line) line = text;
      return number < d.line;
    });
    size_t i = lexing::skip_blanks(line, d.column + d.name.size());
    if (i >= line.size() || line[i] != ';') return {};
    i = lexing::skip_blanks(line, i + 1);
    if (line.substr(i, 2) != "//") return {};
    i = lexing::skip_blanks(line, i + 2);
    const size_t end = std::min(line.find_first_of(" \t\r", i), line.size());
    const std::string_view token = line.substr(i, end - i);
    if (token.empty() || !(lexing::is_digit(token[0]) || token[0] == '.')) return {};
    std::string why;
    if (std::optional<BufferSize> size = parse_buffer_size(token, token.find('x') != std::string_view::npos, &why))
      return *size;
    error(at.file, at.line, static_cast<int>(i) + 1,
          "the size of '" + std::string(d.name) + "' after its declaration is WxH (each from 1 to " +
              std::to_string(BufferSize::kMaxSide) + ") or a share of the picture's (above 0, at most 1), not '" +
              brief(token) + "'");
    return {};
  }

  const SourceOptions& options_;
  const FileSystem& fs_;
  const fs::path shaderlib_dir_;  // absolute: the files shaderlib's, which a -U leaves alone
  Source out_;
  std::uintmax_t total_bytes_ = 0;  // of every file read, held to kMaxShaderBytes
  std::unordered_map<std::string, int> file_index_;  // path -> index in out_.files
  std::unordered_set<int> included_for_certain_;     // files included outside any #if
  std::unordered_map<std::string, FileText> texts_;  // path -> the file's text, read once
  // Each #pragma channelN line read, in the order of the text: one in an #if
  // branch is bound once the compiler's preprocessor says it takes it.
  struct ChannelPragmaLine {
    size_t body_line;  // its index in body_
    bool in_branch;
    int channel;
    std::optional<ChannelSpec> spec;  // nullopt: `problem` says why
    Diagnostic problem;
  };
  std::vector<ChannelPragmaLine> channel_pragmas_;
  std::deque<std::pair<std::string, std::optional<std::string>>> preprocessed_;  // inputs, and their active_code()
  std::vector<bool> open_conditionals_;              // each #if block open: whether it is a branch
  std::vector<int> stack_;
  std::string body_;             // the user's lines, includes expanded, each ending in '\n'
  std::vector<Origin> body_map_;  // where each line of body_ came from
  std::optional<VersionInfo> version_;
  Origin version_origin_;
  int host_lines_ = 0;
  bool in_dropped_define_ = false;  // the last line was a dropped #define ending in a backslash
  std::string pass_define_;       // a glslViewer pass's (BUFFER_0, POSTPROCESSING), or empty
  bool glslviewer_pass_ = false;  // the scene is a path glslviewer_pass() made
  bool postprocessed_ = false;    // it has a POSTPROCESSING branch: u_scene reads its scene pass
};

}  // namespace

const char* to_string(ShaderKind kind) {
  switch (kind) {
    case ShaderKind::Shadertoy: return "shadertoy";
    case ShaderKind::Complete: return "complete";
    case ShaderKind::Legacy: return "legacy";
  }
  return "?";
}

FileSystem disk_file_system() {
  FileSystem disk;
  disk.read = [](const fs::path& path, Diagnostic* why) {
    return read_shader_file(path, &why->message, &why->unchecked);
  };
  disk.exists = [](const fs::path& path) {
    std::error_code ec;
    return fs::exists(path, ec);
  };
  return disk;
}

std::pair<std::string, int> Source::locate(int final_line) const {
  if (final_line < 1 || static_cast<size_t>(final_line) > line_map.size()) return {"", 0};
  const Origin& o = line_map[static_cast<size_t>(final_line) - 1];
  if (o.file == kCommandLineFile) return {"<command-line>", o.line};
  if (o.file < 0) return {"", 0};  // a host line: the caller attributes it to the scene
  return {files[static_cast<size_t>(o.file)].string(), o.line};
}

std::string Source::final_line_text(int final_line) const {
  if (final_line < 1) return "";
  size_t start = 0;
  for (int i = 1; i < final_line; ++i) {
    start = text.find('\n', start);
    if (start == std::string::npos) return "";
    ++start;
  }
  size_t end = text.find('\n', start);
  return text.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

Source preprocess(const fs::path& scene, const SourceOptions& options, const FileSystem& files) {
  return Preprocessor(options, files).run(scene);
}

namespace {

// A sampler the scene's own code declares that no channel binds
// (`uniform sampler2D u_buffer0;`), at its name.
struct StraySampler {
  std::string name;
  int line = 0;      // in the final text
  int channel = -1;  // glslViewer's u_texN with nothing bound: N
};

// What a read of a sampler no channel binds gets, and why: glslViewer's
// scene samplers read a pass that only a POSTPROCESSING branch has, and a
// depth that no model drawn here has.
std::string stray_sampler_message(const std::string& name) {
  if (name == "u_scene")
    return "'u_scene' is read, but it is glslViewer's scene pass, which only a POSTPROCESSING pass reads "
           "(#ifdef POSTPROCESSING), so it reads black";
  if (name == "u_sceneDepth")
    return "'u_sceneDepth' is read, but the host draws no model, so there is no depth and it reads black";
  return "'" + name + "' is read, but the host binds nothing to it, so it reads black (it binds iChannel0-3 "
         "and u_tex0-3, to what #pragma channelN \"FILE\" names)";
}

}  // namespace

Diagnostics unbound_channel_reads(const Source& source, const std::array<bool, 4>& bound, std::string_view active) {
  Diagnostics out;
  const std::string code = lexing::strip_comments(source.text);  // with the file's columns
  // `expanded`: the line as the preprocessor gave it, where `name` is read.
  // A read through a macro is placed at the macro: the first word of the
  // line that the expansion replaced.
  auto warn_at = [&](int number, const std::string& name, std::string message, std::string_view expanded = {}) {
    auto [path, at_line] = source.locate(number);
    std::string_view line;
    for_each_line(code, [&](std::string_view text, int n) {
      if (n == number) line = text;
      return n < number;
    });
    std::optional<size_t> column = lexing::find_word(line, name);
    if (!column && !expanded.empty())
      lexing::any_word(line, [&](size_t begin, size_t end) {
        if (lexing::has_word(expanded, line.substr(begin, end - begin))) return false;
        column = begin;
        return true;
      });
    Diagnostic d;
    d.severity = Severity::Warning;
    d.path = path;
    d.line = at_line;
    d.column = column ? static_cast<int>(*column) + 1 : 0;
    d.message = std::move(message);
    out.push_back(std::move(d));
  };
  auto unbound_message = [](const std::string& name, int c) {
    return name + " is read but nothing is bound to it, so it reads transparent black (#pragma channel" +
           std::to_string(c) + " \"FILE\" names an input)";
  };
  auto own_line = [&](int number) {  // not the host's (the prelude declares every channel)
    return static_cast<size_t>(number) <= source.line_map.size() && source.line_map[static_cast<size_t>(number) - 1].file >= 0;
  };
  std::array<bool, 4> warned = bound;
  std::vector<StraySampler> strays;
  std::unordered_map<std::string, size_t> stray_index;
  const std::string_view reads = active.empty() ? std::string_view(code) : active;
  for_each_line(reads, [&](std::string_view line, int number) {
    if (!own_line(number)) return true;
    for (int c = 0; c < 4; ++c) {
      const std::string name = "iChannel" + std::to_string(c);
      if (warned[static_cast<size_t>(c)] || !lexing::has_word(line, name)) continue;
      warned[static_cast<size_t>(c)] = true;
      warn_at(number, name, unbound_message(name, c), line);
    }
    return true;
  });
  auto bound_by_name = [&](const std::string& name) {
    return std::any_of(source.channels.begin(), source.channels.end(),
                       [&](const ChannelSpec& c) { return c.sampler_name == name; });
  };
  for (const DeclaredName& declared : declared_samplers(code)) {
    const std::string name(declared.name);
    if (!own_line(declared.line) || stray_index.count(name) || bound_by_name(name)) continue;
    const int channel = channel_of_sampler(name);
    if (channel >= 0 && (name[0] == 'i' || bound[static_cast<size_t>(channel)])) continue;
    stray_index[name] = strays.size();
    strays.push_back({name, declared.line, channel});
  }
  if (strays.empty()) return out;
  // A stray sampler warns where it is declared, if any other line reads it.
  std::vector<bool> read(strays.size(), false);
  for_each_line(reads, [&](std::string_view line, int number) {
    if (!own_line(number)) return true;
    lexing::any_word(line, [&](size_t begin, size_t end) {
      const auto found = stray_index.find(std::string(line.substr(begin, end - begin)));
      if (found != stray_index.end() && strays[found->second].line != number) read[found->second] = true;
      return false;
    });
    return true;
  });
  for (size_t i = 0; i < strays.size(); ++i) {
    if (!read[i]) continue;
    const StraySampler& stray = strays[i];
    warn_at(stray.line, stray.name,
            stray.channel >= 0 ? unbound_message(stray.name, stray.channel) : stray_sampler_message(stray.name));
  }
  return out;
}

}  // namespace rm
