#include "window/window_app.h"

// epoxy is the GL loader; GLFW must not pull in its own GL header.
#include "core/gl.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <ctime>
#include <iostream>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <utility>

#include "core/address_space.h"
#include "core/capture.h"
#include "core/channels.h"
#include "core/frame_budget.h"
#include "core/frame_graph.h"
#include "core/driver_ready.h"
#include "core/files.h"
#include "core/hw_performance.h"
#include "core/project.h"
#include "core/gl_census.h"
#include "core/gl_debug.h"
#include "core/glslang_client.h"
#include "core/glslviewer_passes.h"
#include "core/views.h"
#include "core/stop_signals.h"
#include "core/wake_on_readable.h"
#include "core/watch.h"
#include "core/renderer.h"
#include "core/knobs.h"
#include "core/scene.h"
#include "core/stderr_shut.h"
#include "window/builder.h"
#include "window/display_lost.h"
#include "window/kept_picture.h"
#include "window/key_codes.h"
#include "window/panels.h"
#include "window/shot_writer.h"
#include "window/steady_ns.h"
#include "window/take_recorder.h"
#include "window/tiled_shot.h"
#include "window/ui.h"

namespace rm {

const char* window_keys_help() {
  return "keys:\n"
         "  F12          screenshot (PNG, or --shot-format exr)\n"
         "  Space        pause / resume time\n"
         "  R            restart time and frame counter\n"
         "  Left/Right   step time by 1/60 s (while paused)\n"
         "  F9           start / stop recording a take (render it with: raymarching render --take)\n"
         "  F11          toggle fullscreen\n"
         "  V            cycle views: picture, steps, normals, depth, nan\n"
         "  F2           hide / show the interface (errors, HUD, controls)\n"
         "  F3           HUD: frame times on the CPU and GPU, fps, iTime, passes\n"
         "  Esc, Q       quit\n"
         "  F1           print these keys\n"
         "  A project that reads the keyboard (#pragma channelN keyboard) gets every\n"
         "  key but F1-F12 and Esc; quit it with Esc.\n"
         "mouse:\n"
         "  left drag    iMouse (moves the light in the examples)\n";
}

namespace {

// GLFW's errors while the window is being made are held, and the host's one
// line says the last; once it is made, each is printed as it comes.
std::string glfw_held_error;
bool glfw_errors_held = true;
void on_glfw_error(int, const char* message) {
  if (glfw_errors_held) glfw_held_error = message;
  else std::cerr << "raymarching: glfw: " << message << '\n';
}

bool mesa_cache_disabled() {
  for (const char* name : {"MESA_SHADER_CACHE_DISABLE", "MESA_GLSL_CACHE_DISABLE"}) {
    const char* value = std::getenv(name);
    if (value && (std::string(value) == "true" || std::string(value) == "1")) return true;
  }
  return false;
}

class WindowApp {
 public:
  WindowApp(const WindowOptions& options, GLFWwindow* window)
      : options_(options), window_(window), source_(options.source), building_source_(options.source),
        shown_source_(options.source),
        project_(project_files(options.scene, options.media), options.source, options.channels),
        watcher_(make_watcher(options.watch)), wake_on_save_(watcher_->event_fd(), [] { glfwPostEmptyEvent(); }),
        wake_on_signal_(stop_signals_.fd(), [] { glfwPostEmptyEvent(); }),
        graph_(renderer_), builder_(window), ui_(window),
        budget_(options.target_fps > 0 ? 1000.0 / options.target_fps : 0.0) {
    glfwGetCursorPos(window_, &cursor_.first, &cursor_.second);
    model_.values = &inputs_.uniforms;
    model_.hud = options.hud;
    if (options.controls) model_.open_controls = true;
    ui_.set_visible(options.interface);
  }

  ~WindowApp() { on_display_lost({}); }  // its last words are this window's

  // A build still running once run() has returned: the driver may compile
  // a large shader for a minute more.
  bool building() const { return builder_.running() || background_.running(); }

  int run() {
    on_display_lost([this] { write_what_is_left(); });
    for (size_t i = 0; i < options_.channels.size(); ++i) {
      const auto& path = options_.channels[i];
      std::string error;
      if (!path.empty() && !check_channel_image(path, &error)) {
        std::cerr << "raymarching: error: --channel" << i << " '" << path.string() << "': " << error << '\n';
        return kExitUsage;
      }
    }
    // The first program is built as a save's is, on the builder: the window
    // shows its grey and answers Q while the driver compiles (a large shader
    // held a window that could not be quit for a minute).
    watcher_->watch({options_.scene});
    load();
    // Made while the first program builds: made before it, its two contexts
    // held the first picture back (50 ms as hidden windows, now about 16).
    background_.open(window_);
    while (!glfwWindowShouldClose(window_) && !quit_) {
      // A picture that cannot change is drawn once: then sleep until an event
      // or a save (wake_on_save_), or until the watcher or a background build
      // needs the loop (idle_wait_s). A picture drawn in tiles comes back
      // here between slices of tiles.
      // An atlas with letters the interface lacked: its text is drawn again.
      if (ui_.fonts_arrived()) ui_frames_ = std::max(ui_frames_, 1);
      auto busy = [&] {
        return load_after_tile_ || redraw_needed() || ui_frames_ > 0 || (drawing_ && !holds_for_build()) ||
               (refining() && builders_idle()) || shot_requested_ || (!shots_.empty() && !holds_shots());
      };
      if (busy()) glfwPollEvents();
      else glfwWaitEventsTimeout(idle_wait_s());
      if (watcher_->changed() || std::exchange(load_after_tile_, false)) load();
      wake_on_save_.rearm();
      // Ctrl-C in the terminal, or a kill: quit as Q does, so that a take
      // being recorded is written and no half file is left.
      if (stop_signals_.received()) quit_ = true;
      if (const std::optional<ReloadStatus> built = builder_.finished()) take_build(*built);
      // A background build is taken with no save's build under way: that
      // one changes the project its results are checked against.
      if (!builder_.busy())
        if (const std::optional<ReloadStatus> built = background_.finished()) take_background(*built);
      if (builders_idle()) background_build();
      if (busy() && !quit_) frame(redraw_needed());
    }
    // Gone from the screen at once: a build under way, the teardown and the
    // process's exit (llvmpipe's threads, LLVM) come after it.
    glfwHideWindow(window_);
    if (options_.verbose) std::cerr << "raymarching: window hidden at " << steady_ns() << '\n';
    if (take_.recording()) finish_take();  // quitting ends a take as F9 does
    for (const TiledShot& shot : shots_)
      std::cerr << "raymarching: screenshot not taken: the window closed before " << shot.path().string() << " was drawn\n";
    if (options_.verbose) std::cerr << "raymarching: drew " << frames_drawn_ << " frames\n";
    if (const int signal = stop_signals_.received()) {
      std::cerr << "raymarching: the window was closed by " << signal_name(signal) << '\n';
      return 128 + signal;  // as a shell reports a program a signal ended
    }
    return kExitOk;
  }

  // A press over a panel is the interface's, and so is its drag: iMouse
  // follows only presses on the picture.
  void on_mouse_button(int button, int action, int mods) {
    ui_.on_mouse_button(button, action, mods);
    ui_event();
    if (button != GLFW_MOUSE_BUTTON_LEFT) return;
    if (action == GLFW_PRESS && ui_.covers(cursor_window())) {
      ui_holds_mouse_ = true;
      return;
    }
    if (action == GLFW_RELEASE && std::exchange(ui_holds_mouse_, false)) return;
    if (action == GLFW_PRESS) mouse_.press(cursor_pixels());
    else if (action == GLFW_RELEASE) mouse_.release();
    if (use_.drag) dirty_ = true;
  }
  void on_cursor(double x, double y) {
    cursor_ = {x, y};
    ui_event();
    if (ui_holds_mouse_) return;
    mouse_.move(cursor_pixels());
    if (use_.pointer || (use_.drag && mouse_.imouse().z > 0.0f)) dirty_ = true;
  }
  // Events the interface alone reads.
  void on_char(unsigned int codepoint) { ui_.on_char(codepoint); ui_event(); }
  void on_scroll(double x, double y) { ui_.on_scroll(x, y); ui_event(); }
  void on_cursor_enter(bool entered) { ui_.on_cursor_enter(entered); ui_event(); }
  void on_focus(bool focused) { ui_.on_focus(focused); ui_event(); }
  // An uncovered window: its contents again.
  void on_refresh() { show_again(); }
  // Nothing is drawn while minimised, animated or not.
  void on_iconify(bool iconified) {
    iconified_ = iconified;
    if (!iconified) show_again();
    if (options_.verbose) std::cerr << "raymarching: " << (iconified ? "minimised" : "restored") << '\n';
  }
  // A minimised window may report 0x0; frame() then draws nothing.
  void on_resize(int width, int height) {
    dirty_ = true;
    if (options_.verbose) std::cerr << "raymarching: framebuffer " << width << "x" << height << '\n';
  }
  void on_key(int key, int scancode, int action, int mods);

