#include "headless/accuracy_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <sstream>
#include <tuple>

#include "core/capture.h"
#include "core/frame_graph.h"
#include "core/knobs.h"
#include "core/project.h"
#include "core/check.h"
#include "core/diagnostics.h"
#include "core/renderer.h"
#include "core/scene.h"
#include "core/views.h"
#include "headless/egl_context.h"
#include "headless/svg_chart.h"

namespace rm {
namespace {

// One point of the sweep: a knob at one value (or a preset, or the textbook loop).
struct Setting {
  std::string knob;    // the curve it belongs to
  std::string value;
  std::vector<Define> defines;
  std::vector<std::string> strip;  // scene #defines removed besides the knobs set
  std::string label() const { return knob == value ? knob : knob + "=" + value; }
};

struct Measured {
  Setting setting;
  bool ok = false;
  bool no_effect = false;  // compiles to the same program as the default
  double ms = 0, wall_ms = 0, evals_mean = 0, evals_max = 0, rmse = 0, psnr = 0, hit_miss = 0, depth_error = 0;
  double bound_evals_mean = 0;  // mapBound() calls (RM_MAP_BOUND): the work besides map()
  size_t nan = 0;
};

std::vector<Setting> sweep() {
  std::vector<Setting> out = {{"default", "default", {}, {}}};
  auto knob = [&](const std::string& name, std::initializer_list<const char*> values) {
    for (const char* v : values) out.push_back({name, v, {{name, v}}, {}});
  };
  knob("RM_HIT_PIXELS", {"0.25", "0.5", "2", "4", "8"});
  for (const char* eps : {"0.01", "0.001", "0.0001"})  // a fixed absolute threshold, no pixel cone
    out.push_back({"absolute threshold", eps, {{"RM_HIT_PIXELS", "0.0"}, {"RM_HIT_EPSILON", eps}}, {}});
  knob("RM_MAX_STEPS", {"32", "64", "128", "256", "512"});
  knob("RM_MAX_DISTANCE", {"20.0", "50.0"});
  knob("RM_OMEGA", {"1.2", "1.4", "1.6"});
  knob("RM_NORMAL_TAPS", {"6"});
  knob("RM_NORMAL_EPSILON", {"1e-5", "1e-3", "1e-2"});
  knob("RM_SHADOW_STEPS", {"8", "16", "32", "128"});
  knob("RM_SHADOW_SHARPNESS", {"8.0", "32.0"});
  knob("RM_AO_SAMPLES", {"2", "3", "8"});
  knob("RM_REFLECTIONS", {"0", "1", "2", "4"});
  knob("RM_REFRACTION", {"0", "2", "4", "8"});
  knob("RM_SAMPLES", {"2", "3"});
  for (const char* preset : {"draft", "interactive", "final"})
    out.push_back({"preset", preset, {{"RM_QUALITY", preset_macro(preset)}}, {}});
  // The loop a tutorial writes: a fixed absolute epsilon, no over-relaxation, no
  // bounds (nor the scene's mapBound), and a grid marched step by step like any other map().
  out.push_back({"textbook", "textbook",
                 {{"RM_HIT_PIXELS", "0.0"}, {"RM_HIT_EPSILON", "0.001"}, {"RM_OMEGA", "1.0"}, {"RM_GRID_MARCH", "0"}},
                 {"RM_BOUNDING_SPHERE", "RM_BOUNDING_BOX_MIN", "RM_BOUNDING_BOX_MAX", "RM_MAP_BOUND"}});
  return out;
}

struct Renders {
  Image color;   // the picture
  Image data;    // RM_VIEW_DATA: (map() calls, primary t or -1, bad, mapBound() calls)
  double ms = 0;       // GPU time per frame, GL_TIME_ELAPSED
  double wall_ms = 0;  // draw + glFinish on the clock: what a frame costs the user
};

class Bench {
 public:
  Bench(const AccuracyRequest& req) : req_(req), target_(req.size.x, req.size.y) {
    inputs_.resolution = glm::vec3(req.size, 1.0f);
    inputs_.time = static_cast<float>(req.time);
    inputs_.frame = static_cast<int>(req.time * 60.0);
    inputs_.frame_rate = 60.0f;
    inputs_.time_delta = 1.0f / 60.0f;
  }

  // The program text of `setting` after glslang's preprocessor: equal texts
  // are the same program.
  std::string expanded(const Setting& setting) {
    SourceOptions options = options_for(setting);
    const Source source = preprocess(req_.scene, options);
    Diagnostics diags;
    return expand_preprocessor(source, &diags).value_or("");
  }

