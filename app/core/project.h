// Project: the pass graph. A project is buffer passes and one image pass,
// each a Scene (its program, kept while a reload fails) with four channel
// bindings. The image pass is the file the person opened; every shader file
// a pass names in a `#pragma channelN "FILE"` is a buffer pass
// (core/channel_spec.h). Buffers draw in the order of their file names
// (buffer_a.frag before buffer_b.frag, as Shadertoy draws Buffer A before
// B), then the image. A single shader is a project of one pass, so the
// window, `render`, `accuracy` and the tests share one path.
//
// No GL objects but programs live here: core/frame_graph.h draws a project.
#pragma once
#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "core/host_inputs.h"
#include "core/scene.h"
#include "core/user_uniforms.h"

namespace rm {

struct Pass {
  fs::path file;
  Scene* scene = nullptr;              // owned by the project
  std::array<ChannelSpec, 4> channels;  // with `self` resolved to a Pass of this file
  bool is_image = false;
  bool cube = false;   // a Cube A pass: drawn into the six faces of a cube map
  int cube_size = 0;   // its face size
  BufferSize size;     // a flat buffer's own size, if a reader gives one; else the picture's
};

// Where a project's passes come from: a shader file is the image pass and
// names the rest; a Shadertoy .json (core/shadertoy_json.h) is served from
// memory as PROJECT.json/image.frag and its neighbours.
struct ProjectFiles {
  fs::path image;
  FileSystem files;
  std::vector<std::string> forced_includes;  // for every pass (a JSON's common.glsl)
};
ProjectFiles project_files(const fs::path& path, const fs::path& media_dir = {});

// The pass-graph rules that need no GL, shared by Project::reload and
// check_project: walks every pass reachable from `image`, the image first,
// calling visit(file) for each; visit returns the pass's source, or a null
// one if the pass failed. The graph's own errors (a pass reading the image, a
// cube pass read flat, too many passes) go to *diags.
struct VisitedPass {
  const Source* source = nullptr;  // null: the pass failed
  std::string_view active;         // its active_code() (core/check.h), if known
};
struct PassWalk {
  std::vector<fs::path> reached;       // image first
  std::map<fs::path, int> cube_size;   // the Cube A passes: the largest size=N a reader gives; 0: none
  std::map<fs::path, BufferSize> buffer_size;  // the flat buffers a reader gives a size of their own
  bool ok = true;                      // every pass built, and the graph holds together
};
// Also warns of channels a pass reads with nothing bound (`image_channels_given`:
// the command line's --channelN files, which bind the image pass's channels).
PassWalk walk_passes(const fs::path& image, const std::function<VisitedPass(const fs::path&)>& visit,
                     Diagnostics* diags, const std::array<bool, 4>& image_channels_given = {});

// `check`: preprocesses and validates every pass with glslang, with no GL.
// Returns the image pass's source (empty if it failed).
Source check_project(const ProjectFiles& from, const SourceOptions& options, Diagnostics* diags);

class Project {
 public:
  static constexpr int kMaxBuffers = 16;

  // `channels` are the command line's --channelN images: they replace what
  // the image pass names for those channels.
  Project(fs::path image, SourceOptions options, FileSystem files = disk_file_system(),
          std::array<fs::path, 4> channels = {});
  Project(const ProjectFiles& from, SourceOptions options, std::array<fs::path, 4> channels = {});