 private:
  // The cursor in framebuffer pixels, origin at the bottom left (GL's), where
  // the last event put it. glfwGetCursorPos would ask X11 where the pointer is
  // now: with events queued behind a slow frame, a press would then take the
  // position of a later move.
  glm::vec2 cursor_pixels() const {
    const auto [x, y] = cursor_;
    int w = 0, h = 0, fw = 0, fh = 0;
    glfwGetWindowSize(window_, &w, &h);
    glfwGetFramebufferSize(window_, &fw, &fh);
    const double sx = w > 0 ? double(fw) / w : 1.0, sy = h > 0 ? double(fh) / h : 1.0;
    return {static_cast<float>(x * sx), static_cast<float>(fh - y * sy)};
  }
  glm::vec2 cursor_window() const { return {static_cast<float>(cursor_.first), static_cast<float>(cursor_.second)}; }

  // The interface is immediate-mode: after an event it is drawn a few times
  // (a hover shows a frame after the move), over the kept picture.
  void ui_event() {
    if (ui_.visible()) ui_frames_ = 3;
  }

  // A reload with the options as they are now (-D, the view). It is built on
  // the builder's thread while the running program keeps drawing; one asked
  // for during a save's build starts when that one is done. A background
  // build (a twin, a tweak's exact program) works on copies (Scene's jobs)
  // on a builder of its own. A save meanwhile that needs no compile (a
  // number edit the twin shows, a text built before) is shown at once; one
  // that needs a compile is built at once, beside the background build's
  // stage under way, which puts that build off (a code edit of tori waited
  // for it). `show_now` false: from within a tile, whose picture showing it
  // would change under it, so the loop loads again once the tile is done.
  void load(bool show_now = true) {
    if (builder_.busy()) {
      load_again_ = true;
      background_.cancel();  // it would be built for a picture about to go
      return;
    }
    project_.set_options(source_, with_view(source_, view_));
    if (background_building()) {
      const ReloadStatus status = project_.prepare_without_compiling();
      if (status != ReloadStatus::NeedsCompile) {
        if (status != ReloadStatus::Failed && read_stale_images_then_take(status)) return;
        if (show_now) show_without_compiling(status);
        else load_after_tile_ = true;
        return;
      }
      background_.cancel();  // a save goes before a twin, or a tweak's exact program
    }
    building_source_ = source_;
    if (!builder_.available()) {
      loaded(project_.reload());
      return;
    }
    log_build_start();
    ImageTextures::HeldImages held = graph_.images_held();
    builder_.start([this, warm = warm_up_hook(held, builder_, &images_read_), held = std::move(held)] {
      images_read_.clear();
      const ReloadStatus status =
          project_.prepare(warm, [this] { return builder_.cancelled(); },
                           [this](const std::vector<std::function<void()>>& jobs) { builder_.run_jobs(jobs, background_); });
      if (status != ReloadStatus::Failed) read_images(project_.images_read(), held);
      return status;
    });
  }

  void log_build_start() const {
    if (options_.verbose) std::cerr << "raymarching: building generation " << project_.generation() + 1 << " at " << steady_ns() << '\n';
  }

  // On the builder: the images of `specs` that changed on disk since
  // `held`, read into images_read_ for the graph.
  void read_images(const std::vector<ChannelSpec>& specs, const ImageTextures::HeldImages& held) {
    for (const ChannelSpec& spec : specs) read_ahead(spec, held, images_read_);
    glFinish();  // complete before the window's context draws with them
  }

  // What project_.prepare_without_compiling() gave, taken once the saves'
  // builder has read the images that changed on disk (read on the window's
  // thread, a large one held it: 4096x4096 noise, 1.1 s); nothing compiles.
  // False, with nothing started, where no image changed.
  bool read_stale_images_then_take(ReloadStatus status) {
    ImageTextures::HeldImages held = graph_.images_held();
    std::vector<ChannelSpec> specs = project_.images_read();
    if (std::none_of(specs.begin(), specs.end(), [&](const ChannelSpec& s) { return ImageTextures::stale(s, held); }))
      return false;
    if (status == ReloadStatus::Swapped) background_.cancel();  // it was for the picture about to go
    building_source_ = source_;
    log_build_start();
    builder_.start([this, status, held = std::move(held), specs = std::move(specs)] {
      images_read_.clear();
      read_images(specs, held);
      return status;
    });
    return true;
  }

  // What project_.prepare_without_compiling() gave, shown.
  void show_without_compiling(ReloadStatus status) {
    if (options_.verbose)
      std::cerr << "raymarching: shown without compiling during a background build at " << steady_ns() << '\n';
    building_source_ = source_;
    if (status == ReloadStatus::Swapped) {
      project_.commit();
      background_.cancel();  // it was for the picture shown before
    }
    loaded(status);
  }

  // A save's finished build: its program on screen; then the build of a
  // save that came meanwhile.
  void take_build(ReloadStatus built) {
    if (built == ReloadStatus::Swapped) project_.commit();
    graph_.hand_over(std::exchange(images_read_, {}));
    loaded(built, builder_.job_threads());
    if (!builder_.error().empty()) {  // the last good picture stays, under the stale badge
      show_error(builder_.error());
      ++errors_;
      update_title(true);
    }
    shots_wait_for_build_ = false;
    if (std::exchange(load_again_, false)) load();
  }

  // A finished background build: its twins kept, or the tweak's exact
  // program on screen, where they still hold.
  void take_background(ReloadStatus built) {
    // Nobody waits for it: what it could not build is built when a save asks.
    if (!background_.error().empty())
      std::cerr << "raymarching: warning: a background build failed: " << background_.error() << '\n';
    if (std::exchange(twin_build_, false)) {
      const bool taken = project_.take_twins(std::exchange(twin_results_, {}));
      if (taken) project_.commit_twins();
      if (project_.ready()) take_knobs();  // a float knob's change may now be a tweak
      // Unchanged but not cancelled: the twins were current already, or
      // there is nothing to lift, or glslang or the driver rejected them.
      // Built but not taken: a save's program came meanwhile, whose twins
      // are built next.
      if (options_.verbose)
        std::cerr << "raymarching: "
                  << (built == ReloadStatus::Swapped ? (taken ? "twins built" : "stale twins dropped")
                      : background_.cancelled()      ? "twins put off"
                                                     : "no new twins")
                  << " for generation " << project_.generation() << " in "
                  << (steady_ns() - twins_started_ns_) / 1e6 << " ms, at " << steady_ns() << '\n';
      if (options_.verbose) log_constants_compiled();
    } else if (std::exchange(exact_build_, false)) {
      const bool put_off = background_.cancelled();
      const ReloadStatus status = project_.take_exact(std::exchange(exact_results_, {}));
      if (status == ReloadStatus::Swapped) project_.commit();
      if (put_off && status == ReloadStatus::Unchanged) {
        settle_tried_ = -1;  // put off: built again once saves pause
        if (options_.verbose) std::cerr << "raymarching: the tweak's exact program put off at " << steady_ns() << '\n';
      }
      taking_exact_ = true;
      loaded(status);
      taking_exact_ = false;
    }
  }

  // On the builder: the texture of a channel image the build binds, read
  // there where the graph has not read it or it changed on disk since
  // (`held`: the graph's images when the build started), once a build; the
  // graph takes it. 0 where the graph's own is current, or where the file
  // cannot be read: the graph then says why, without reading it again. A
  // large image held the window for its decoding and upload (4096x4096
  // noise: 1.2 s). `read`: where that build keeps what it read; the
  // build's passes warm up on two threads (Builder::run_jobs), which take
  // turns here.
  using ImagesRead = std::vector<std::pair<ChannelSpec, ImageTextures::Entry>>;
  static GLuint read_ahead(const ChannelSpec& spec, const ImageTextures::HeldImages& held, ImagesRead& read) {
    static std::mutex reading;
    const std::lock_guard<std::mutex> lock(reading);
    if (!ImageTextures::stale(spec, held)) return 0;
    for (const auto& [done, texture] : read)
      if (ImageTextures::key_of(done) == ImageTextures::key_of(spec)) return texture.texture.get();
    read.emplace_back(spec, ImageTextures::read(spec));
    return read.back().second.texture.get();
  }

  // Each new program is drawn once into its pass's format, with what the
  // pass reads now where its channels are bound as before, with the images
  // the graph will read anew (read ahead), and elsewhere (a new pass, a
  // channel the save changed) with textures like those it will read; and
  // drawn so again in the probe context of the thread's builder (`builder`,
  // or the one whose contexts Builder::run_jobs lent), so that Mesa's cache
  // holds its code before the window draws it. `held`:
  // the graph's images as the build starts (read_ahead). `read`: where the
  // images it reads go; without it (a background build, which the graph
  // takes no images from), an image the graph holds stale is stood in for.
  OnBuilt warm_up_hook(ImageTextures::HeldImages held, Builder& builder, ImagesRead* read) {
    return [this, &builder, read, states = graph_.pass_states(project_), held = std::move(held)](
               const fs::path& pass, const Program& program, const Source& source) {
      if (!warm_up_) return;
      const std::array<ChannelSpec, 4> channels = project_.channels_of(pass, source);
      FrameGraph::StandIns stand_ins = graph_.stand_ins(source.cubemap, channels, held);
      FrameGraph::PassState& state = stand_ins.state;
      const auto now = states.find(pass);
      if (now != states.end()) state.format = now->second.format;
      for (size_t c = 0; c < 4; ++c) {
        if (now != states.end() && now->second.specs[c] == channels[c]) state.channels[c] = now->second.channels[c];
        else if (channels[c].kind == ChannelSpec::Kind::Image && read)
          if (const GLuint texture = read_ahead(channels[c], held, *read)) state.channels[c].texture = texture;
      }
      warm_up(program, state.format, state.channels);
      builder.in_probe_context([&] { warm_up(program, state.format, state.channels); });
    };
  }