  // The picture and the data view of `setting`; the data view of `data_setting`
  // when given (the reference's depth comes from one centred sample).
  // `status`, when given, is set to the exit status of a failure to build.
  std::optional<Renders> render(const Setting& setting, std::string* error, const Setting* data_setting = nullptr,
                                int* status = nullptr) {
    const Setting& d = data_setting ? *data_setting : setting;
    Project color(req_.scene, options_for(setting));
    Project data(req_.scene, with_view(options_for(d), View::Data));
    if (color.reload() != ReloadStatus::Swapped || data.reload() != ReloadStatus::Swapped) {
      const Diagnostics& failed = color.diagnostics().empty() ? data.diagnostics() : color.diagnostics();
      *error = join(failed);
      if (status) *status = build_failure_status(failed);
      return std::nullopt;
    }
    FrameGraph color_graph(renderer_), data_graph(renderer_);
    if (!color_graph.update(color, error) || !data_graph.update(data, error)) return std::nullopt;
    Renders out;
    std::string no_error;
    inputs_.uniforms = uniform_values(color.user_uniforms(), {}, &no_error).value_or(std::vector<UniformValue>{});
    std::tie(out.ms, out.wall_ms) = time_frames(color, color_graph);
    out.color = color_graph.render_frame(color, inputs_, req_.size);
    out.data = data_graph.render_frame(data, inputs_, req_.size);
    return out;
  }

 private:
  // The scene's own #defines of the knobs set here give way to them (a -D
  // does that by itself), and so do those of the macros the setting strips.
  SourceOptions options_for(const Setting& setting) const {
    SourceOptions options = req_.source;
    for (const Define& d : setting.defines) options.defines = with_define(options.defines, d.name, d.value.empty() ? "1" : d.value);
    options.undefines.insert(options.undefines.end(), setting.strip.begin(), setting.strip.end());
    return options;
  }

  // The time of one frame, the median of kFrames after kWarmUp (the first draws
  // of a program also compile it): GPU time from GL_TIME_ELAPSED queries, and
  // the wall clock around draw + glFinish. Software renderers (llvmpipe)
  // rasterise on worker threads that the query does not see, so there the
  // wall clock is the one to trust.
  static constexpr int kWarmUp = 5, kFrames = 15;
  std::pair<double, double> time_frames(const Project& project, FrameGraph& graph) {
    GLuint query = 0;
    glGenQueries(1, &query);
    std::vector<double> gpu, wall;
    for (int i = 0; i < kWarmUp + kFrames; ++i) {
      glFinish();  // nothing earlier may still be running inside this frame
      const auto start = std::chrono::steady_clock::now();
      glBeginQuery(GL_TIME_ELAPSED, query);
      graph.draw(project, inputs_, req_.size, target_.framebuffer());
      glFinish();
      glEndQuery(GL_TIME_ELAPSED);
      const auto end = std::chrono::steady_clock::now();
      GLuint64 ns = 0;
      glGetQueryObjectui64v(query, GL_QUERY_RESULT, &ns);
      if (i < kWarmUp) continue;
      gpu.push_back(static_cast<double>(ns) / 1e6);
      wall.push_back(std::chrono::duration<double, std::milli>(end - start).count());
    }
    glDeleteQueries(1, &query);
    std::sort(gpu.begin(), gpu.end());
    std::sort(wall.begin(), wall.end());
    return {gpu[gpu.size() / 2], wall[wall.size() / 2]};
  }

