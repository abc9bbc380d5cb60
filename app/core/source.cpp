#include "core/source.h"

#include <unistd.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <system_error>

namespace rm {

namespace {

constexpr int kMaxIncludeDepth = 256;
constexpr int kHostFile = -1;
constexpr int kCommandLineFile = -2;

const char* const kShadertoyPrelude = R"(uniform vec3 iResolution;
uniform float iTime;
uniform float iTimeDelta;
uniform float iFrameRate;
uniform int iFrame;
uniform vec4 iMouse;
uniform vec4 iDate;
uniform float iSampleRate;
uniform float iChannelTime[4];
uniform vec3 iChannelResolution[4];
uniform sampler2D iChannel0;
uniform sampler2D iChannel1;
uniform sampler2D iChannel2;
uniform sampler2D iChannel3;
uniform vec2 rm_FragCoordOffset;
out vec4 rm_FragColor;)";

// Shadertoy leaves fragColor's start value undefined; we start from opaque black.
// With RM_VIEW (render --view, the window's V key) the pixel becomes a debug
// view: nan works for any shader, the others read what shaderlib recorded.
const char* const kShadertoyMain = R"glsl(#ifdef RM_VIEW
vec4 rm_view(vec4 color, vec2 fragCoord) {
  bool bad = any(isnan(color)) || any(isinf(color));
#if RM_VIEW == 4
  float grey = dot(clamp(color.rgb, 0.0, 1.0), vec3(0.2126, 0.7152, 0.0722));
  return bad ? vec4(1.0, 0.0, 1.0, 1.0) : vec4(vec3(0.2 + 0.6 * grey), 1.0);
#elif defined(RM_VIEWS_GLSL)
  return rmView(color, fragCoord, iResolution, bad);
#else
#error "this view needs a scene that marches with shaderlib (rm/march.glsl)"
#endif
}
#endif
void main() {
  vec4 color = vec4(0.0, 0.0, 0.0, 1.0);
  vec2 fragCoord = gl_FragCoord.xy + rm_FragCoordOffset;
  mainImage(color, fragCoord);
#ifdef RM_VIEW
  color = rm_view(color, fragCoord);
#endif
  rm_FragColor = color;
})glsl";

// GLSL 1.10/1.20 and ES 1.00 names mapped onto a 4.50 core profile.
const char* const kLegacyPrelude = R"(#define texture2D texture
#define texture2DLod textureLod
#define texture2DProj textureProj
#define textureCube texture
#define varying in)";

std::string strip_comments(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size(); ++i) {
    if (text.compare(i, 2, "//") == 0) {
      while (i < text.size() && text[i] != '\n') ++i;
      if (i < text.size()) out += '\n';
    } else if (text.compare(i, 2, "/*") == 0) {
      size_t end = text.find("*/", i + 2);
      for (size_t j = i; j < std::min(end, text.size()); ++j)
        if (text[j] == '\n') out += '\n';
      i = end == std::string::npos ? text.size() : end + 1;
    } else {
      out += text[i];
    }
  }
  return out;
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::string line;
  for (size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') continue;
    if (c == '\n') {
      lines.push_back(std::move(line));
      line.clear();
    } else {
      line += c;
    }
  }
  if (!line.empty()) lines.push_back(std::move(line));
  return lines;
}

struct IncludeDirective {
  bool angled = false;
  std::string target;
  int column = 0;  // 1-based column of the opening quote
};

struct ChannelPragma {
  int channel = 0;
  std::string target;
  int column = 0;  // 1-based column of "#"
};