  // The builds nobody waits for (core/tweak.h), once the saves have paused:
  // a tweak's exact program, and the twins that show the next number edit
  // at once. They leave the picture moving at its pace.
  bool wants_background_build() const {
    // Both builders: a save built in place would change the project under the background's.
    return builder_.available() && background_.available() && ((project_.tweaked() && settle_tried_ != project_.generation()) || project_.wants_twins());
  }
  void background_build() {
    if (!wants_background_build() || steady_ns() - last_swap_ns_ < kBackgroundDelayNs) return;
    // Each runs on copies (Scene's jobs) on a builder of its own, so that a
    // save meanwhile is shown at once where it needs no compile
    // (show_without_compiling), and built at once beside it where it does.
    if (project_.tweaked() && settle_tried_ != project_.generation()) {
      settle_tried_ = project_.generation();
      exact_build_ = true;
      if (options_.verbose)
        std::cerr << "raymarching: building the tweak's exact program, generation " << project_.generation() + 1
                  << ", at " << steady_ns() << '\n';
      background_.start([this, jobs = project_.exact_jobs(), warm = warm_up_hook(graph_.images_held(), background_, nullptr)] {
        exact_results_ = Project::build_exact(jobs, warm, [this] { return background_.cancelled(); });
        const bool any = std::any_of(exact_results_.begin(), exact_results_.end(),
                                     [](const Scene::ExactResult& r) { return r.built.has_value(); });
        return any ? ReloadStatus::Swapped : ReloadStatus::Unchanged;
      });
    } else if (project_.wants_twins()) {
      twin_build_ = true;
      twins_started_ns_ = steady_ns();
      if (options_.verbose) std::cerr << "raymarching: building twins at " << twins_started_ns_ << '\n';
      background_.start([this, jobs = project_.twin_jobs(), warm = warm_up_hook(graph_.images_held(), background_, nullptr)] {
        twin_results_ = Project::build_twins(jobs, warm, [this] { return background_.cancelled(); });
        const bool any = std::any_of(twin_results_.begin(), twin_results_.end(),
                                     [](const Scene::TwinResult& r) { return r.twin.has_value(); });
        return any ? ReloadStatus::Swapped : ReloadStatus::Unchanged;
      });
    }
  }

  // `job_threads`: how many threads the passes' links and warm-ups ran on.
  void loaded(ReloadStatus status, int job_threads = 1) {
    watcher_->watch(project_.watch_list());
    std::string channel_error;
    if (status == ReloadStatus::Unchanged) {  // a channel image may have changed
      if (project_.ready() && !graph_.update(project_, &channel_error)) show_error(channel_error);
      if (graph_.images_changed()) {
        dirty_ = true;
        if (options_.verbose) std::cerr << "raymarching: channel images changed on disk, read at " << steady_ns() << '\n';
      }
      return;
    }
    const Diagnostics& diags = project_.diagnostics();
    if (!diags.empty()) std::cerr << join(diags);
    errors_ = count_errors(diags);
    model_.errors.clear();
    model_.warnings.clear();
    for (const Diagnostic& d : diags) (d.severity == Severity::Error ? model_.errors : model_.warnings).push_back(d);
    if (project_.ready()) use_ = project_.inputs_read();
    model_.has_picture = project_.ready();
    // A tweak's exact program draws what its twin drew: the picture in
    // progress, or its refinement, goes on.
    const bool same_picture = status == ReloadStatus::Swapped && taking_exact_;
    if (status == ReloadStatus::Swapped) {
      shown_source_ = building_source_;
      take_.reloaded(shown_source_, project_);
      take_user_uniforms();
      take_knobs();
      // A new program: the picture in progress is the old one's, and what
      // the new one costs is unknown until a first small tile has measured it
      // (a tweak's twin, or its exact program, costs what the last did).
      if (!same_picture) drawing_.reset();
      if (!project_.tweaked() && !taking_exact_) {
        budget_.forget();
        buffer_cost_.clear();
        last_moving_done_ = 0;
        program_drawn_ = false;
      }
      // A shot shows the scene as saved, and records the program it shows.
      for (TiledShot& shot : shots_) shot.restart(shot_metadata(shot.inputs(), 1, shot.metadata()));
      too_slow_ = false;
      last_swap_ns_ = steady_ns();
    }
    // A new program is drawn. A failed save changes no picture: it is shown
    // again under the stale badge.
    if (status == ReloadStatus::Failed) show_again();
    else if (!same_picture) dirty_ = true;
    ui_event();
    if (status == ReloadStatus::Swapped && !graph_.update(project_, &channel_error)) show_error(channel_error);
    if (options_.verbose) {
      std::cerr << "raymarching: reload " << (status == ReloadStatus::Swapped ? "ok" : "failed") << " generation "
                << project_.generation();
      if (status == ReloadStatus::Swapped) {
        std::cerr << (project_.tweaked() ? " (tweaked:" : " (rebuilt:");
        for (const fs::path& pass : project_.rebuilt()) std::cerr << ' ' << pass.filename().string();
        const ReloadTimes& t = project_.times();
        std::cerr << "; preprocess " << t.preprocess << " ms, glslang " << t.validate << " ms, driver compile+link "
                  << t.driver << " ms, warm-up " << t.warm << " ms";
        // The passes' links and warm-ups ran side by side: their times are sums.
        if (job_threads > 1) std::cerr << ", the last two summed over " << job_threads << " threads";
        if (t.wall > 0) std::cerr << "; built in " << t.wall << " ms";
        std::cerr << ')';
      }
      std::cerr << " at " << steady_ns() << '\n';
      std::cerr << "raymarching: gl objects: " << to_string(take_gl_census()) << '\n';
    }
    update_title(true);
  }

  // The window shows what it showed again (uncovered, restored, or with the
  // stale badge now): the kept picture is presented again, with its samples.
  void show_again() {
    if (picture_.has_picture()) ui_frames_ = std::max(ui_frames_, 1);
    else dirty_ = true;
  }

  // -v: passes whose constants' numbers compile when changed, and why.
  // glslang's error is at the constant that needs one.
  void log_constants_compiled() const {
    for (const Pass& pass : project_.passes())
      if (const auto& why = pass.scene->constants_twin_rejected())
        std::cerr << "raymarching: " << pass.file.filename().string()
                  << ": a number in a const, a global, a #define or a -D compiles when changed, not tweaked, as "
                     "another constant needs it: "
                  << why->str() << '\n';
  }

  void show_error(const std::string& error) {
    std::cerr << "raymarching: error: " << error << '\n';
    model_.errors.push_back({Severity::Error, "", 0, 0, error});
    ui_event();
  }

  // The shader's own uniforms at their declared defaults, but those the
  // person set in the panel keep their values across reloads, by name.
  void take_user_uniforms() {
    UserUniforms uniforms = project_.user_uniforms();
    if (!uniforms.warnings.empty()) std::cerr << join(uniforms.warnings);
    model_.warnings.insert(model_.warnings.end(), uniforms.warnings.begin(), uniforms.warnings.end());
    std::string no_error;
    std::vector<UniformValue> values = uniform_values(uniforms, {}, &no_error).value_or(std::vector<UniformValue>{});
    for (UniformValue& v : values) {
      auto old = std::find_if(inputs_.uniforms.begin(), inputs_.uniforms.end(),
                              [&](const UniformValue& o) { return o.name == v.name; });
      if (old == inputs_.uniforms.end() || !touched_uniforms_.count(v.name)) continue;
      std::string error;
      if (auto kept = parse_uniform_value(*uniforms.find(v.name), old->text, &error)) {
        v.value = *kept;
        v.text = old->text;
      }
    }
    inputs_.uniforms = std::move(values);
    model_.uniforms = std::move(uniforms);
  }

  // shaderlib's knobs this scene uses, as its preprocessor sees them now.
  void take_knobs() {
    const std::vector<KnobControl> before = std::move(model_.knobs);
    model_.knobs.clear();
    model_.preset.clear();
    for (const Define& d : source_.defines)
      for (const char* preset : quality_presets())
        if (d.name == "RM_QUALITY" && d.value == preset_macro(preset)) model_.preset = preset;
    const Scene& scene = *project_.image().scene;
    for (const KnobValue& k : scene.knobs()) {
      KnobControl control{k, false, 0.0f};
      for (const Define& d : source_.defines) control.overridden |= d.name == k.knob->name;
      control.edit = static_cast<float>(std::atof(k.value.c_str()));
      control.live = control.overridden && !k.knob->integer && scene.tweaks_knob(k.knob->name);
      // A slider held while the knobs are read again (twins built mid-drag)
      // keeps the value it was dragged to: its release applies that one.
      for (const KnobControl& b : before)
        if (b.held && b.value.knob == k.knob) {
          control.edit = b.edit;
          control.held = true;
        }
      model_.knobs.push_back(control);
    }
  }