  const AccuracyRequest& req_;
  Renderer renderer_;
  RenderTarget target_;
  FrameInputs inputs_;
};

void compare(const Renders& got, const Renders& reference, Measured* m) {
  const size_t pixels = got.color.rgba.size() / 4;
  double squared = 0, depth = 0, evals = 0, evals_max = 0, bound_evals = 0;
  size_t mismatched = 0, both_hit = 0;
  for (size_t i = 0; i < pixels; ++i) {
    bool bad = false;
    for (int c = 0; c < 3; ++c) {
      const float v = got.color.rgba[i * 4 + c];
      bad = bad || !std::isfinite(v);
      const double d = std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f) -
                       std::clamp(reference.color.rgba[i * 4 + c], 0.0f, 1.0f);
      squared += d * d;
    }
    m->nan += bad;
    const float count = got.data.rgba[i * 4], t = got.data.rgba[i * 4 + 1], ref_t = reference.data.rgba[i * 4 + 1];
    evals += count;
    bound_evals += got.data.rgba[i * 4 + 3];
    evals_max = std::max<double>(evals_max, count);
    if ((t < 0) != (ref_t < 0)) ++mismatched;
    if (t >= 0 && ref_t >= 0) depth += std::abs(t - ref_t), ++both_hit;
  }
  m->rmse = std::sqrt(squared / (3.0 * pixels));
  m->psnr = m->rmse > 0 ? std::min(99.0, 20.0 * std::log10(1.0 / m->rmse)) : 99.0;
  m->hit_miss = static_cast<double>(mismatched) / pixels;
  m->depth_error = both_hit ? depth / both_hit : 0.0;
  m->evals_mean = evals / pixels;
  m->evals_max = evals_max;
  m->bound_evals_mean = bound_evals / pixels;
}

std::string fixed(double v, int decimals) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

// The pictures (path, encoded bytes) drawn on the way.
using Pictures = std::vector<std::pair<fs::path, std::string>>;

// The table, the chart and the pictures, all or none (an older report is
// not left with some of a new one's files); false with *error set when one
// could not be written.
bool write_outputs(const AccuracyRequest& req, const std::vector<Measured>& rows, const Pictures& pictures,
                   std::string* error) {
  std::ostringstream csv;
  csv << "knob,value,ms,wall_ms,evaluations_mean,evaluations_max,rmse,psnr_db,hit_miss_share,depth_error,nan_pixels,no_effect,"
         "bound_evaluations_mean\n";
  for (const Measured& m : rows)
    if (m.ok)
      csv << m.setting.knob << ',' << m.setting.value << ',' << fixed(m.ms, 3) << ',' << fixed(m.wall_ms, 3) << ','
          << fixed(m.evals_mean, 2) << ','
          << fixed(m.evals_max, 0) << ',' << fixed(m.rmse, 5) << ',' << fixed(m.psnr, 2) << ','
          << fixed(m.hit_miss, 5) << ',' << fixed(m.depth_error, 5) << ',' << m.nan << ',' << m.no_effect << ','
          << fixed(m.bound_evals_mean, 2) << '\n';

  // A curve per knob through the default, ordered by time.
  std::map<std::string, ChartSeries> curves;
  const Measured* base = rows.front().ok ? &rows.front() : nullptr;
  for (const Measured& m : rows) {
    if (!m.ok || m.no_effect || m.setting.knob == "default") continue;
    ChartSeries& s = curves[m.setting.knob];
    s.name = m.setting.knob;
    s.points.emplace_back(m.wall_ms, m.psnr);
  }
  std::vector<ChartSeries> series;
  for (auto& [name, s] : curves) {
    if (base && name != "preset" && name != "textbook") s.points.emplace_back(base->wall_ms, base->psnr);
    std::sort(s.points.begin(), s.points.end());
    series.push_back(std::move(s));
  }
  if (base) series.push_back({"default", {{base->wall_ms, base->psnr}}});
  const std::string svg =
      svg_chart(req.scene.filename().string() + ": image error against GPU time (" + std::to_string(req.size.x) + "x" +
                    std::to_string(req.size.y) + ")",
                "frame time, draw + glFinish (ms)", "PSNR against the reference (dB)", series);
  const std::string table = csv.str();
  std::vector<std::pair<fs::path, std::string_view>> files{{req.out / "accuracy.csv", table},
                                                           {req.out / "accuracy.svg", svg}};
  for (const auto& [path, bytes] : pictures) files.emplace_back(path, bytes);
  return write_whole_files(files, error);
}

}  // namespace

