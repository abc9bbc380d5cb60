// raymarching: a live shader playground for ray-marched SDF scenes.
//   raymarching [SCENE]            open a window (default scene without SCENE)
//   raymarching render SCENE -o F  render headless through EGL
//   raymarching check SCENE [-E]   preprocess and validate only (-E: print the result)
//   raymarching accuracy SCENE     what each accuracy knob costs and buys

#include <CLI/CLI.hpp>
#include <cmath>
#include <ctime>
#include <iostream>
#include <regex>

#include "core/data_paths.h"
#include "core/diagnostics.h"
#include "core/source.h"
#include "core/views.h"
#include "headless/accuracy_command.h"
#include "headless/render_command.h"
#include "window/window_app.h"

namespace {

namespace fs = std::filesystem;

struct UsageError {
  std::string message;
};

glm::ivec2 parse_size(const std::string& text, const char* option) {
  static const std::regex re(R"(^\s*(-?\d+)\s*[xX]\s*(-?\d+)\s*$)");
  std::smatch m;
  if (!std::regex_match(text, m, re)) throw UsageError{std::string(option) + " '" + text + "': expected WIDTHxHEIGHT, e.g. 640x360"};
  long w = 0, h = 0;
  try {
    w = std::stol(m[1].str());
    h = std::stol(m[2].str());
  } catch (const std::exception&) {
    throw UsageError{std::string(option) + " '" + text + "': number out of range"};
  }
  if (w <= 0 || h <= 0) throw UsageError{std::string(option) + " '" + text + "': width and height must be positive"};
  constexpr long kMax = 16384;
  if (w > kMax || h > kMax) throw UsageError{std::string(option) + " '" + text + "': at most " + std::to_string(kMax) + " pixels a side"};
  return {static_cast<int>(w), static_cast<int>(h)};
}

double parse_number(const std::string& text, const std::string& what) {
  size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !std::isfinite(v)) throw UsageError{what + " '" + text + "': not a finite number"};
  return v;
}

glm::vec4 parse_mouse(const std::string& text) {
  std::vector<double> parts;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) parts.push_back(parse_number(item, "--mouse"));
  if (parts.size() != 2 && parts.size() != 4) throw UsageError{"--mouse '" + text + "': expected X,Y or X,Y,CX,CY"};
  if (parts.size() == 2) return glm::vec4(parts[0], parts[1], 0, 0);
  return glm::vec4(parts[0], parts[1], parts[2], parts[3]);
}

std::chrono::system_clock::time_point parse_date(const std::string& text) {
  static const std::regex re(R"(^(\d{4})-(\d{2})-(\d{2})[T ](\d{2}):(\d{2}):(\d{2}(\.\d+)?)$)");
  std::smatch m;
  if (!std::regex_match(text, m, re)) throw UsageError{"--date '" + text + "': expected YYYY-MM-DDTHH:MM:SS[.sss]"};
  std::tm tm{};
  tm.tm_year = std::stoi(m[1].str()) - 1900;
  tm.tm_mon = std::stoi(m[2].str()) - 1;
  tm.tm_mday = std::stoi(m[3].str());
  tm.tm_hour = std::stoi(m[4].str());
  tm.tm_min = std::stoi(m[5].str());
  const double seconds = std::stod(m[6].str());
  tm.tm_sec = static_cast<int>(seconds);
  tm.tm_isdst = -1;
  const std::time_t t = std::mktime(&tm);
  return std::chrono::system_clock::from_time_t(t) +
         std::chrono::duration_cast<std::chrono::system_clock::duration>(std::chrono::duration<double>(seconds - tm.tm_sec));
}

// A scene that cannot be read is an I/O error (exit 2), not a shader error.
void require_readable_file(const fs::path& path) {
  if (auto why = rm::unreadable_because(path)) {
    if (*why == "is a directory") *why += ", not a shader file";
    throw UsageError{"'" + path.string() + "': " + *why};
  }
}

struct Common {
  std::vector<std::string> includes;
  std::vector<std::string> defines;
  std::string quality;