  // -D NAME=VALUE for every pass from now on (VALUE "": the scene's own), and a rebuild.
  void set_define(const std::string& name, const std::string& value) {
    source_.defines = with_define(source_.defines, name, value);
    load();
    if (options_.verbose) std::cerr << "raymarching: -D " << name << "=" << (value.empty() ? "(the scene's)" : value) << '\n';
  }

  void apply(const UiChanges& c) {
    if (c.uniforms) {
      for (const UniformValue& v : inputs_.uniforms) touched_uniforms_.insert(v.name);
      dirty_ = true;
    }
    if (c.toggle_pause) clock_.set_paused(!clock_.paused());
    if (c.restart) restart();
    if (c.step != 0) {
      clock_.set_paused(true);
      clock_.step(c.step / 60.0);
    }
    if (c.seek) clock_.seek(*c.seek);
    if (c.speed) clock_.set_speed(*c.speed);
    if (c.toggle_pause || c.restart || c.step || c.seek || c.speed) clock_changed();
    if (c.dismiss_warnings) model_.warnings.clear();
    if (c.knob) set_define(c.knob->first, c.knob->second);
    if (c.preset) set_define("RM_QUALITY", c.preset->empty() ? "" : preset_macro(*c.preset));
  }

  void restart() {
    clock_.restart();
    graph_.restart();
    dirty_ = true;
  }

  // The clock was paused, stepped, sought or sped: a picture that reads it
  // (or a feedback project's) is drawn again; any other would be the same.
  void clock_changed() {
    if (use_.time || project_.has_feedback()) dirty_ = true;
    update_title(true);
  }

  void step_paused(double seconds) {
    if (!clock_.paused()) return;
    clock_.step(seconds);
    clock_changed();
  }