int accuracy_command(const AccuracyRequest& input) {
  AccuracyRequest req = input;
  if (req.out.empty()) req.out = "accuracy-" + req.scene.stem().string();
  std::error_code ec;
  fs::create_directories(req.out, ec);
  if (ec) {
    std::cerr << "raymarching: error: '" << req.out.string() << "': " << ec.message() << '\n';
    return kExitUsage;
  }
  // The reference preset's knobs as -D's: a scene's own RM_SHADOW_STEPS 32
  // (or a -D of it) must not lower the yardstick it is measured against.
  // Read before the GL context starts its threads (the preprocessor runs in a
  // forked child); without them the reference would be the scene's own.
  std::vector<Define> reference_knobs = preset_knobs("reference", req.source.shaderlib_dir);
  if (reference_knobs.empty()) {
    std::cerr << "raymarching: error: accuracy: cannot read the reference preset's knobs from "
              << (req.source.shaderlib_dir / "rm" / "quality.glsl").string() << '\n';
    return kExitUsage;
  }
  reference_knobs.push_back({"RM_QUALITY", preset_macro("reference")});
  std::string error;
  auto context = EglContext::create(&error);
  if (!context) {
    std::cerr << "raymarching: error: " << error << '\n';
    return kExitUsage;
  }
  {
    Source plain = preprocess(req.scene, req.source);
    if (!plain.ok()) {
      std::cerr << join(plain.errors);
      return kExitShaderError;
    }
    if (auto problem = view_problem(plain, View::Steps)) {
      std::cerr << "raymarching: error: accuracy: " << *problem << '\n';
      return kExitUsage;
    }
  }

  Bench bench(req);
  std::cerr << "accuracy: rendering the reference (preset reference)...\n";
  const Setting reference_setting{"reference", "reference", reference_knobs, {}};
  const Setting reference_centre{"reference", "reference", with_define(reference_knobs, "RM_SAMPLES", "1"), {}};
  int failed = kExitShaderError;
  const auto reference = bench.render(reference_setting, &error, &reference_centre, &failed);
  if (!reference) {
    std::cerr << error;
    return failed;
  }
  Pictures pictures;
  auto keep_picture = [&](const fs::path& path, const Image& image) {
    auto bytes = encode_image(path, image, {}, &error);
    if (bytes) pictures.emplace_back(path, std::move(*bytes));
    else std::cerr << "raymarching: error: " << error << '\n';
    return bytes.has_value();
  };
  if (!keep_picture(req.out / "reference.png", reference->color)) return kExitUsage;

  const std::vector<Setting> settings = sweep();
  const std::string default_text = bench.expanded(settings.front());
  std::vector<Measured> rows;
  for (size_t i = 0; i < settings.size(); ++i) {
    const Setting& s = settings[i];
    std::cerr << "accuracy: [" << i + 1 << "/" << settings.size() << "] " << s.label() << '\n';
    Measured m{s};
    // The scene does not use this knob: the same text (a text that could not
    // be expanded is no evidence, and is rendered).
    if (i > 0 && !default_text.empty() && bench.expanded(s) == default_text) {
      m = rows.front();
      m.setting = s;
      m.no_effect = true;
      rows.push_back(m);
      continue;
    }
    auto got = bench.render(s, &error);
    if (!got) {
      std::cerr << "accuracy: " << s.label() << " does not build:\n" << error;
      rows.push_back(m);
      continue;
    }
    m.ok = true;
    m.ms = got->ms;
    m.wall_ms = got->wall_ms;
    compare(*got, *reference, &m);
    rows.push_back(m);
  }
  // The default's steps as a heatmap picture. A scene whose steps view does
  // not build (its own #if RM_VIEW == 1) still gets its table and chart.
  {
    SourceOptions steps = with_view(req.source, View::Steps);
    Project project(req.scene, steps);
    if (project.reload() != ReloadStatus::Swapped) {
      std::cerr << "accuracy: the steps view does not build, so no steps.png is written:\n"
                << join(project.diagnostics());
      if (fs::exists(req.out / "steps.png"))
        std::cerr << "accuracy: the steps.png in " << req.out.string() << " is an earlier run's\n";
    } else {
      Renderer renderer;
      FrameGraph graph(renderer);
      std::string ignored;
      graph.update(project, &ignored);
      FrameInputs in;
      in.resolution = glm::vec3(req.size, 1.0f);
      in.time = static_cast<float>(req.time);
      in.uniforms = uniform_values(project.user_uniforms(), {}, &ignored).value_or(std::vector<UniformValue>{});
      if (!keep_picture(req.out / "steps.png", graph.render_frame(project, in, req.size))) return kExitUsage;
    }
  }

  // mapBound() calls get a column where the scene has a bound (RM_MAP_BOUND).
  const bool bounded = std::any_of(rows.begin(), rows.end(), [](const Measured& m) { return m.bound_evals_mean > 0; });
  std::printf("| setting | GPU ms | frame ms | map() calls mean | max |%s PSNR dB | hit/miss differs | depth error | NaN |\n",
              bounded ? " mapBound() calls mean |" : "");
  std::printf("|---|---|---|---|---|%s---|---|---|---|\n", bounded ? "---|" : "");
  for (const Measured& m : rows) {
    if (!m.ok) {
      std::printf("| %s | does not build | | | |%s | | | |\n", m.setting.label().c_str(), bounded ? " |" : "");
      continue;
    }
    const std::string bound_column = bounded ? " " + fixed(m.bound_evals_mean, 1) + " |" : "";
    std::printf("| %s%s | %.2f | %.2f | %.1f | %.0f |%s %.1f | %.2f%% | %.4f | %zu |\n", m.setting.label().c_str(),
                m.no_effect ? " (no effect)" : "", m.ms, m.wall_ms, m.evals_mean, m.evals_max, bound_column.c_str(), m.psnr,
                100.0 * m.hit_miss, m.depth_error, m.nan);
  }
  if (!write_outputs(req, rows, pictures, &error)) {
    std::cerr << "raymarching: error: " << error << '\n';
    return kExitUsage;
  }
  std::cerr << "accuracy: wrote " << (req.out / "accuracy.csv").string() << ", accuracy.svg";
  for (const auto& picture : pictures) std::cerr << ", " << picture.first.filename().string();
  std::cerr << '\n';
  return kExitOk;
}

}  // namespace rm
