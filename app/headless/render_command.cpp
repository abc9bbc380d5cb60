#include "headless/render_command.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "core/address_space.h"
#include "core/capture.h"
#include "core/channels.h"
#include "core/check.h"
#include "core/files.h"
#include "core/lexing.h"
#include "core/frame_graph.h"
#include "core/glslang_client.h"
#include "core/image_codecs.h"
#include "core/inputs.h"
#include "core/project.h"
#include "core/renderer.h"
#include "core/user_uniforms.h"
#include "core/scene.h"
#include "headless/run_guard.h"
#include "headless/egl_context.h"
#include "headless/progress.h"
#include "headless/video.h"

namespace rm {

namespace {

int fail(const std::string& message, int code) {
  std::cerr << "raymarching: error: " << message << '\n';
  return code;
}

void print_diagnostics(const Diagnostics& diags) { std::cerr << join(diags); }

// The shader's uniforms as a take recorded them, by name; those the take
// does not have (declared since) keep `defaults`, and values the shader no
// longer declares, or of another size, are dropped.
std::vector<UniformValue> with_take_values(std::vector<UniformValue> defaults, const std::vector<UniformValue>& take) {
  for (UniformValue& v : defaults) {
    auto it = std::find_if(take.begin(), take.end(), [&](const UniformValue& t) { return t.name == v.name; });
    if (it != take.end() && it->value.size() == v.value.size()) v = *it;
  }
  return defaults;
}

}  // namespace

std::optional<std::filesystem::path> sequence_path(const std::filesystem::path& pattern, int index) {
  const std::string name = pattern.filename().string();
  // Exactly one %d, %0Nd or %Nd (N up to two digits); %% is a literal %.
  int counters = 0;
  for (size_t i = 0; i < name.size(); ++i) {
    if (name[i] != '%') continue;
    if (++i < name.size() && name[i] == '%') continue;
    if (i < name.size() && name[i] == '0') ++i;
    for (int digits = 0; digits < 2 && i < name.size() && lexing::is_digit(name[i]); ++digits) ++i;
    if (i >= name.size() || name[i] != 'd') return std::nullopt;
    ++counters;
  }
  if (counters != 1) return std::nullopt;
  char buf[4096];
  std::snprintf(buf, sizeof buf, name.c_str(), index);
  return pattern.parent_path() / buf;
}

namespace {

// A file `render` cannot write, with what it can: pictures, and videos
// (a .gif is one here); nullopt for a picture it can write.
std::optional<std::string> unknown_output_type(const fs::path& out) {
  const auto codecs = image_codecs();
  if (codecs->unavailable() || (!out.extension().empty() && codecs->can_encode(out))) return std::nullopt;
  const std::string can =
      " (pictures: " + writable_image_extensions(is_video_path) + "; videos: " + video_extensions() + ")";
  if (out.extension().empty()) return "'" + out.string() + "' has no extension to choose a format" + can;
  return "'" + out.string() + "': cannot write files of type '" + out.extension().string() + "'" + can;
}

int render_frames(const RenderRequest& req) {
  // Everything that can be known wrong is reported before any GL work.
  const bool sequence = req.frames > 0;
  const bool video = is_video_path(req.out);
  const VideoSettings video_settings{req.size, req.fps, req.codec, req.crf};
  // iFrame of the first frame; an int, like the last one's (--time 1e300 made an undefined cast).
  const double first_iframe = req.take ? 0 : req.frame ? *req.frame : std::floor(req.time * req.fps + 1e-9);
  const double last_iframe = first_iframe + std::max(req.frames, 1) - 1;
  if (auto why = iframe_out_of_range(first_iframe < INT_MIN ? first_iframe : last_iframe))
    return fail(*why + ": give a smaller --time, --frame or --frames", kExitUsage);
  if (req.frame_range) {
    if (!sequence) return fail("--frame-range is a slice of a sequence: give --frames COUNT too", kExitUsage);
    if (req.frame_range->y >= req.frames)
      return fail("--frame-range " + std::to_string(req.frame_range->x) + ":" + std::to_string(req.frame_range->y) +
                      ": the sequence has frames 0 to " + std::to_string(req.frames - 1),
                  kExitUsage);
    if (video)
      return fail("--frame-range writes frames, not a video: give OUT a counter (frame_%04d.png) and join the "
                  "slices with ffmpeg (docs/farm.md)",
                  kExitUsage);
  }
  if (req.skip_existing && video)
    return fail("--skip-existing goes on with frames already written, and a video is one file: give OUT a counter "
                "(frame_%04d.png)",
                kExitUsage);
  char limit[64];
  std::snprintf(limit, sizeof limit, "--timeout %g", req.timeout);
  // Declared before the guard, whose watch may abandon it until the guard is gone.
  std::unique_ptr<VideoEncoder> encoder;
  // From here on: the checks below read images (the image module's load
  // among them), and a limit or a signal ends them as it ends a draw.
  RunGuard guard(req.timeout, limit);
  if (video) {
    if (!sequence)
      return fail("'" + req.out.string() + "': a video needs --frames COUNT or --duration SECONDS", kExitUsage);
    if (auto problem = check_video(req.out, video_settings)) return fail(*problem, kExitUsage);
  } else {
    if (!req.codec.empty() || req.crf)
      return fail("--codec and --crf are for a video (" + video_extensions() + "), not '" + req.out.string() + "'",
                  kExitUsage);
    const auto first_out = sequence ? sequence_path(req.out, 0) : std::optional(req.out);
    if (!first_out)
      return fail("'" + req.out.string() + "': --frames needs a counter such as %04d in the output name (or a video: " +
                      video_extensions() + ")",
                  kExitUsage);
    if (auto problem = unknown_output_type(*first_out)) return fail(*problem, kExitUsage);
    if (auto problem = check_output_path(*first_out)) return fail(*problem, kExitUsage);
  }
  for (size_t i = 0; i < req.channels.size(); ++i) {
    const auto& path = req.channels[i];
    std::string error;
    // Named as the user gave it: on the command line, or recorded in the take.
    const bool recorded = req.take && path == req.take->channels[i];
    const std::string given = recorded ? "take: channel " + std::to_string(i) : "--channel" + std::to_string(i);
    if (!path.empty() && !check_channel_image(path, &error))
      return fail(given + " '" + path.string() + "': " + error, kExitUsage);
  }

  const ProjectFiles from = project_files(req.scene, req.media);
  SourceOptions plain = req.source;
  plain.forced_includes = from.forced_includes;
  // Before validation, where a view the scene cannot show would stop at the
  // wrapper's #error instead of this one line.
  if (req.view != View::Picture)
    if (const Source source = preprocess(from.image, plain, from.files); source.ok())
      if (auto problem = view_problem(source, req.view))
        return fail("--view " + std::string(to_string(req.view)) + ": " + *problem, kExitUsage);

  // The glslang worker starts while EGL opens the display.
  GlslangWarmUp glslang(kHostVersionLine);
  std::string error;
  auto context = EglContext::create(&error);
  if (!context) return fail(error, kExitUsage);
  // The project validates every pass with glslang before the driver sees it.
  Project project(from, req.source, req.channels);
  project.set_options(req.source, with_view(req.source, req.view));
  const bool built = project.reload() == ReloadStatus::Swapped;
  print_diagnostics(project.diagnostics());
  if (!built) return build_failure_status(project.diagnostics());
  Renderer renderer;
  if (std::max(req.size.x, req.size.y) > renderer.max_tile() && !project.image_source().movable_frag_coord)
    return fail("--size " + std::to_string(req.size.x) + "x" + std::to_string(req.size.y) + " is larger than " +
                    std::to_string(renderer.max_tile()) +
                    " pixels, and a shader that redeclares gl_FragCoord cannot be drawn in tiles",
                kExitUsage);
  FrameGraph graph(renderer);
  if (!graph.update(project, &error)) return fail(error, kExitUsage);

  // The shader's own uniforms: at their declared defaults, then --set.
  const UserUniforms uniforms = project.user_uniforms();
  print_diagnostics(uniforms.warnings);
  const auto values = uniform_values(uniforms, req.sets, &error);
  if (!values) return fail("--set " + error, kExitUsage);
  if (req.take)
    if (auto changes = take_source_changes(*req.take, pass_hashes(project)))
      std::cerr << "raymarching: warning: take: " << *changes << '\n';

  // Frames drawn apart from the ones before them would lack what those fed into them.
  const char* apart = req.frame_range ? "--frame-range" : req.skip_existing ? "--skip-existing" : nullptr;
  if (apart && project.has_feedback())
    return fail(std::string(apart) + ": this project feeds each frame into the next (a buffer reads itself or a "
                "later pass), so its frames cannot be rendered apart; render it in one run",
                kExitUsage);
  // The frames this run draws, numbered as in the whole sequence.
  const int first = req.frame_range ? req.frame_range->x : 0;
  MotionBlur motion{req.shutter, req.motion_samples, req.fps, {}};
  const int count = req.frame_range ? req.frame_range->y - first + 1 : sequence ? req.frames : 1;
  const int first_frame = static_cast<int>(first_iframe);
  const auto date = req.date.value_or(std::chrono::system_clock::now());
  // A take's frame `n`: its inputs where the replay is in the take, and what
  // happened since the frame before (a click, keys, a knob) once.
  std::optional<TakeReplay> replay;
  if (req.take) replay.emplace(*req.take, req.take_fps);
  // A knob set in the panel while the take recorded: the program it made, from that frame on.
  auto take_knobs = [&](int n) {
    const auto [first_crossed, end_crossed] = replay->crossed(n);
    for (const TakeEvent& e : req.take->events) {
      if (e.frame <= 0 || e.frame < first_crossed || e.frame >= end_crossed) continue;
      SourceOptions now = req.source;
      now.defines = e.defines;
      project.set_options(now, with_view(now, req.view));
      if (project.reload() == ReloadStatus::Failed) {
        print_diagnostics(project.diagnostics());
        error = "take: the program of frame " + std::to_string(e.frame) + " (its knobs set) does not build";
        return false;
      }
      if (!graph.update(project, &error)) return false;
    }
    return true;
  };
  auto take_frame_inputs = [&](int n, double) {
    const Take& take = *req.take;
    FrameInputs in = take_inputs_at(take, replay->wall(n), req.size, uniforms);
    in.uniforms = with_take_values(*values, in.uniforms);
    in.frame = req.take_fps > 0 ? take.frames.front().frame + n : in.frame;
    // As in the window: what iTime moved since the frame before (0 while the
    // take was paused), so that a simulation steps as it stepped live. The
    // first frame's, whose frame before is not replayed, is one at --fps.
    const double before = n > 0 ? take_inputs_at(take, replay->wall(n - 1), req.size, uniforms).time : in.time - 1.0 / req.fps;
    in.time_delta = static_cast<float>(in.time - before);
    // Frames per second of the take's wall clock, as the window counts them.
    const double wall_step = n > 0 ? replay->wall(n) - replay->wall(n - 1) : 1.0 / req.fps;
    in.frame_rate = static_cast<float>(wall_step > 0 ? 1.0 / wall_step : req.fps);
    in.date = date_of(date + std::chrono::duration_cast<std::chrono::system_clock::duration>(
                                 std::chrono::duration<double>(replay->wall(n))));
    const auto [first_crossed, end_crossed] = replay->crossed(n);
    for (int j = first_crossed; j < end_crossed; ++j) {
      const TakeFrame& f = take.frames[static_cast<size_t>(j)];
      const glm::vec2 scale = glm::vec2(req.size) / glm::vec2(f.size);
      if (f.mouse.w > 0) in.mouse = f.mouse * glm::vec4(scale, scale);  // the press, in the frame it happened
      for (const KeyEvent& k : f.keys) k.down ? graph.keyboard().press(k.code) : graph.keyboard().release(k.code);
    }
    return in;
  };
  // Motion blur in a take: the mouse and the uniforms move over the shutter as iTime does.
  double frame_wall = 0;  // where the frame being drawn is in the take
  if (replay)
    motion.move = [&](FrameInputs& in, double seconds) {
      const FrameInputs moved = take_inputs_at(*req.take, frame_wall + seconds, req.size, uniforms);
      in.time = moved.time;
      in.mouse = glm::vec4(glm::vec2(moved.mouse), in.mouse.z, in.mouse.w);
      in.cursor = moved.cursor;
      in.uniforms = with_take_values(*values, moved.uniforms);
    };
  auto inputs_at = [&](int frame, double time, double since_first) {
    if (replay) return take_frame_inputs(frame, since_first);
    FrameInputs in;
    in.resolution = glm::vec3(req.size, 1.0f);
    in.time = static_cast<float>(time);
    in.time_delta = static_cast<float>(1.0 / req.fps);
    in.frame_rate = static_cast<float>(req.fps);
    in.frame = frame;
    in.mouse = req.mouse;
    in.cursor = glm::vec2(req.mouse);
    in.uniforms = *values;
    in.date = date_of(date + std::chrono::duration_cast<std::chrono::system_clock::duration>(
                                 std::chrono::duration<double>(since_first)));
    return in;
  };
  // A project that feeds frames into later ones shows at frame N what it
  // would show live: every frame before it is drawn first.
  const bool warm_up = project.has_feedback() && first_frame > 0;
  const int total = (warm_up ? first_frame : 0) + count;
  Progress progress(total);
  for (int f = 0; warm_up && f < first_frame; ++f) {
    graph.draw_buffers(project, inputs_at(f, f / req.fps, (f - first_frame) / req.fps), req.size);
    if (f % 16 == 15) glFinish();  // bound the work queued on software renderers
    progress.show(f + 1);
  }
  // A video's frames go to ffmpeg as they are drawn; its destructor abandons
  // an encode that does not finish, and so does the time limit.
  if (video) {
    encoder = VideoEncoder::start(req.out, video_settings, &error);
    if (!encoder) return fail(error, kExitUsage);
    guard.on_end([&encoder] { encoder->abandon(); }, "the video it was writing");
  }
  // A slice of a take: the keys and knobs of the frames before it, without drawing them.
  for (int i = 0; replay && i < first; ++i) {
    if (!take_knobs(i)) return fail(error, kExitShaderError);
    take_frame_inputs(i, 0);
    graph.keyboard().end_frame();
  }
  for (int n = 0; n < count; ++n) {
    const int i = first + n;
    if (replay && !take_knobs(i)) return fail(error, kExitShaderError);
    if (replay) frame_wall = replay->wall(i);
    const FrameInputs in = inputs_at(first_frame + i, req.time + i / req.fps, i / req.fps);
    // A video's frames have no files; a still's and a sequence's each have one.
    const std::filesystem::path out = sequence && !video ? *sequence_path(req.out, i) : req.out;
    if (req.skip_existing && exists_on_disk(out)) {  // whole: frames are renamed into place
      graph.keyboard().end_frame();
      if (sequence) progress.show(total - count + n + 1);
      continue;
    }
    Image image = graph.render_frame(project, in, req.size, req.samples, motion);
    graph.keyboard().end_frame();
    if (video) {
      if (!guard.guard([&] { return encoder->add(image, &error); })) return fail(error, kExitUsage);
    } else {
      const bool written = guard.write(out, [&] {
        return write_image(out, image, frame_metadata(req.scene, req.source, in, req.samples, motion), Overwrite::Replace,
                           &error).has_value();
      });
      if (!written) return fail(error, kExitUsage);
    }
    if (sequence || warm_up) progress.show(total - count + n + 1);
  }
  if (video && !guard.write(req.out, [&] { return encoder->finish(&error); })) return fail(error, kExitUsage);
  return kExitOk;
}

}  // namespace

// Running out of memory is one line, not an abort: a --size of 16384x16384
// holds 4 GiB of floats before it is written.
int render_command(const RenderRequest& req) {
  try {
    return render_frames(req);
  } catch (const NoRoomForDriver& e) {
    return fail(e.what(), kExitUsage);
  } catch (const std::bad_alloc&) {
    // The picture is named where it alone is a lot (a channel image that is
    // too much says so where it is read).
    const double mib = 16.0 * req.size.x * req.size.y / (1 << 20);
    if (mib < 256) return fail("not enough memory for this render", kExitUsage);
    return fail("not enough memory to render " + std::to_string(req.size.x) + "x" + std::to_string(req.size.y) +
                    " pixels (" + std::to_string(static_cast<long long>(mib)) + " MiB a picture as floats)",
                kExitUsage);
  }
}

}  // namespace rm