  // One iteration's picture: the scene drawn again when `redraw`, then the
  // stale badge and the interface. The scene goes into the kept picture,
  // which is copied to the window, so that the interface can be drawn again
  // over it without the shader. Drawing straight into the window would save
  // the copy (about a millisecond), but llvmpipe generates a shader's code
  // for each target format, and the builder's warm-up draws into the kept
  // picture's: the window would generate each new program's code itself.
  void frame(bool redraw) {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    if (width <= 0 || height <= 0) {  // minimised: nothing to draw into
      glfwWaitEventsTimeout(0.05);
      clock_.tick();
      ui_frames_ = 0;
      return;
    }
    // A picture drawn because something changed once gives way to a newer
    // one; a moving one is finished first. A new window size starts over.
    if (drawing_ && (drawing_->window != glm::ivec2(width, height) || (drawing_->resting && redraw))) drawing_.reset();
    if (!drawing_ && redraw) {
      if (shots_.empty()) start_picture(width, height, true);  // a shot waiting is of the frame before: it goes first
    } else if (!drawing_ && refining() && builders_idle()) {
      start_picture(width, height, false, samples_);
    }
    // A screenshot in progress goes first: the picture waits for it, so
    // that each turn of the loop draws one slice of the budget, not two.
    // But not for a picture's buffers under way: the shot is of that
    // picture's frame, whose image reads them whole.
    if (!shots_.empty() && !holds_shots() && !buffers_under_way()) {
      continue_shot();
      // The picture on screen waits for the shot: presenting it again after
      // each slice cost a 4K shot of tori about as much as its tiles (5.8 to
      // 7.0 s; now 4.5 to 5.7).
      if (!shots_.empty() && present_can_wait()) return;
    }
    if (drawing_ && (shots_.empty() || buffers_under_way()) && !holds_for_build()) {
      continue_picture();
      // So is a picture's: in a 1280x720 window under Xvfb, presenting each
      // slice's partial picture made abstract's 16 samples 4.3 to 4.6 s,
      // against 3.9 to 4.0 s.
      if (drawing_ && present_can_wait()) return;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDisable(GL_SCISSOR_TEST);
    glViewport(0, 0, width, height);
    if (picture_.has_picture()) {
      picture_.present({width, height});
    } else {  // the grey until a first good load
      glClearNamedFramebufferfv(0, GL_COLOR, 0, kNoPictureGrey);
    }
    if (errors_ > 0) draw_stale_badge(width, height);
    draw_interface();
    // Before the swap, with this frame's inputs; a supersample under way is finished first.
    if (shot_requested_ && !(drawing_ && drawing_->inputs.sample > 0)) {
      shot_requested_ = false;
      screenshot();
    }
    glfwSwapBuffers(window_);
    last_present_ns_ = steady_ns();
    ui_frames_ = std::max(0, ui_frames_ - 1);
    // Only once the program has drawn into it: a picture held for a build
    // (holds_for_build) shows the previous program's still.
    if (presented_generation_ != drawn_generation_) {
      presented_generation_ = drawn_generation_;
      if (options_.verbose)
        std::cerr << "raymarching: presented generation " << presented_generation_ << " at " << steady_ns() << '\n';
    }
    update_title(false);
  }

  // Whether this turn of the loop may skip its present while tiles of a
  // shot or a picture are still to come: the screen already shows what it
  // would. Not for input (ui_frames_), F12, or a new program's first tiles;
  // the rest, such as a new error's badge, waits kPartialPresentIntervalNs
  // at most. Input is read between slices all the same.
  bool present_can_wait() const {
    return ui_frames_ == 0 && !shot_requested_ && presented_generation_ == drawn_generation_ &&
           steady_ns() - last_present_ns_ < kPartialPresentIntervalNs;
  }

  void draw_interface() {
    if (!ui_.visible()) return;
    model_.time = clock_.time();
    model_.paused = clock_.paused();
    model_.speed = clock_.speed();
    want_letters(ui_, model_);
    ui_.begin();
    const UiChanges changes = draw_panels(ui_, model_);
    ui_.end();
    apply(changes);
  }

  // Starts the next picture: fixes its inputs, advances the clock, draws the
  // buffer passes, and plans the image pass's tiles. A moving picture (the
  // clock runs, the left button is held) is drawn at the budget's scale; one
  // at rest at full size. Feedback projects are always drawn at full size:
  // their buffers carry pictures from frame to frame. Without `advance`, the
  // last picture's image pass again, at full size, with the same inputs:
  // sample 0 shows it again, a later sample refines it (--refine).
  void start_picture(int width, int height, bool advance, int sample = 0) {
    if (advance) take_inputs(width, height);
    if (!project_.ready() || too_slow_) {  // the grey, or the picture as it is
      dirty_ = false;  // presented once: it was presented in a loop, a core's worth, while nothing compiled
      return;
    }
    if (advance) take_.frame(inputs_);

    const bool moving = advance && ((use_.time && !clock_.paused()) || mouse_.imouse().z > 0.0f);
    if (moving) last_moving_start_ = steady_ns();
    budget_.resized(double(width) * height);
    const bool budget_on = budget_.budget_ms() > 0;
    const bool scaled = moving && budget_on && !project_.has_feedback();
    // Nothing has measured a new program's buffers yet, and they are drawn
    // whole before its image: at the last program's scale (full size at the
    // start) a heavy one would take seconds, even in tiles. Its first moving
    // picture is drawn at the smallest scale, in tiles like any other, and
    // what it costs sizes the next.
    const bool unmeasured_buffers = budget_.full_frame_ms() == 0 && project_.passes().size() > 1;
    const double scale = !scaled ? 1.0
                         : unmeasured_buffers ? ScaleController::scale_of(ScaleController::kSteps - 1)
                                              : budget_.scale();
    const glm::ivec2 window(width, height);
    FrameInputs in = inputs_at_scale(window, scale);
    in.sample = sample;
    const glm::ivec2 size(in.resolution);

    const bool timed = ui_.visible() && (model_.hud || !model_.knobs.empty());
    graph_.time_passes(timed, true);
    const long long start = steady_ns();
    // The buffer passes are drawn in continue_picture, in tiles like the
    // image, so that a heavy one holds input no longer than a slice.
    if (advance) graph_.begin_frame(project_);
    // Tiles of one budget, from the cost per pixel the last pictures
    // measured (unknown after a reload): a picture the controller sized to
    // fit (under kHoldAt of it, which leaves room for the present) is one tile.
    drawing_.emplace(Picture{in, window, size, scale, !moving,
                             TilePlan(size, slice_ms(), measured_per_pixel_ms({width, height})),
                             (steady_ns() - start) / 1e6});
    drawing_->next_buffer = advance ? 0 : project_.passes().size() - 1;
    if (sample == 0) samples_ = 0;
    if (!advance) return;
    // At rest, the picture is drawn again at full size, to be refined. Not a
    // feedback project's: that would advance its buffers while paused.
    rest_due_ = scale < 1.0 || (moving && options_.refine > 1 && !project_.has_feedback());
    ++frames_drawn_;
    // iMouse.w > 0 only in the frame of a press: the next frame must show it gone.
    dirty_ = use_.drag && inputs_.mouse.w > 0.0f;
    mouse_.end_frame();
    graph_.keyboard().end_frame();
    if (!clock_.paused()) clock_.next_frame();
  }

  // What a pixel of the current program costs at full size, as the budget
  // measured it for a window of `window` pixels; 0 before its first draw
  // (a tile plan then starts with its smallest tile).
  // How long the window draws before it reads input again: the frame
  // budget, or with the budget off (--target-fps 0) kSliceWithoutBudgetMs,
  // so that no shader freezes the window even then: its pictures are at
  // full size, and a heavy one is drawn in tiles.
  static constexpr double kSliceWithoutBudgetMs = 100;
  double slice_ms() const { return budget_.budget_ms() > 0 ? budget_.budget_ms() : kSliceWithoutBudgetMs; }

  double measured_per_pixel_ms(glm::ivec2 window) const {
    return program_drawn_ ? budget_.full_frame_ms() / (double(window.x) * window.y) : 0.0;
  }

  // A tile of the smallest size, which the plan cannot make cheaper: the one
  // the watchdog (--tile-limit) times. (A larger tile that overruns says
  // only that the shader costs more there, and the next is smaller.)
  static bool smallest_tile(glm::ivec4 tile) { return tile.z * tile.w <= TilePlan::kSmallest * TilePlan::kSmallest; }

  // The next frame's inputs for a picture of `window` at `scale` per axis:
  // its resolution, and the mouse's pixels in it.
  FrameInputs inputs_at_scale(glm::ivec2 window, double scale) const {
    const glm::ivec2 size = glm::max(glm::ivec2(1), glm::ivec2(glm::round(glm::dvec2(window) * scale)));
    const glm::vec2 ratio = glm::vec2(size) / glm::vec2(window);
    FrameInputs in = inputs_;
    in.resolution = glm::vec3(size, 1.0f);
    in.mouse *= glm::vec4(ratio, ratio);
    in.cursor *= ratio;
    return in;
  }

  // The inputs of the next frame, at the window's size: the clock ticks.
  void take_inputs(int width, int height) {
    inputs_.time_delta = clock_.tick();  // 0 while paused
    inputs_.resolution = glm::vec3(width, height, 1.0f);
    inputs_.time = static_cast<float>(clock_.time());
    inputs_.frame_rate = clock_.frame_rate();
    inputs_.frame = clock_.frame();
    inputs_.mouse = mouse_.imouse();
    inputs_.cursor = mouse_.cursor();
    inputs_.date = date_of(std::chrono::system_clock::now());
  }

  // Draws tiles of the picture in progress until one slice of the budget is
  // spent, so that the loop reads input between slices. The first tile of a
  // picture that fits the budget is the whole picture.
  void continue_picture() {
    Picture& p = *drawing_;
    const long long slice_start = steady_ns();
    do {
      if (buffer_tile()) {
        if (!drawing_) return;  // the watchdog stopped it
        continue;
      }
      const glm::ivec4 tile = p.plan.next();
      const bool first_draw = !program_drawn_;
      const long long start = steady_ns();
      graph_.draw_image(project_, p.inputs, p.size, picture_.target(p.size), tile);
      drawn_generation_ = project_.generation();
      finish_tile();  // input is read before the next
      const double ms = (steady_ns() - start) / 1e6;
      p.plan.drawn(tile, ms);
      ++p.tiles;
      picture_.mark_drawn();
      // The first draw of a program also compiles it in the driver: not a measure of the shader.
      const bool smallest = smallest_tile(tile);
      if (smallest && program_drawn_ && ms > options_.tile_limit_s * 1000.0) {
        report_too_slow(project_.passes().back().file, tile, ms);
        return;
      }
      if (!program_drawn_ && smallest) p.compile_ms = ms;
      if (!program_drawn_ && options_.verbose)
        std::cerr << "raymarching: first draw of generation " << project_.generation() << ": a " << tile.z << "x"
                  << tile.w << " tile, " << ms << " ms (the driver finishes compiling in it)\n";
      program_drawn_ = true;
      if (!first_draw && replan(ms)) return;
    } while (!p.plan.done() && (steady_ns() - slice_start) / 1e6 < slice_ms() && !holds_for_build());
    if (p.plan.done()) finish_picture();
  }

  // Waits for the tile just drawn, of a picture or a shot. A save that
  // comes meanwhile starts its build at once, beside the tile, not once the
  // slice is done (a heavy shader's tile may take seconds); a program waits
  // for the tile's end. On the builder only: a build in place would swap
  // programs mid-picture.
  void finish_tile() {
    if (!builder_.available()) {
      glFinish();
      return;
    }
    constexpr GLuint64 kSaveCheckNs = 2'000'000;
    GLsync done = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    GLbitfield flush = GL_SYNC_FLUSH_COMMANDS_BIT;
    while (glClientWaitSync(done, std::exchange(flush, 0), kSaveCheckNs) == GL_TIMEOUT_EXPIRED) {
      if (watcher_->changed()) load(false);
    }
    glDeleteSync(done);
  }

  // One tile of the next buffer pass this picture still draws; false when
  // its buffers are all drawn. Each pass's cost per pixel is kept from the
  // frame before, so that a light buffer is one tile. The watchdog looks at
  // every smallest tile but a pass's first since the reload, in which the
  // driver may still be compiling.
  bool buffer_tile() {
    auto& p = *drawing_;
    const size_t buffers = project_.passes().size() - 1;
    while (p.next_buffer < buffers) {
      const size_t index = p.next_buffer;
      const fs::path& file = project_.passes()[index].file;
      if (!p.buffer_plan) {
        if (!graph_.begin_pass(project_, index, p.size)) {
          ++p.next_buffer;  // static, and drawn: its picture is still right
          continue;
        }
        const glm::ivec2 size = graph_.pass_size(project_, index, p.size);
        const auto cost = buffer_cost_.find(file);
        p.buffer_plan.emplace(size, slice_ms(), cost == buffer_cost_.end() ? 0.0 : cost->second);
      }
      const glm::ivec4 tile = p.buffer_plan->next();
      const bool first_of_pass = p.buffer_plan->drawn_ms() == 0 && !buffer_cost_.count(file);
      const long long start = steady_ns();
      graph_.draw_pass_region(project_, index, p.inputs, tile);
      finish_tile();  // input is read before the next
      const double ms = (steady_ns() - start) / 1e6;
      if (smallest_tile(tile) && !first_of_pass && ms > options_.tile_limit_s * 1000.0) {
        report_too_slow(file, tile, ms);
        return true;
      }
      if (first_of_pass && options_.verbose)
        std::cerr << "raymarching: first draw of " << file.filename().string() << " in generation "
                  << project_.generation() << ": a " << tile.z << "x" << tile.w << " tile, " << ms << " ms\n";
      p.buffer_plan->drawn(tile, ms);
      p.buffers_ms += ms;
      ++p.buffer_tiles;
      if (p.buffer_plan->done()) {
        graph_.end_pass(project_, index);
        const glm::ivec2 size = graph_.pass_size(project_, index, p.size);
        buffer_cost_[file] = p.buffer_plan->drawn_ms() / (double(size.x) * size.y);
        p.buffer_plan.reset();
        ++p.next_buffer;
      }
      return true;
    }
    return false;
  }

  // A new program's first moving pictures are sized before anything has
  // measured what it costs (at the last program's scale, or full size at
  // the start), and a heavy one would take seconds in tiles. Once a tile
  // has measured it, a picture that would take more than twice the budget
  // is dropped, and the next is drawn at the scale that cost asks for.
  // (Not the first tile of a program: the driver finishes compiling in it.
  // Nor a tile of under a quarter of the budget, `tile_ms`: a small tile's
  // time is mostly the draw's own, and the default scene's 16x16 tiles said
  // 5.5 s for a picture of 120 ms.)
  bool replan(double tile_ms) {
    const auto& p = *drawing_;
    const double budget = budget_.budget_ms();
    if (p.resting || budget <= 0 || budget_.full_frame_ms() > 0 || project_.has_feedback() || p.plan.done() ||
        tile_ms < budget / 4)
      return false;
    const double whole_ms = p.plan.per_pixel_ms() * p.size.x * p.size.y;
    if (whole_ms <= 2 * budget) return false;
    budget_.measured(p.scale, whole_ms);
    if (budget_.scale() >= p.scale) return false;
    if (options_.verbose)
      std::cerr << "raymarching: a new program's picture at scale " << p.scale << " would take " << whole_ms
                << " ms; drawn again at scale " << budget_.scale() << '\n';
    drawing_.reset();
    dirty_ = true;
    return true;
  }

  void finish_picture() {
    const Picture& p = *drawing_;
    // The picture kept at rest, at full size, now holds this many samples.
    // A feedback project's moving picture counts too: it is never drawn
    // again at rest (that would advance its buffers), so once the clock
    // stops, its last picture is the one refined.
    samples_ = (p.resting || project_.has_feedback()) && p.scale == 1.0 ? p.inputs.sample + 1 : 0;
    model_.figures.samples = samples_;
    if (p.inputs.sample > 0) {  // the budget measured sample 0's picture, with its buffers
      frame_ms_ = p.plan.drawn_ms();
      model_.figures.tiles = p.tiles;
      log_done("sample " + std::to_string(samples_) + " of " + std::to_string(options_.refine));
      drawing_.reset();
      update_title(true);
      return;
    }
    frame_ms_ = p.buffers_ms + p.plan.drawn_ms() - p.compile_ms;
    // Between two moving pictures in a row, what the interval held besides
    // the drawing (the present, the events) is the frame's fixed cost.
    const long long done = steady_ns();
    const double interval_ms = (done - last_moving_done_) / 1e6;
    const bool in_a_row = !p.resting && last_moving_done_ > 0 && p.tiles == 1 && interval_ms < 2 * budget_.budget_ms();
    budget_.measured(p.scale, frame_ms_, in_a_row ? std::min(interval_ms - frame_ms_, budget_.budget_ms() / 2) : 0.0);
    last_moving_done_ = p.resting ? 0 : done;
    model_.figures.scale = p.scale;
    model_.figures.tiles = p.tiles;
    if (ui_.visible() && (model_.hud || !model_.knobs.empty()) && p.tiles == 1) take_figures(p.window.x, p.window.y);
    std::ostringstream what;
    what << "picture " << p.size.x << "x" << p.size.y << " scale " << p.scale;
    log_done(what.str());
    drawing_.reset();
  }

  // -v: the picture in progress is done ("WHAT in N tiles, MS ms, done at
  // NS"), in the one format the benchmarks read.
  void log_done(const std::string& what) const {
    if (!options_.verbose) return;
    const int tiles = drawing_->tiles;
    std::cerr << "raymarching: " << what << " in " << tiles << (tiles == 1 ? " tile, " : " tiles, ") << frame_ms_
              << " ms, done at " << steady_ns();
    if (const int n = drawing_->buffer_tiles; n > 0) std::cerr << ", its buffers in " << n << (n == 1 ? " tile" : " tiles");
    std::cerr << '\n';
  }

  // The watchdog: a shader whose smallest tile takes longer than the limit
  // is not drawn again until a save replaces it; the picture stays as it is.
  // A glslViewer buffer's pass is named by its file and its define.
  void report_too_slow(const fs::path& file, glm::ivec4 tile, double ms) {
    const std::optional<GlslViewerPass> buffer = glslviewer_pass_of(file);
    char message[200];
    std::snprintf(message, sizeof message,
                  "too slow: a %dx%d tile took %.2f s (--tile-limit %g s); not drawn again until the next save",
                  tile.z, tile.w, ms / 1000.0, options_.tile_limit_s);
    const Diagnostic too_slow{Severity::Error, (buffer ? buffer->file : file).string(), 0, 0,
                              (buffer ? "its " + buffer->name + " pass is " : std::string()) + message};
    std::cerr << too_slow.str() << '\n';
    model_.errors.push_back(too_slow);
    ++errors_;
    too_slow_ = true;
    drawing_.reset();
    ui_event();
    update_title(true);
  }

  void take_figures(int width, int height) {
    HudFigures& f = model_.figures;
    f.cpu_ms = f.gpu_ms = 0;
    f.passes.clear();
    for (const FrameGraph::PassTime& t : graph_.pass_times()) {
      f.cpu_ms += t.wall_ms;
      f.gpu_ms += t.gpu_ms;
      f.passes.push_back({t.pass.filename().string(), t.size, t.gpu_ms});
    }
    const auto now = std::chrono::steady_clock::now();
    presents_.push_back(now);
    while (presents_.size() > 1 && now - presents_.front() > std::chrono::seconds(1)) presents_.erase(presents_.begin());
    const double span = std::chrono::duration<double>(now - presents_.front()).count();
    f.fps = span > 0 ? (presents_.size() - 1) / span : 0.0;
    f.resolution = {width, height};
    f.time = inputs_.time;
    f.frame = inputs_.frame;
    f.paused = clock_.paused();
    f.animated = use_.time;
  }

  // A red frame around the kept picture: the shader on screen is stale.
  void draw_stale_badge(int width, int height) const {
    const int b = std::max(3, std::min(width, height) / 100);
    glEnable(GL_SCISSOR_TEST);
    glClearColor(0.85f, 0.1f, 0.1f, 1.0f);
    const int rects[4][4] = {{0, 0, width, b}, {0, height - b, width, b}, {0, 0, b, height}, {width - b, 0, b, height}};
    for (const auto& r : rects) {
      glScissor(r[0], r[1], r[2], r[3]);
      glClear(GL_COLOR_BUFFER_BIT);
    }
    glDisable(GL_SCISSOR_TEST);
  }

  void update_title(bool force) {
    const auto now = std::chrono::steady_clock::now();
    if (!force && now - title_updated_ < std::chrono::milliseconds(250)) return;
    title_updated_ = now;
    std::string title = options_.scene.filename().string() + " \xE2\x80\x94 ";
    if (errors_ > 0) {
      title += std::to_string(errors_) + (errors_ == 1 ? " error" : " errors");
      title += project_.ready() ? ", showing last good" : ", nothing to show yet";
    } else if (!project_.ready()) {  // the first program, on the builder
      title += "compiling";
    } else if (drawing_ && (drawing_->tiles > 0 || drawing_->buffer_plan)) {  // a picture in tiles, still coming
      title += "drawing in tiles";
    } else {
      // The last picture's own time, through glFinish: not an average, so it
      // does not drift while nothing is drawn.
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.1f ms", frame_ms_);
      title += buf;
      if (model_.figures.scale < 1.0) {
        std::snprintf(buf, sizeof buf, " at scale %.2f", model_.figures.scale);
        title += buf;
      }
      if (model_.figures.tiles > 1) title += " in " + std::to_string(model_.figures.tiles) + " tiles";
    }
    if (samples_ > 1) title += ", " + std::to_string(samples_) + "/" + std::to_string(options_.refine) + " samples";
    if (view_ != View::Picture) title += std::string(" (view: ") + to_string(view_) + ")";
    if (clock_.paused()) title += " (paused)";
    if (take_.recording()) title += " (recording a take: " + std::to_string(take_.frames()) + " frames)";
    if (project_.ready() && !use_.time) title += " (static: drawn on change)";
    glfwSetWindowTitle(window_, title.c_str());
  }

  // F12. A picture too large for the memory there is is one line, and the
  // window goes on.
  void screenshot() {
    try {
      start_screenshot();
    } catch (const std::bad_alloc&) {
      std::cerr << "raymarching: error: no screenshot: not enough memory for its picture\n";
    }
  }
  void start_screenshot() {
    if (!project_.ready()) {
      std::cerr << "raymarching: error: no picture to take: the scene has not compiled yet\n";
      return;
    }
    if (too_slow_) {
      std::cerr << "raymarching: error: no picture to take: the scene is too slow to draw (--tile-limit)\n";
      return;
    }
    int scale = std::max(1, options_.shot_scale);
    if (scale > 1 && project_.has_feedback()) {
      std::cerr << "raymarching: warning: --shot-scale " << scale
                << " does not apply to a project whose buffers feed its next frame (they hold pictures of the "
                   "window's size): the shot is at the window's size\n";
      scale = 1;
    }
    const glm::ivec2 size = glm::ivec2(glm::vec2(inputs_.resolution)) * scale;
    const std::string pixels = std::to_string(size.x) + "x" + std::to_string(size.y);
    if (std::max(size.x, size.y) > kMaxPictureSide) {
      std::cerr << "raymarching: error: no screenshot: " << pixels << " pixels (the window's at --shot-scale " << scale
                << ") is over " << kMaxPictureSide << " a side; a smaller --shot-scale or window takes one\n";
      return;
    }
    if (std::max(size.x, size.y) > renderer_.max_tile() && !project_.image_source().movable_frag_coord) {
      std::cerr << "raymarching: error: --shot-scale " << scale << " exceeds " << renderer_.max_tile()
                << " pixels, and a shader that redeclares gl_FragCoord cannot be drawn in tiles\n";
      return;
    }
    // Buffers the size of the picture were drawn for the last one, which the
    // budget may have scaled: a shot of another size draws them anew. (Not a
    // feedback project's, which the budget never scales.)
    const bool own_buffers = !project_.has_feedback() && !graph_.buffers_sized_for(project_, size);
    if (own_buffers && std::max(size.x, size.y) > renderer_.max_tile()) {
      std::cerr << "raymarching: error: no screenshot: " << pixels << " pixels (the window's at --shot-scale " << scale
                << "): its buffer passes are drawn again for it, whole, at most " << renderer_.max_tile()
                << " pixels a side; a smaller --shot-scale or window takes one\n";
      return;
    }
    FrameInputs in = inputs_;
    in.resolution = glm::vec3(size, 1.0f);
    in.mouse *= static_cast<float>(scale);
    in.cursor *= static_cast<float>(scale);
    // A refined picture at rest is the one to keep: it is what `render
    // --samples` with the samples it has gathered draws.
    const bool refined = samples_ > 1 && !drawing_ && picture_.size() == size;
    const std::string name = options_.scene.stem().string() + "-" + file_timestamp() + "." + options_.shot_format;
    // Which frame of the take being recorded this is: `render --take` draws it again.
    Metadata taken;
    if (take_.recording()) taken.emplace_back(kTakeFrame, std::to_string(take_.current_frame()));
    Metadata metadata = shot_metadata(in, refined ? samples_ : 1, taken);
    if (refined) {
      save_shot(picture_.read(), options_.shot_dir / name, metadata);
    } else {
      // Drawn in tiles between the window's own (continue_shot), from the
      // cost per pixel the window measured.
      shots_wait_for_build_ = waiting_for_build();
      shots_.emplace_back(in, size, renderer_.max_tile(), slice_ms(),
                          measured_per_pixel_ms(glm::ivec2(inputs_.resolution)), options_.shot_dir / name,
                          std::move(metadata), own_buffers);
    }
  }

  // Tiles of the oldest screenshot in progress for a slice of the budget;
  // once it is whole, it is written.
  void continue_shot() {
    TiledShot& shot = shots_.front();
    try {
      if (!shot.draw(graph_, project_, budget_.budget_ms(), [this] { finish_tile(); })) return;
    } catch (const std::bad_alloc&) {
      const glm::ivec2 size(shot.inputs().resolution);
      std::cerr << "raymarching: error: no screenshot: not enough memory for " << size.x << "x" << size.y
                << " pixels (" << shot.path().string() << ")\n";
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      shots_.pop_front();
      return;
    }
    if (options_.verbose) std::cerr << "raymarching: screenshot drawn in " << shot.tiles() << " tiles\n";
    save_shot(shot.read(), shot.path(), shot.metadata());
    shots_.pop_front();
  }

  // What a shot records: the program shown now, and the take's frame from
  // `taken` (kept when a new program restarts the shot).
  Metadata shot_metadata(const FrameInputs& in, int samples, const Metadata& taken) const {
    Metadata metadata = frame_metadata(options_.scene, shown_source_, in, samples);
    for (const auto& entry : taken)
      if (entry.first == kTakeFrame) metadata.push_back(entry);
    return metadata;
  }
  static constexpr char kTakeFrame[] = "raymarching:take_frame";

  void save_shot(Image image, const fs::path& path, const Metadata& metadata) {
    if (options_.verbose) std::cerr << "raymarching: screenshot handed to the writer at " << steady_ns() << '\n';
    shot_writer_.write(std::move(image), path, metadata);
  }

  // F9: a take starts recording the inputs of every frame from the next one
  // on; F9 again writes it beside the scene. A project whose frames feed the
  // next starts over (as R does), so that its replay, which starts from
  // empty buffers, shows the same frames.
  void toggle_take() {
    if (take_.recording()) {
      finish_take();
      return;
    }
    if (!project_.ready()) {
      std::cerr << "raymarching: error: take: nothing to record: the scene has not compiled yet\n";
      return;
    }
    if (project_.has_feedback()) restart();
    take_.start(options_.scene, options_.media, options_.channels, shown_source_, project_);
    dirty_ = true;  // the next frame is the take's first, even in a static scene
    std::cout << "take: recording" << std::endl;
    update_title(true);
  }

  void finish_take() {
    write_take();
    update_title(true);
  }
  void write_take() {
    const int frames = take_.frames();
    std::string error;
    if (auto written = take_.stop(&error))
      std::cout << "take: " << written->string() << " (" << frames << " frames)" << std::endl;
    else
      std::cerr << "raymarching: error: take: " << error << '\n';
  }

  // The X server is gone: what is being written is written, with no call to
  // the display (display_lost.h).
  void write_what_is_left() {
    if (take_.recording()) write_take();
    shot_writer_.finish();
  }

  // V: picture, steps, normals, depth, nan, picture; views this scene cannot
  // show are skipped. Each view is its own program, cached by the scene.
  void cycle_view() {
    View next = next_view(view_);
    while (next != View::Picture && view_problem(project_.image_source(), next)) next = next_view(next);
    view_ = next;
    load();
    if (options_.verbose) std::cerr << "raymarching: view " << to_string(view_) << '\n';
  }

  void toggle_fullscreen() {
    if (glfwGetWindowMonitor(window_)) {
      glfwSetWindowMonitor(window_, nullptr, windowed_[0], windowed_[1], windowed_[2], windowed_[3], 0);
      return;
    }
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    if (!monitor) return;
    glfwGetWindowPos(window_, &windowed_[0], &windowed_[1]);
    glfwGetWindowSize(window_, &windowed_[2], &windowed_[3]);
    const GLFWvidmode* mode = glfwGetVideoMode(monitor);
    glfwSetWindowMonitor(window_, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
  }

  // Draw the scene this iteration? Always while the shader reads a running clock;
  // otherwise only after something it reads changed (or a screenshot is due).
  // Never while minimised: nobody sees it.
  bool redraw_needed() const {
    return !iconified_ && !too_slow_ && (dirty_ || ((rest_due_ || (use_.time && !clock_.paused())) && animation_due()));
  }
  // While a reload builds, the running clock draws a picture every
  // kBuildFrameInterval, not as fast as the budget allows: on a CPU renderer
  // the compiler then has most of the cores, and the new program shows
  // sooner (a fresh edit of room about 40 ms). The picture keeps moving, and
  // input still draws at once.
  static constexpr long long kBuildFrameIntervalNs = 100'000'000;
  bool animation_due() const {
    return !waiting_for_build() || steady_ns() - last_moving_start_ >= kBuildFrameIntervalNs;
  }
  // A picture at rest waits, in tiles or samples, while a reload is built:
  // the build gets the cores, and the new program may replace it anyway. A
  // moving picture keeps moving.
  bool holds_for_build() const { return waiting_for_build() && drawing_ && drawing_->resting; }
  // A shot waits for the build of a save under way when it was asked for, so
  // that it shows the scene as saved, but for no build after that one: in a
  // storm of saves it would wait for the storm's end.
  bool holds_shots() const { return shots_wait_for_build_ && waiting_for_build(); }
  // background_build()'s build (twins, or a tweak's exact program) is under way.
  bool background_building() const { return background_.busy(); }
  // A build of a save is under way (not one in the background).
  bool waiting_for_build() const { return builder_.busy(); }
  bool builders_idle() const { return !builder_.busy() && !background_.busy(); }
  // How long the loop may sleep with nothing to draw. A save wakes it at
  // once through the watcher's descriptor. A polling watcher, a burst of
  // saves still settling, a build under way (whose moving picture is due
  // every kBuildFrameInterval) and a background build coming due need it
  // sooner. The cap bounds what a need not listed here would wait.
  double idle_wait_s() const {
    if (!wake_on_save_.active() || watcher_->settling() || !builders_idle()) return 0.02;
    constexpr double kCap = 0.25;
    if (!wants_background_build()) return kCap;
    return std::clamp(double(last_swap_ns_ + kBackgroundDelayNs - steady_ns()) / 1e9, 0.001, kCap);
  }
  // A background build starts this long after the last swap: saves come in
  // bursts, and one that comes while it runs puts it off at its next stage.
  static constexpr long long kBackgroundDelayNs = 1'000'000'000;
  // The picture in progress has buffer passes still to draw: they hold
  // the frame before's output, or some of them this frame's.
  bool buffers_under_way() const { return drawing_ && drawing_->next_buffer + 1 < project_.passes().size(); }
  // A picture at rest still gathering supersamples (--refine).
  bool refining() const {
    return samples_ > 0 && samples_ < options_.refine && !iconified_ && !too_slow_ && project_.ready();
  }

  const WindowOptions& options_;
  GLFWwindow* window_;
  SourceOptions source_;  // the command line's, with the knobs and preset set in the panel
  // source_ as the latest build began with it, and as the running program
  // was built with it: a screenshot or a take records the program it shows,
  // not a knob whose build failed or has not finished.
  SourceOptions building_source_, shown_source_;
  Project project_;
  std::unique_ptr<Watcher> watcher_;
  WakeOnReadable wake_on_save_;  // after the watcher, whose descriptor it polls: its thread ends first
  StopSignals stop_signals_;
  WakeOnReadable wake_on_signal_;  // after stop_signals_, whose descriptor it polls
  Renderer renderer_;
  FrameGraph graph_;
  // The images the builder read for the graph its build will bind.
  ImagesRead images_read_;
  // After the project, the graph and images_read_, whose textures their
  // warm-ups read and which the first writes: they are destroyed, and their
  // threads joined, before them. builder_ builds the saves, background_
  // background_build()'s builds (opened in run()).
  Builder builder_, background_;
  bool load_again_ = false;  // a reload asked for while a save's build was under way
  bool load_after_tile_ = false;  // one shown without compiling, seen from within a tile
  bool twin_build_ = false;   // background_'s build is of twins
  bool exact_build_ = false;  // ... or of a tweak's exact program
  bool taking_exact_ = false;      // loaded() shows that exact program: the picture stays
  // The background build's results, which its thread writes and this one
  // takes once it has finished.
  std::vector<Scene::TwinResult> twin_results_;
  std::vector<Scene::ExactResult> exact_results_;
  int settle_tried_ = -1;          // the generation whose tweak's exact program was built
  long long last_swap_ns_ = 0, twins_started_ns_ = 0;
  long long last_present_ns_ = 0;  // the last glfwSwapBuffers
  static constexpr long long kPartialPresentIntervalNs = 100'000'000;  // see present_can_wait()
  // The builder draws each new program once, so that llvmpipe generates its
  // code there and the window's first draw finds it in Mesa's shader cache.
  // With the cache off it would be generated twice.
  const bool warm_up_ = !mesa_cache_disabled();
  KeptPicture picture_;
  Ui ui_;
  UiModel model_;
  int ui_frames_ = 0;            // presents still due to the interface
  bool ui_holds_mouse_ = false;  // the left button went down over a panel
  std::set<std::string> touched_uniforms_;  // set in the panel: they keep their values across reloads
  std::vector<std::chrono::steady_clock::time_point> presents_;  // of the last second, for fps
  MouseState mouse_;
  TakeRecorder take_;  // F9
  std::pair<double, double> cursor_;  // window coordinates, from the last cursor event
  ShaderClock clock_;
  FrameInputs inputs_;
  int errors_ = 0;
  int presented_generation_ = 0, drawn_generation_ = 0;  // of the last swap, and of the last tile drawn
  bool shot_requested_ = false;
  std::deque<TiledShot> shots_;  // F12's pictures in progress, drawn in tiles, oldest first
  ShotWriter shot_writer_{options_.verbose};  // ... and those drawn, being written
  bool shots_wait_for_build_ = false;  // see holds_shots()
  bool quit_ = false;
  bool iconified_ = false;
  InputUse use_;       // what the running program reads
  View view_ = View::Picture;
  long frames_drawn_ = 0;
  bool dirty_ = true;  // something it reads changed since the last frame
  double frame_ms_ = 0;  // the last picture's, measured

  // A picture being drawn: its inputs are fixed when it starts, and it is
  // drawn whole or, when it would not fit the budget, tile by tile over
  // several turns of the event loop.
  struct Picture {
    FrameInputs inputs;  // at the picture's size
    glm::ivec2 window;   // the framebuffer it is for
    glm::ivec2 size;     // window * scale
    double scale = 1;
    bool resting = false;  // not moving: a newer picture replaces it
    TilePlan plan;
    double buffers_ms = 0;
    size_t next_buffer = 0;              // the buffer pass to draw next; the image pass's index: none left
    int buffer_tiles = 0;                // drawn so far, of every buffer pass
    std::optional<TilePlan> buffer_plan{};  // of the buffer pass being drawn
    int tiles = 0;  // drawn so far
    double compile_ms = 0;  // a new program's first tile, which the driver compiles it in: not the picture's cost
  };
  ScaleController budget_;
  std::optional<Picture> drawing_;
  bool rest_due_ = false;     // the last picture moved: at rest, draw it at full size
  long long last_moving_start_ = 0;  // when the last moving picture began (steady ns)
  long long last_moving_done_ = 0;  // when the last moving picture was done (steady ns); 0: none just before
  int samples_ = 0;             // supersamples the kept picture holds of the picture at rest; 0: not at rest
  bool program_drawn_ = false;  // the current program has drawn a tile (the driver has compiled it)
  bool too_slow_ = false;       // the watchdog stopped the current program
  std::map<fs::path, double> buffer_cost_;  // each buffer pass's ms per pixel in its last frame
  std::chrono::steady_clock::time_point title_updated_{};
  int windowed_[4] = {0, 0, 800, 450};
};

void WindowApp::on_key(int key, int scancode, int action, int mods) {
  ui_.on_key(key, scancode, action, mods);
  ui_event();
  if (ui_.wants_keyboard()) return;  // typing into a field of the panel
  // A project that reads the keyboard gets every key but F1-F12 and Esc.
  const bool host_key = (key >= GLFW_KEY_F1 && key <= GLFW_KEY_F25) || key == GLFW_KEY_ESCAPE;
  if (project_.reads_keyboard()) {
    const int code = browser_key_code(key);
    if (code >= 0 && (action == GLFW_PRESS || action == GLFW_RELEASE)) {
      const bool down = action == GLFW_PRESS;
      if (down) graph_.keyboard().press(code);
      else graph_.keyboard().release(code);
      take_.key(code, down);
    }
    dirty_ = true;
    if (!host_key) return;
  }
  if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
  const bool press = action == GLFW_PRESS;
  switch (key) {
    case GLFW_KEY_F12: if (press) shot_requested_ = true; break;
    case GLFW_KEY_SPACE: if (press) clock_.set_paused(!clock_.paused()); update_title(true); break;
    case GLFW_KEY_R: if (press) restart(); break;
    case GLFW_KEY_LEFT: step_paused(-1.0 / 60.0); break;
    case GLFW_KEY_RIGHT: step_paused(1.0 / 60.0); break;
    case GLFW_KEY_F9: if (press) toggle_take(); break;
    case GLFW_KEY_F11: if (press) toggle_fullscreen(); break;
    case GLFW_KEY_V: if (press) cycle_view(); break;
    case GLFW_KEY_ESCAPE: case GLFW_KEY_Q: if (press) quit_ = true; break;
    case GLFW_KEY_F1: if (press) std::cout << window_keys_help() << std::flush; break;
    case GLFW_KEY_F2: if (press) ui_.set_visible(!ui_.visible()); ui_frames_ = 1; break;
    case GLFW_KEY_F3:
      if (press) {
        model_.hud = !model_.hud || !ui_.visible();
        ui_.set_visible(true);
        dirty_ = true;  // the figures come from a timed frame
      }
      break;
    default: break;
  }
}

WindowApp* app_of(GLFWwindow* window) { return static_cast<WindowApp*>(glfwGetWindowUserPointer(window)); }

}  // namespace

int run_window(const WindowOptions& options) {
  // The builder reads channel images with stderr shut (libpng's lines):
  // the window's own lines must not be lost meanwhile.
  send_cerr_past_shuts();
  // The worker starts while GLFW opens the window and the driver its context.
  GlslangWarmUp glslang(kHostVersionLine);
  glfwSetErrorCallback(on_glfw_error);
  // The display may go away from here on (GLFW's init is dozens of requests),
  // before the window has anything to write: one line and status 2 too,
  // not Xlib's exit(1).
  on_display_lost({});
  if (!glfwInit()) {
    // X11 says "Failed to open display" where it had no file descriptor left.
    const std::string limit = within_open_file_limit();
    std::cerr << "raymarching: error: cannot open a window ("
              << (glfw_held_error.empty() ? "no display?" : glfw_held_error) << ")"
              << (limit.empty() ? "; `raymarching render` needs none" : limit) << '\n';
    return kExitUsage;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  GLFWwindow* window = [&] {
    const ContextMadeWhileDisplayMayGo guard;
    return glfwCreateWindow(options.size.x, options.size.y, options.scene.filename().c_str(), nullptr, nullptr);
  }();
  if (!window) {
    glfwTerminate();
    std::cerr << "raymarching: error: cannot create an OpenGL 4.5 core window"
              << (glfw_held_error.empty() ? "" : " (" + glfw_held_error + ")") << within_address_space_limit()
              << within_open_file_limit() << '\n';
    return kExitUsage;
  }
  glfw_errors_held = false;
  glfwMakeContextCurrent(window);
  report_gl_errors();
  if (const auto missing = driver_cannot_draw()) {
    std::cerr << "raymarching: error: " << *missing << '\n';
    return kExitUsage;  // not torn down: that would wait for the draw for ever
  }
  glfwSwapInterval(1);  // capped by vsync
  int status = kExitOk;
  {
    WindowOptions for_this = options;
    const std::string gl_renderer = current_renderer();
    for_this.source = for_renderer(options.source, gl_renderer);
    if (options.verbose)
      std::cerr << "raymarching: renderer " << gl_renderer
                << (for_this.source.defines != options.source.defines
                        ? ", on the CPU: -D HW_PERFORMANCE=0 (-D HW_PERFORMANCE=1 draws what a desktop GPU gets)"
                        : "")
                << '\n';
    // The builder's warm-up reaches the window only through Mesa's cache.
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    if (mesa_cache_disabled() && version && std::string(version).find("Mesa") != std::string::npos)
      std::cerr << "raymarching: warning: Mesa's shader cache is off (MESA_SHADER_CACHE_DISABLE): the driver "
                   "generates each new program's code in the window's first draw of it, which holds the window that long\n";
    WindowApp app(for_this, window);
    glfwSetWindowUserPointer(window, &app);
    glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int mods) { app_of(w)->on_mouse_button(button, action, mods); });
    glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) { app_of(w)->on_cursor(x, y); });
    glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int scancode, int action, int mods) { app_of(w)->on_key(key, scancode, action, mods); });
    glfwSetCharCallback(window, [](GLFWwindow* w, unsigned int c) { app_of(w)->on_char(c); });
    glfwSetScrollCallback(window, [](GLFWwindow* w, double x, double y) { app_of(w)->on_scroll(x, y); });
    glfwSetCursorEnterCallback(window, [](GLFWwindow* w, int entered) { app_of(w)->on_cursor_enter(entered != 0); });
    glfwSetWindowFocusCallback(window, [](GLFWwindow* w, int focused) { app_of(w)->on_focus(focused != 0); });
    glfwSetWindowRefreshCallback(window, [](GLFWwindow* w) { app_of(w)->on_refresh(); });
    glfwSetWindowIconifyCallback(window, [](GLFWwindow* w, int iconified) { app_of(w)->on_iconify(iconified); });
    glfwSetFramebufferSizeCallback(window, [](GLFWwindow* w, int width, int height) { app_of(w)->on_resize(width, height); });
    status = app.run();
    if (app.building()) {
      // The window is gone and all it writes is written (a take, the shots'
      // lines), but the builder's context cannot be torn down under the
      // driver's compile: the process ends now instead of waiting for it.
      if (options.verbose) std::cerr << "raymarching: the build under way is abandoned\n";
      std::cout.flush();
      std::cerr.flush();
      std::_Exit(status);
    }
  }
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}

}  // namespace rm