  void add_to(CLI::App& app) {
    app.add_option("-I", includes, "Add DIR to the #include search path")->type_name("DIR")->allow_extra_args(false);
    app.add_option("-D", defines, "Define macro NAME (as VALUE, default 1) after #version")->type_name("NAME[=VALUE]")->allow_extra_args(false);
    app.add_option("--quality", quality, "shaderlib preset: the same as -D RM_QUALITY=RM_<NAME>")
        ->check(CLI::IsMember({"draft", "interactive", "final", "reference"}));
  }

  rm::SourceOptions source() const {
    static const std::regex name_re(R"(^[A-Za-z_][A-Za-z0-9_]*$)");
    rm::SourceOptions out;
    out.shaderlib_dir = rm::shaderlib_dir();
    for (const auto& dir : includes) out.include_dirs.emplace_back(dir);
    for (const auto& d : defines) {
      const auto eq = d.find('=');
      rm::Define def{d.substr(0, eq), eq == std::string::npos ? "" : d.substr(eq + 1)};
      if (!std::regex_match(def.name, name_re)) throw UsageError{"-D '" + d + "': '" + def.name + "' is not a macro name"};
      out.defines.push_back(def);
    }
    if (!quality.empty()) {
      std::string name = "RM_" + quality;
      std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::toupper(c); });
      out.defines.push_back({"RM_QUALITY", name});
    }
    return out;
  }
};

