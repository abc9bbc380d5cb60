#include "commands/window.h"

#include "core/data_paths.h"
#include "core/supersampling.h"
#include "window/window_app.h"

namespace rm::cli {

WindowCommand::WindowCommand(CLI::App& app) {
  app.add_option("scene", scene_, "Shader or Shadertoy .json to open (default: the bundled default scene)")->type_name("SCENE");
  app.add_option("--media", media_, "Where a .json's shadertoy.com media are, by file name")->type_name("DIR");
  source_.add_to(app);
  app.add_option("--size", size_, "Window size in screen coordinates")->type_name("WxH");
  app.add_option("--shot-dir", shot_dir_, "Directory for F12 screenshots")->type_name("DIR");
  app.add_option("--shot-format", shot_format_, "Screenshot format")->check(CLI::IsMember({"png", "exr"}));
  app.add_option("--shot-scale", shot_scale_, "Render screenshots at N times the window's pixels")->check(whole_between(1, 16));
  app.add_option("--watch", watch_, "File watching backend")->check(CLI::IsMember({"auto", "inotify", "poll"}));
  app.add_flag("-v,--verbose", verbose_, "Log reloads and presented frames to stderr");
  app.add_flag("--no-ui", no_ui_, "Start with the interface hidden (F2 shows it)");
  app.add_flag("--hud", hud_, "Start with the HUD shown (F3 toggles it)");
  app.add_flag("--controls", controls_, "Start with the controls panel open");
  app.add_option("--target-fps", target_fps_, "Frame budget: a changing picture is drawn at a lower resolution "
                                              "(down to 1/8 per axis), and a heavy one in tiles, to hold this rate; "
                                              "0 turns it off (full size, a heavy picture still in tiles of 100 ms)")
      ->type_name("F")->check(finite_between(0.0, 1000.0));
  app.add_option("--tile-limit", tile_limit_, "A shader whose smallest tile takes longer is reported too slow and "
                                              "no longer drawn, until the next save")
      ->type_name("SECONDS")->check(finite_between(0.001, 3600.0));
  app.add_option("--refine", refine_, "A picture at rest is refined to N supersamples per pixel, as render "
                                      "--samples N draws them; 0 or 1 turns it off")
      ->type_name("N")->check(whole_between(0, kMaxSamples));
  channels_.add_to(app);
}

int WindowCommand::run() const {
  WindowOptions opts;
  opts.scene = scene_.empty() ? default_scene() : std::filesystem::path(scene_);
  require_readable_file(opts.scene);
  opts.media = media_;
  opts.source = source_.source();
  opts.size = parse_size(size_, "--size");
  opts.shot_dir = shot_dir_;
  std::error_code ec;
  if (!std::filesystem::is_directory(opts.shot_dir, ec)) throw UsageError{"--shot-dir '" + shot_dir_ + "': not a directory"};
  opts.shot_format = shot_format_;
  opts.shot_scale = shot_scale_;
  opts.channels = channels_.get();
  opts.watch = watch_ == "poll"      ? WatchBackend::Poll
               : watch_ == "inotify" ? WatchBackend::Inotify
                                     : WatchBackend::Auto;
  opts.verbose = verbose_;
  opts.interface = !no_ui_;
  opts.hud = hud_;
  opts.controls = controls_;
  opts.target_fps = target_fps_;
  opts.tile_limit_s = tile_limit_;
  opts.refine = std::max(1, refine_);
  return run_window(opts);
}

}  // namespace rm::cli
