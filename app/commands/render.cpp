#include "commands/render.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>

#include "core/knobs.h"
#include "core/supersampling.h"
#include "core/take.h"
#include "core/views.h"
#include "headless/render_command.h"
#include "headless/video.h"

namespace rm::cli {

namespace {
constexpr int kMaxFrames = 1000000;  // --frames, and --duration x --fps
}  // namespace

RenderCommand::RenderCommand(CLI::App& app)
    : command_(app.add_subcommand("render", "Render SCENE headless through EGL (no display, no GPU needed)")) {
  CLI::App& c = *command_;
  c.add_option("scene", scene_, "Shader or Shadertoy .json to render (or --take)")->type_name("SCENE");
  c.add_option("--take", take_, "Render a take recorded in the window (F9): its scene, -I/-D and every frame's "
                                "inputs, as recorded or resampled at --fps")->type_name("TAKE");
  c.add_option("--media", media_, "Where a .json's shadertoy.com media are, by file name")->type_name("DIR");
  c.add_option("-o,--output", out_, "Output picture: .png (8-bit, clamped), .exr (raw float), .jpg, .tif, ... "
                                    "(OpenImageIO's); or a video through ffmpeg: .mp4 or .mov (H.264), .webm (VP9), .gif")->required()->type_name("OUT");
  source_.add_to(c);
  c.add_option("--size", size_, "Picture size in pixels")->type_name("WxH");
  c.add_option("--time", time_, "iTime of the (first) frame in seconds")->type_name("T");
  c.add_option("--frame", frame_, "iFrame of the (first) frame (default: time * fps)")->type_name("N")->check(whole_between(0, INT_MAX));
  auto* frames = c.add_option("--frames", frames_, "Render COUNT frames; OUT is a video, or needs a counter like "
                                                   "frame_%04d.png")->type_name("COUNT")->check(whole_between(1, kMaxFrames));
  c.add_option("--duration", duration_, "Render SECONDS of frames at --fps (instead of --frames)")
      ->type_name("SECONDS")->check(finite_between(0.001, 1e6))->excludes(frames);
  c.add_option("--frame-range", frame_range_, "Render only frames FIRST to LAST of the --frames sequence, numbered "
                                            "as in the whole run, so that runs on several machines make it up")
      ->type_name("FIRST:LAST");
  c.add_flag("--skip-existing", skip_existing_, "Draw only the frames whose files are not there yet (each was written "
                                                "whole): a stopped run, started again, goes on where it stopped");
  auto* motion = c.add_option("--motion-samples", motion_samples_, "Motion blur: average N times over the open "
                                                                 "shutter in every frame")
                     ->type_name("N")->check(whole_between(1, 256));
  c.add_option("--shutter", shutter_, "Motion blur: the share of the frame interval the shutter is open, centred on "
                                      "the frame's time (default 0.5, with --motion-samples)")
      ->type_name("FRACTION")->check(finite_between(0.0, 1.0))->needs(motion);
  c.add_option("--codec", codec_, "A video's ffmpeg encoder (default: libx264 for .mp4 and .mov, libvpx-vp9 for .webm)")
      ->type_name("NAME");
  c.add_option("--crf", crf_, "A video's quality, lower is better (default: 18 for H.264, 32 for VP9)")
      ->type_name("N")->check(whole_between(0, 63));
  c.add_option("--fps", fps_, "Frames per second of a sequence")->type_name("F")->check(finite_between(0.001, 100000.0));
  c.add_option("--mouse", mouse_, "iMouse as X,Y[,CX,CY] in pixels")->type_name("X,Y[,CX,CY]");
  c.add_option("--set", sets_, "A value for one of the shader's own uniforms (repeatable; a screenshot records "
                               "every value this way)")->type_name("NAME=VALUE");
  c.add_option("--date", date_, "iDate as local YYYY-MM-DDTHH:MM:SS[.sss] (default: now)")->type_name("DATE");
  c.add_option("--view", view_, "A debug view instead of the picture: map() calls per pixel as a heatmap, "
                                "normals, depth, or NaN/Inf pixels in magenta")
      ->check(CLI::IsMember({"steps", "normals", "depth", "nan"}));
  c.add_option("--samples", samples_, "Supersamples per pixel, averaged: sub-pixel offsets from the pixel's centre "
                                      "(the window's --refine takes the same ones)")
      ->type_name("N")->check(whole_between(1, kMaxSamples));
  c.add_option("--timeout", timeout_, "Stop a render that runs longer, with exit status 124; nothing it wrote "
                                      "is left")->type_name("SECONDS")->check(finite_between(0.001, 1e8));
  channels_.add_to(c);
}

// `render --take`: the scene, its -I/-D (the command line's after the
// take's), the size and the frames come from the take.
void RenderCommand::take_into(RenderRequest& req) const {
  if (!scene_.empty()) throw UsageError{"--take names its own scene: give SCENE or --take, not both"};
  for (const char* option : {"--time", "--frame", "--frames", "--duration", "--mouse", "--set", "--date"})
    if (command_->count(option) > 0)
      throw UsageError{std::string(option) + ": a take gives every frame's inputs; leave it out with --take"};
  // read_take refuses what is not a regular file, and a take may be larger than a shader.
  std::string error;
  std::optional<Take> take = read_take(take_, &error);
  if (!take) throw UsageError{error};
  req.scene = take->scene;
  if (media_.empty()) req.media = take->media;
  SourceOptions from_command_line = req.source;
  req.source.include_dirs = take->include_dirs;
  req.source.include_dirs.insert(req.source.include_dirs.end(), from_command_line.include_dirs.begin(),
                                 from_command_line.include_dirs.end());
  req.source.defines = take->defines_at(0);
  for (const Define& d : from_command_line.defines)
    req.source.defines = with_define(req.source.defines, d.name, d.value.empty() ? "1" : d.value);
  // The take's -U's, and the command line's, which also take back the take's -D of the name.
  req.source.undefines = take->undefines;
  for (const std::string& name : from_command_line.undefines) {
    req.source.defines = with_define(req.source.defines, name, "");
    if (std::find(req.source.undefines.begin(), req.source.undefines.end(), name) == req.source.undefines.end())
      req.source.undefines.push_back(name);
  }
  if (command_->count("--size") == 0) req.size = take->frames.front().size;
  // Without --fps, the take's own frames; a video of them plays at their mean rate.
  req.take_fps = command_->count("--fps") > 0 ? fps_ : 0.0;
  const double span = take->duration();
  req.fps = req.take_fps > 0 ? req.take_fps : span > 0 ? (take->frames.size() - 1) / span : 60.0;
  req.frames = TakeReplay(*take, req.take_fps).frames();
  if (req.frames > kMaxFrames) {
    char message[160];
    std::snprintf(message, sizeof message, "the take at %g frames a second is %s%d frames; at most %d", req.fps,
                  req.frames == INT_MAX ? "over " : "", req.frames, kMaxFrames);
    throw UsageError{message};
  }
  if (!is_video_path(req.out) && !sequence_path(req.out, 0))
    throw UsageError{"'" + req.out.string() + "': a take is a sequence of " + std::to_string(req.frames) +
                     " frames: give OUT a counter such as %04d, or a video (" + video_extensions() + ")"};
  if (!take->date.empty()) req.date = parse_date(take->date);
  req.take = std::move(take);
}

int RenderCommand::run() const {
  if (scene_.empty() && take_.empty()) throw UsageError{"render needs SCENE, or --take TAKE"};
  RenderRequest req;
  req.scene = scene_;
  req.source = source_.source();
  req.out = out_;
  req.size = parse_size(size_, "--size");
  req.media = media_;
  if (!take_.empty()) take_into(req);
  require_readable_file(req.scene);
  check_project_file(req.scene, req.media);
  req.time = parse_number(time_, "--time");
  if (frame_ >= 0) req.frame = frame_;
  if (!req.take) {
    req.frames = frames_;
    req.fps = fps_;
  }
  if (duration_ > 0) {
    // The bound of --frames: a long duration at a high rate is more frames than an int holds.
    const double frames = std::max(1.0, std::round(duration_ * fps_));
    if (frames > kMaxFrames) {
      char message[160];
      std::snprintf(message, sizeof message, "--duration %g at --fps %g is %.0f frames; at most %d", duration_, fps_,
                    frames, kMaxFrames);
      throw UsageError{message};
    }
    req.frames = static_cast<int>(frames);
  }
  req.codec = codec_;
  if (!frame_range_.empty()) req.frame_range = parse_frame_range(frame_range_, "--frame-range");
  // OUT with a counter and no --frames is a sequence of one frame, f_0000.png, not a file named f_%04d.png.
  if (req.frames == 0 && !req.frame_range && !is_video_path(req.out) && sequence_path(req.out, 0)) req.frames = 1;
  if (crf_ >= 0) req.crf = crf_;
  if (!view_.empty()) req.view = *view_from_string(view_);
  if (!mouse_.empty()) req.mouse = parse_mouse(mouse_);
  if (!date_.empty()) req.date = parse_date(date_);
  req.channels = channels_.get();
  // A take's --channelN, as the window had them, unless the command line gives its own.
  for (size_t c = 0; req.take && c < 4; ++c)
    if (req.channels[c].empty()) req.channels[c] = req.take->channels[c];
  req.sets = sets_;
  req.timeout = timeout_;
  req.skip_existing = skip_existing_;
  req.samples = samples_;
  req.motion_samples = motion_samples_;
  req.shutter = motion_samples_ > 1 ? (shutter_ >= 0 ? shutter_ : 0.5) : 0.0;
  if (req.samples * req.motion_samples > kMaxSamples)
    throw UsageError{"--samples " + std::to_string(req.samples) + " x --motion-samples " +
                     std::to_string(req.motion_samples) + ": at most " + std::to_string(kMaxSamples) + " draws a pixel"};
  return render_command(req);
}

}  // namespace rm::cli