struct ChannelOptions {
  std::array<std::string, 4> paths;
  void add_to(CLI::App& app) {
    for (int i = 0; i < 4; ++i)
      app.add_option("--channel" + std::to_string(i), paths[static_cast<size_t>(i)],
                     "Image for iChannel" + std::to_string(i))->type_name("IMAGE");
  }
  std::array<fs::path, 4> get() const {
    std::array<fs::path, 4> out;
    for (size_t i = 0; i < 4; ++i) out[i] = paths[i];
    return out;
  }
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"raymarching: a live shader playground for ray-marched SDF scenes.\n"
               "Opens SCENE (a .frag file) in a window and reloads it on every save.",
               "raymarching"};
  app.set_version_flag("--version", std::string("raymarching ") + RM_VERSION);
  app.footer(std::string("\n") + rm::window_keys_help() +
             "\nexit status: 0 ok, 1 shader error, 2 usage or I/O error");
  app.require_subcommand(0, 1);

  // Window (default command).
  Common window_common;
  ChannelOptions window_channels;
  std::string scene, window_size = "800x450", shot_dir = ".", shot_format = "png", watch = "auto";
  int shot_scale = 1;
  bool verbose = false;
  app.add_option("scene", scene, "Shader to open (default: the bundled default scene)")->type_name("SCENE");
  window_common.add_to(app);
  app.add_option("--size", window_size, "Window size in screen coordinates")->type_name("WxH");
  app.add_option("--shot-dir", shot_dir, "Directory for F12 screenshots")->type_name("DIR");
  app.add_option("--shot-format", shot_format, "Screenshot format")->check(CLI::IsMember({"png", "exr"}));
  app.add_option("--shot-scale", shot_scale, "Render screenshots at N times the window's pixels")->check(CLI::Range(1, 16));
  app.add_option("--watch", watch, "File watching backend")->check(CLI::IsMember({"auto", "inotify", "poll"}));
  app.add_flag("-v,--verbose", verbose, "Log reloads and presented frames to stderr");
  window_channels.add_to(app);

  // render
  CLI::App* render = app.add_subcommand("render", "Render SCENE headless through EGL (no display, no GPU needed)");
  Common render_common;
  ChannelOptions render_channels;
  std::string render_scene, out, size = "640x360", time = "0", mouse, date;
  int frame = -1, frames = 0;
  double fps = 60.0;
  render->add_option("scene", render_scene, "Shader to render")->required()->type_name("SCENE");
  render->add_option("-o,--output", out, "Output image: .png (8-bit, clamped) or .exr (raw float)")->required()->type_name("OUT");
  render_common.add_to(*render);
  render->add_option("--size", size, "Picture size in pixels")->type_name("WxH");
  render->add_option("--time", time, "iTime of the (first) frame in seconds")->type_name("T");
  render->add_option("--frame", frame, "iFrame of the (first) frame (default: time * fps)")->type_name("N")->check(CLI::NonNegativeNumber);
  render->add_option("--frames", frames, "Render COUNT frames; OUT needs a counter like frame_%04d.png")->type_name("COUNT")->check(CLI::Range(1, 1000000));
  render->add_option("--fps", fps, "Frames per second of a sequence")->type_name("F")->check(CLI::Range(0.001, 100000.0));
  render->add_option("--mouse", mouse, "iMouse as X,Y[,CX,CY] in pixels")->type_name("X,Y[,CX,CY]");
  render->add_option("--date", date, "iDate as local YYYY-MM-DDTHH:MM:SS[.sss] (default: now)")->type_name("DATE");
  std::string view;
  render->add_option("--view", view, "A debug view instead of the picture: map() calls per pixel as a heatmap, "
                                     "normals, depth, or NaN/Inf pixels in magenta")
      ->check(CLI::IsMember({"steps", "normals", "depth", "nan"}));
  render_channels.add_to(*render);

  // check
  CLI::App* check = app.add_subcommand("check", "Preprocess and validate SCENE with glslang; print diagnostics");
  Common check_common;
  std::string check_scene;
  check->add_option("scene", check_scene, "Shader to check")->required()->type_name("SCENE");
  bool expand = false;
  check->add_flag("-E,--expand", expand, "Print what the compiler sees: the source after the preprocessor");
  check_common.add_to(*check);

  // accuracy
  CLI::App* accuracy = app.add_subcommand(
      "accuracy", "Measure what each shaderlib accuracy knob costs (GPU time, map() calls) and buys (error against a reference)");
  Common accuracy_common;
  std::string accuracy_scene, accuracy_size = "320x180", accuracy_out;
  double accuracy_time = 1.0;
  accuracy->add_option("scene", accuracy_scene, "Scene that renders with shaderlib")->required()->type_name("SCENE");
  accuracy->add_option("--size", accuracy_size, "Picture size in pixels (default 320x180)")->type_name("WxH");
  accuracy->add_option("--time", accuracy_time, "iTime of the measured frame (default 1)")->type_name("T");
  accuracy->add_option("--out", accuracy_out, "Directory for accuracy.csv, accuracy.svg, reference.png, steps.png "
                                              "(default accuracy-SCENE)")->type_name("DIR");
  accuracy_common.add_to(*accuracy);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "raymarching: error: " << e.what() << " (see raymarching --help)\n";
    return rm::kExitUsage;
  }

  try {
    if (*accuracy) {
      require_readable_file(accuracy_scene);
      rm::AccuracyRequest req;
      req.scene = accuracy_scene;
      req.source = accuracy_common.source();
      req.size = parse_size(accuracy_size, "--size");
      req.time = accuracy_time;
      req.out = accuracy_out;
      return rm::accuracy_command(req);
    }
    if (*check) {
      require_readable_file(check_scene);
      return rm::check_command(check_scene, check_common.source(), expand);
    }
    if (*render) {
      require_readable_file(render_scene);
      rm::RenderRequest req;
      req.scene = render_scene;
      req.source = render_common.source();
      req.out = out;
      req.size = parse_size(size, "--size");
      req.time = parse_number(time, "--time");
      if (frame >= 0) req.frame = frame;
      req.frames = frames;
      req.fps = fps;
      if (!view.empty()) req.view = *rm::view_from_string(view);
      if (!mouse.empty()) req.mouse = parse_mouse(mouse);
      if (!date.empty()) req.date = parse_date(date);
      req.channels = render_channels.get();
      return rm::render_command(req);
    }
    rm::WindowOptions opts;
    opts.scene = scene.empty() ? rm::default_scene() : fs::path(scene);
    require_readable_file(opts.scene);
    opts.source = window_common.source();
    opts.size = parse_size(window_size, "--size");
    opts.shot_dir = shot_dir;
    std::error_code ec;
    if (!fs::is_directory(opts.shot_dir, ec)) throw UsageError{"--shot-dir '" + shot_dir + "': not a directory"};
    opts.shot_format = shot_format;
    opts.shot_scale = shot_scale;
    opts.channels = window_channels.get();
    opts.watch = watch == "poll" ? rm::WatchBackend::Poll : watch == "inotify" ? rm::WatchBackend::Inotify : rm::WatchBackend::Auto;
    opts.verbose = verbose;
    return rm::run_window(opts);
  } catch (const UsageError& e) {
    std::cerr << "raymarching: error: " << e.message << '\n';
    return rm::kExitUsage;
  }
}