  // Re-reads every pass. Swapped only when every pass of the new graph built:
  // a broken pass keeps the whole last good graph running. A pass whose text
  // did not change is not compiled again.
  ReloadStatus reload();
  // reload() in two steps, for a window that builds on another thread:
  // prepare() reads and builds every pass (Swapped: a new graph is ready to
  // commit()) and changes nothing that drawing the running graph reads, so
  // it may run on a thread whose GL context shares this one's objects, while
  // this one draws. Nothing else may be called on the project meanwhile but
  // the drawing's reads: passes(), image(), the programs and their sources.
  // `cancelled` puts off the exact build of a tweak (Scene::prepare).
  // `run` runs the passes' driver compiles and warm-ups (RunJobs).
  ReloadStatus prepare(const OnBuilt& on_built = {}, const Cancelled& cancelled = {}, const RunJobs& run = {});
  // prepare() where no pass needs a compile (Scene::prepare_without_compiling):
  // else NeedsCompile, and the project is as it was. It reads no GL.
  ReloadStatus prepare_without_compiling();
  void commit();
  // Number tweaks (core/tweak.h), over every pass. tweaked(): a pass shows a
  // tweak with its twin, and the next prepare() builds the exact program.
  bool tweaked() const;
  bool wants_twins() const;  // a running pass may have a twin not built yet
  // Builds the running passes' twins, under prepare()'s terms (true: some
  // are ready to commit_twins()).
  bool prepare_twins(const OnBuilt& on_built = {}, const Cancelled& cancelled = {});
  void commit_twins();
  // The same two builds as jobs that touch no project while they run
  // (Scene's three steps), so that the window can take a save meanwhile.
  // The jobs are in draw order; take_exact() gives Swapped when an exact
  // program is ready to commit(), take_twins() true when twins are ready to
  // commit_twins().
  std::vector<Scene::ExactJob> exact_jobs() const;
  static std::vector<Scene::ExactResult> build_exact(const std::vector<Scene::ExactJob>& jobs,
                                                     const OnBuilt& on_built = {}, const Cancelled& cancelled = {});
  ReloadStatus take_exact(std::vector<Scene::ExactResult> results);
  std::vector<Scene::TwinJob> twin_jobs();
  static std::vector<Scene::TwinResult> build_twins(const std::vector<Scene::TwinJob>& jobs,
                                                    const OnBuilt& on_built = {}, const Cancelled& cancelled = {});
  bool take_twins(std::vector<Scene::TwinResult> results);
  // -I/-D for every pass, and for the image pass alone (a debug view); they
  // apply at the next reload().
  void set_options(SourceOptions all, SourceOptions image_only);

  bool ready() const { return !passes_.empty(); }
  // In draw order: buffers, then the image pass last. Empty before the first good load.
  const std::vector<Pass>& passes() const { return passes_; }
  const Pass& image() const { return passes_.back(); }
  const Program* image_program() const { return ready() ? image().scene->program() : nullptr; }
  const Source& image_source() const;
  const fs::path& path() const { return image_path_; }

  // Errors and warnings of the latest attempt, of every pass.
  const Diagnostics& diagnostics() const { return diagnostics_; }
  std::vector<fs::path> watch_list() const;
  // What pass `file`, of `source`, reads on each channel: its pragmas with
  // `self` resolved, and the image pass's with the --channelN files. Safe on
  // a builder's thread (it reads only what the constructor set).
  std::array<ChannelSpec, 4> channels_of(const fs::path& file, const Source& source) const;
  // The image files the passes read (Image channels): those prepare() made
  // ready to commit, or else the running ones. Safe on the builder's
  // thread after prepare().
  std::vector<ChannelSpec> images_read() const;
  int generation() const { return generation_; }  // counts swaps
  // The passes the latest swap compiled anew (the others kept their programs).
  const std::vector<fs::path>& rebuilt() const { return rebuilt_; }
  const ReloadTimes& times() const { return times_; }  // of the latest reload(), every pass's summed

  // What changes the picture from frame to frame, over all passes: a pass
  // that reads a previous frame (itself or a later buffer) is animated.
  InputUse inputs_read() const;
  // The shader's own uniforms over all passes (core/user_uniforms.h), and
  // their declared defaults: what every front end hands a frame unless told
  // otherwise (render --set).
  UserUniforms user_uniforms() const;
  bool reads_keyboard() const;
  bool has_feedback() const;
  // Whether pass `reader` sees `buffer`'s output of this frame (it drew
  // earlier) or of the previous frame (itself, or later in the order).
  static bool reads_current(const std::vector<Pass>& passes, size_t reader, const fs::path& buffer);

 private:
  Scene& scene_for(const fs::path& file);
  ReloadStatus prepare(const OnBuilt& on_built, const Cancelled& cancelled, const RunJobs& run, bool compile);
  Diagnostics latest_diagnostics() const;  // the file system's warnings, then each pass's
  bool collect(const fs::path& file, std::vector<fs::path>* order, Diagnostics* diags);

  fs::path image_path_;
  std::vector<std::string> forced_includes_;  // added to every pass's options
  SourceOptions options_, image_options_;
  FileSystem files_;
  std::array<fs::path, 4> channel_overrides_;
  std::map<fs::path, std::unique_ptr<Scene>> scenes_;
  std::vector<Pass> passes_;
  std::vector<fs::path> rebuilt_;
  struct PendingSwap {  // what prepare() found, for commit()
    std::vector<fs::path> reached;
    std::map<fs::path, int> cube_size;
    std::map<fs::path, BufferSize> buffer_size;
    std::vector<fs::path> rebuilt;
  };
  std::optional<PendingSwap> pending_;
  PendingSwap shown_;  // the last one committed: the running graph's
  ReloadTimes times_;
  Diagnostics diagnostics_;
  int generation_ = 0;
};

}  // namespace rm