// `#pragma channelN "FILE"`: the scene's default image for iChannelN. Other
// pragmas are the compiler's. *malformed is set for a channel pragma without
// a quoted file name.
std::optional<ChannelPragma> parse_channel_pragma(const std::string& line, bool* malformed) {
  static const std::regex start(R"(^(\s*)#\s*pragma\s+channel([0-9]+)\b(.*)$)");
  static const std::regex quoted(R"re(^\s*"([^"]+)"\s*(//.*)?$)re");
  std::smatch m, q;
  *malformed = false;
  if (!std::regex_match(line, m, start)) return std::nullopt;
  ChannelPragma pragma;
  pragma.column = static_cast<int>(m[1].length()) + 1;
  const std::string rest = m[3];
  if (m[2].length() != 1 || m[2].str()[0] > '3' || !std::regex_match(rest, q, quoted)) {
    *malformed = true;
    return pragma;
  }
  pragma.channel = m[2].str()[0] - '0';
  pragma.target = q[1];
  return pragma;
}

std::optional<IncludeDirective> parse_include(const std::string& line, bool* malformed) {
  static const std::regex re(R"(^\s*#\s*include\b\s*(.*)$)");
  std::smatch m;
  *malformed = false;
  if (!std::regex_match(line, m, re)) return std::nullopt;
  std::string rest = m[1].str();
  size_t rest_pos = static_cast<size_t>(m.position(1));
  static const std::regex target_re(R"re(^("([^"]+)"|<([^>]+)>)\s*(//.*)?$)re");
  std::smatch t;
  if (!std::regex_match(rest, t, target_re)) {
    *malformed = true;
    return IncludeDirective{false, rest, static_cast<int>(rest_pos) + 1};
  }
  IncludeDirective inc;
  inc.angled = t[3].matched;
  inc.target = inc.angled ? t[3].str() : t[2].str();
  inc.column = static_cast<int>(rest_pos) + 1;
  return inc;
}

struct VersionInfo {
  int number = 0;
  std::string profile;  // "core", "es", "compatibility" or ""
  bool modern() const { return number >= 130 && number != 100; }
  bool es() const { return profile == "es"; }
};

std::optional<VersionInfo> parse_version(const std::string& line) {
  // At most 9 digits: every version fits an int (a longer one is left for
  // glslang to reject at its line; std::stoi would throw on it).
  static const std::regex re(R"(^\s*#\s*version\s+(\d{1,9})\s*([a-z]*)\s*(//.*)?$)");
  std::smatch m;
  if (!std::regex_match(line, m, re)) return std::nullopt;
  return VersionInfo{std::stoi(m[1].str()), m[2].str()};
}

class Preprocessor {
 public:
  Preprocessor(const SourceOptions& options, const FileSystem& files) : options_(options), fs_(files) {}

  Source run(const fs::path& scene) {
    fs::path first = fs::absolute(scene).lexically_normal();
    out_.watch.push_back(first);
    include_file(first, /*from*/ -1, 0, 0);
    if (!out_.ok()) return std::move(out_);
    assemble();
    return std::move(out_);
  }

 private:
  struct Line {
    std::string text;
    Origin origin;
  };

  void error(int file, int line, int column, std::string message) {
    Diagnostic d;
    d.path = file >= 0 ? out_.files[static_cast<size_t>(file)].string() : std::string();
    d.line = line;
    d.column = column;
    d.message = std::move(message);
    out_.errors.push_back(std::move(d));
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

  // Reads one file and appends its lines, expanding includes in place.
  void include_file(const fs::path& path, int from_file, int from_line, int from_col) {
    std::string read_error;
    std::optional<std::string> bytes = fs_.read(path, &read_error);
    if (!bytes) {
      if (from_file < 0) {
        error(add_file(path), 0, 0, "cannot read scene: " + read_error);
      } else {
        error(from_file, from_line, from_col, "cannot read include '" + path.string() + "': " + read_error);
      }
      return;
    }
    std::string text = std::move(*bytes);
    if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);
    if (text.find('\0') != std::string::npos) {
      int file = add_file(path);
      error(file, 0, 0, "not a text file (it contains NUL bytes)");
      return;
    }

    int file = add_file(path);
    stack_.push_back(file);
    std::vector<std::string> lines = split_lines(text);
    for (size_t i = 0; i < lines.size() && out_.ok(); ++i) {
      int line_no = static_cast<int>(i) + 1;
      const std::string& line = lines[i];
      if (file == 0 && !version_ && (version_ = parse_version(line))) {
        version_origin_ = Origin{file, line_no};
        continue;  // re-emitted at the top by assemble()
      }
      bool malformed = false;
      if (auto pragma = parse_channel_pragma(line, &malformed)) {
        if (malformed) {
          error(file, line_no, pragma->column, "#pragma channelN expects N in 0..3 and \"FILE\"");
          break;
        }
        const fs::path image = fs::absolute(path.parent_path() / pragma->target).lexically_normal();
        out_.watch.push_back(image);
        if (!fs_.exists(image)) {
          error(file, line_no, pragma->column, "cannot find channel image '" + pragma->target + "'");
          break;
        }
        out_.channels[static_cast<size_t>(pragma->channel)] = image;
        body_.push_back({"", Origin{file, line_no}});  // the driver never sees it; lines keep their numbers
        continue;
      }
      auto inc = parse_include(line, &malformed);
      if (!inc) {
        body_.push_back({line, Origin{file, line_no}});
        continue;
      }
      if (malformed) {
        error(file, line_no, inc->column, "#include expects \"FILE\" or <FILE>");
        break;
      }
      if (stack_.size() >= kMaxIncludeDepth) {
        error(file, line_no, inc->column,
              "#include nested too deeply (more than " + std::to_string(kMaxIncludeDepth) + " levels)");
        break;
      }
      fs::path first_candidate;
      auto target = resolve(*inc, path.parent_path(), &first_candidate);
      if (!target) {
        if (!first_candidate.empty()) out_.watch.push_back(first_candidate);
        error(file, line_no, inc->column, "cannot find include '" + inc->target + "'");
        break;
      }
      int existing = find_file(*target);
      if (existing >= 0) {
        for (size_t s = 0; s < stack_.size(); ++s) {
          if (stack_[s] != existing) continue;
          std::string chain;
          for (size_t k = s; k < stack_.size(); ++k)
            chain += out_.files[static_cast<size_t>(stack_[k])].filename().string() + " -> ";
          error(file, line_no, inc->column,
                "#include cycle: " + chain + target->filename().string());
          break;
        }
        continue;  // already included once in this compile: nothing to add
      }
      out_.watch.push_back(*target);
      include_file(*target, file, line_no, inc->column);
    }
    stack_.pop_back();
  }

  int add_file(const fs::path& path) {
    out_.files.push_back(path);
    return static_cast<int>(out_.files.size()) - 1;
  }

  int find_file(const fs::path& path) const {
    for (size_t i = 0; i < out_.files.size(); ++i)
      if (out_.files[i] == path) return static_cast<int>(i);
    return -1;
  }

  void emit(const std::string& text, Origin origin) {
    out_.text += text;
    out_.text += '\n';
    out_.line_map.push_back(origin);
  }

  void emit_host(const char* block) {
    std::istringstream in(block);
    std::string line;
    while (std::getline(in, line)) emit(line, Origin{kHostFile, ++host_lines_});
  }

  void assemble() {
    std::string body;
    for (const auto& l : body_) body += l.text + '\n';
    const std::string code = strip_comments(body);
    static const std::regex main_re(R"(\bvoid\s+main\s*\()");
    static const std::regex main_image_re(R"(\bmainImage\s*\()");
    static const std::regex frag_color_re(R"(\bgl_FragColor\b)");
    const bool has_main = std::regex_search(code, main_re);
    const bool has_main_image = std::regex_search(code, main_image_re);
    const bool modern = version_ && version_->modern();

    if (has_main_image && !has_main) {
      out_.kind = ShaderKind::Shadertoy;
    } else if (has_main && modern) {
      out_.kind = ShaderKind::Complete;
    } else if (has_main) {
      out_.kind = ShaderKind::Legacy;
    } else {
      error(0, 0, 0, "defines neither mainImage(out vec4, in vec2) nor main()");
      return;
    }

    const bool keep_version = modern;
    out_.version_line = keep_version
        ? "#version " + std::to_string(version_->number) + (version_->profile.empty() ? "" : " " + version_->profile)
        : "#version 450 core";
    emit(out_.version_line, keep_version ? version_origin_ : Origin{kHostFile, ++host_lines_});
    emit("#define HW_PERFORMANCE 1", Origin{kHostFile, ++host_lines_});
    int define_index = 0;
    for (const auto& d : options_.defines)
      emit("#define " + d.name + " " + (d.value.empty() ? "1" : d.value), Origin{kCommandLineFile, ++define_index});
    if (keep_version && version_->es()) emit_host("precision highp float;\nprecision highp int;");

    if (out_.kind == ShaderKind::Shadertoy) {
      emit_host(kShadertoyPrelude);
    } else if (out_.kind == ShaderKind::Legacy) {
      emit_host(kLegacyPrelude);
      if (std::regex_search(code, frag_color_re)) emit_host("#define gl_FragColor rm_FragColor\nout vec4 rm_FragColor;");
    }
    for (const auto& l : body_) emit(l.text, l.origin);
    if (out_.kind == ShaderKind::Shadertoy) emit_host(kShadertoyMain);
  }

  const SourceOptions& options_;
  const FileSystem& fs_;
  Source out_;
  std::vector<int> stack_;
  std::vector<Line> body_;
  std::optional<VersionInfo> version_;
  Origin version_origin_;
  int host_lines_ = 0;
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

std::optional<std::string> unreadable_because(const fs::path& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) return "is a directory";
  if (!fs::exists(path, ec)) return "no such file";
  if (access(path.c_str(), R_OK) != 0) return "permission denied";
  return std::nullopt;
}

FileSystem disk_file_system() {
  FileSystem disk;
  disk.read = [](const fs::path& path, std::string* error) -> std::optional<std::string> {
    if (auto why = unreadable_because(path)) {
      *error = *why;
      return std::nullopt;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      *error = "cannot open";
      return std::nullopt;
    }
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) {
      *error = "read error";
      return std::nullopt;
    }
    return ss.str();
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

}  // namespace rm
