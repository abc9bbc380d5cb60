// Scene: one shader file and what it includes, kept as the last program that
// validated, compiled and linked. A failed reload never replaces it.
#pragma once
#include <functional>
#include <optional>
#include <vector>

#include "core/diagnostics.h"
#include "core/knobs.h"
#include "core/program.h"
#include "core/source.h"
#include "core/tweak.h"

namespace rm {

// Where a reload's time went, in ms: for `-v` and the reload benchmark.
struct ReloadTimes {
  double preprocess = 0;  // reading the files, #include, the wrapper
  double validate = 0;    // glslang, in its sandboxed child
  double driver = 0;      // the driver's compile and link
  double warm = 0;        // the on_built hook: the window's warm-up draw
  // The whole build by the wall clock: its stages may overlap (a project's
  // passes are linked side by side) or leave time between them.
  double wall = 0;
  ReloadTimes& operator+=(const ReloadTimes& o) {
    preprocess += o.preprocess, validate += o.validate, driver += o.driver, warm += o.warm, wall += o.wall;
    return *this;
  }
};

// Called with each program a reload compiled anew (not one from the cache),
// the pass file it belongs to, and its source: the window's warm-up.
using OnBuilt = std::function<void(const fs::path& pass, const Program&, const Source&)>;
// Asked between a build's stages: true puts the build off (a background one).
using Cancelled = std::function<bool()>;
// Runs jobs that each touch one pass (its driver's compile and link, its
// warm-up draw) and returns when all are done: on several threads, each
// with a GL context that shares the caller's objects (the window's
// builder), or, where none is given, one after another on this thread.
// llvmpipe compiles one program on one core; two passes on two threads
// take about half as long.
using RunJobs = std::function<void(const std::vector<std::function<void()>>& jobs)>;

enum class ReloadStatus {
  Swapped,       // a new program is running
  Unchanged,     // the combined source is the same as last attempt: nothing done
  Failed,        // errors; the previous program (if any) keeps running
  NeedsCompile,  // prepare_without_compiling(): the save needs glslang and the driver; nothing changed
};

// Preprocesses and validates with glslang: all that `check` does, no GL.
// With `active`, also glslang's preprocessor output there (core/check.h).
Source check_scene(const fs::path& path, const SourceOptions& options, Diagnostics* diags,
                   const FileSystem& files = disk_file_system(), std::string* active = nullptr);

class Scene {
 public:
  // `files` is how it reads the scene and its includes (tests and the
  // accuracy command pass their own).
  Scene(fs::path path, SourceOptions options, FileSystem files = disk_file_system());

  // Re-reads the files; needs a current GL context. A text built before (a
  // view or a preset switched back) comes from the cache without a compile.
  ReloadStatus reload();
  // reload() in two steps, so that a project swaps all its passes or none:
  // prepare() builds the new program and returns Swapped when one is ready
  // to commit(); discard() keeps it cached and the running one running.
  // prepare() touches nothing that drawing the running program reads, so it
  // may run on another thread whose GL context shares this one's objects;
  // The exact build of a tweak (only it: the picture on screen is right)
  // is put off where `cancelled` says so, before each stage, as Unchanged.
  // With Link::Later, a new text that glslang passes is Swapped with the
  // driver's compile and link still to do (link()), so that a project's
  // passes link on several threads at once (not a tweak's exact build,
  // which links at once).
  enum class Link { Now, Later };
  ReloadStatus prepare(const Cancelled& cancelled = {}, Link link = Link::Now);
  // Whether the latest prepare() compiled a program anew, or left one to
  // link(): one for link() and warm_up() (not one from the cache).
  bool built_anew() const { return validated_ || (pending_ && pending_is_new_); }
  // The driver's compile and link of the text prepare() left unlinked;
  // false if the driver rejects it (diagnostics() say why). It touches this
  // scene alone, on any thread whose GL context shares the scene's objects.
  bool link();
  // prepare() for a save that needs no compile: a number edit the twin
  // shows, a text built before (the cache), a comment edit, a broken
  // include, the text of the tweak on screen (Unchanged: its exact program
  // is the background build's). Anything else is NeedsCompile, and the
  // scene is as it was. It reads no GL, so the window calls it while a
  // background build runs.
  ReloadStatus prepare_without_compiling();
  // Hands the program prepare() compiled anew, if it did, to `on_built`
  // (timed as times().warm). Apart from prepare() so that a project warms
  // its passes up in the order it draws them.
  void warm_up(const OnBuilt& on_built);
  void commit();
  void discard();
  // The source of the prepared program if there is one, else the running one's.
  const Source& latest_source() const {
    return pending_tweak_ ? pending_tweak_->source
           : pending_     ? pending_->source
           : validated_   ? validated_->source
                          : good_source_;
  }
  // Its active_code(): the exact program's while a tweak is prepared (the
  // same lines, other numbers).
  const std::string& latest_active() const {
    return pending_tweak_ ? good_active_ : pending_ ? pending_->active : validated_ ? validated_->active : good_active_;
  }
  const Diagnostics& latest_diagnostics() const {
    return pending_ || pending_tweak_ || validated_ ? pending_diagnostics_ : diagnostics_;
  }
  // New -I/-D options (a view, a preset); they apply at the next reload().
  void set_options(SourceOptions options) { options_ = std::move(options); }

  // The running program: the twin while it shows a tweak.
  const Program* program() const { return showing_twin_ ? &twin_->program : program_ ? &*program_ : nullptr; }

  // Number tweaks (core/tweak.h). A save that changes only literals the
  // twin reads is prepared and committed like a build, with no compile: the
  // twin then runs with the new values. While it does, tweaked() is true,
  // and the next prepare() builds the exact program for the same text.
  bool tweaked() const { return showing_twin_; }
  // Whether the running program may have a twin not built yet.
  bool wants_twin() const { return program_ && !showing_twin_ && twin_checked_ != generation_; }
  // Builds the running program's twin (true: one is ready to commit_twin()),
  // under the same terms as prepare(): it may run on the builder's thread.
  // It gives up, to be asked again, where `cancelled` says so: before the
  // driver's compile, and before the warm-up.
  bool prepare_twin(const OnBuilt& on_built = {}, const Cancelled& cancelled = {});
  void commit_twin();

  // A build that nobody waits for (a tweak's exact program, a twin), in
  // three steps, so that the scene can take a save while it runs (the
  // window shows a number edit at once, not after the build's compile): a
  // job, taken on the scene's thread, copies what the build reads; the
  // build runs the job on any thread whose GL context shares the scene's
  // objects, and touches no scene; the scene takes the result back on its
  // own thread, and keeps of it only what still holds once it has moved on
  // (a program for a text no longer shown goes to the cache).
  struct Built {
    std::string text;
    Program program;
    Source source;
    std::string active;  // see active_code()
  };
  struct Twin {
    LiftScope scope;
    std::string code;  // lexing::code_only of its skeleton: the texts it can show (LiftedLiterals)
    Program program;
    std::vector<KnobValue> knobs;  // WithConstants: as its source has them, a lifted value by its name there
  };
  struct ExactJob {  // the exact program of the tweak on screen
    fs::path path;
    Source source;
    int generation = 0;
  };
  struct ExactResult {
    fs::path path;
    int generation = 0;
    bool put_off = false;  // `cancelled` said so, before a stage
    std::optional<Built> built;
    Diagnostics diagnostics;  // its warnings, or why it failed
    ReloadTimes times;
  };
  struct TwinJob {
    fs::path path;
    Source source;  // the running program's
    fs::path shaderlib_dir;
    std::optional<LiftScope> scope;  // the twin there is, and its code
    std::string code;
    std::string failed[2];  // failed_twins_
    int generation = 0;
  };
  struct TwinResult {
    fs::path path;
    int generation = 0;
    bool current = false;  // the twin there is serves the running program
    bool gave_up = false;  // `cancelled` said so: wanted still
    std::optional<Twin> twin;
    std::string failed[2];
    bool rejected_known = false;  // whether `rejected` says anew why the constants compile
    std::optional<Diagnostic> rejected;
  };
  // While tweaked(): the build of the exact program for the text on screen.
  std::optional<ExactJob> exact_job() const;
  static ExactResult build_exact(const ExactJob& job, const OnBuilt& on_built = {}, const Cancelled& cancelled = {});
  // Swapped: the exact program is ready to commit(). Failed: its errors are
  // the diagnostics, and the tweak stays. Unchanged: put off, or for a text
  // no longer shown.
  ReloadStatus take_exact(ExactResult result);
  // When wants_twin(): the build of the running program's twin (marks the
  // twin looked at, as prepare_twin() does).
  std::optional<TwinJob> twin_job();
  static TwinResult build_twin(const TwinJob& job, const OnBuilt& on_built = {}, const Cancelled& cancelled = {});
  // True: a twin is ready to commit_twin().
  bool take_twin(TwinResult result);
  // Why a constant's number compiles, not tweaked: the driver's first error
  // for the twin that makes the constants variables (an int const made from
  // a float const, say). None when that twin was built, or has no constants.
  const std::optional<Diagnostic>& constants_twin_rejected() const { return constants_rejected_; }
  // shaderlib's knobs the running program uses, at its values (a tweak's too).
  std::vector<KnobValue> knobs() const;
  // Whether a new float value in the -D of knob `name` (one the running
  // program has) is a tweak: the twin is the running program's, lifts
  // constants, and reads the knob from a lifted literal. The window's
  // controls then apply the knob while it is dragged.
  bool tweaks_knob(const std::string& name) const;
  const Source& source() const { return good_source_; }  // of the running program
  // glslang's preprocessor output for the running program's text followed by
  // knob_probes(), line for line (from the same child as its validation).
  const std::string& active_code() const { return good_active_; }
  const fs::path& path() const { return path_; }
  // Errors of the latest attempt; empty after a good load.
  const Diagnostics& diagnostics() const { return diagnostics_; }
  // Every file of the latest attempt, including includes not found yet.
  const std::vector<fs::path>& watch_list() const { return watch_; }
  int generation() const { return generation_; }  // counts swaps
  const ReloadTimes& times() const { return times_; }  // of the latest prepare()

 private:
  fs::path path_;
  SourceOptions options_;
  FileSystem files_;
  std::optional<Program> program_;
  Source good_source_;
  std::string good_active_;
  std::string attempted_text_;
  bool attempted_ = false;
  Diagnostics diagnostics_;
  std::vector<fs::path> watch_;
  int generation_ = 0;
  ReloadTimes times_;
  // Programs built before, by final text, oldest first; at most kCacheSize.
  static constexpr size_t kCacheSize = 8;
  std::vector<Built> cache_;
  std::optional<Built> pending_;  // prepared, not yet committed
  struct Validated {  // glslang passed it; link() compiles it
    Source source;
    std::string active;
  };
  std::optional<Validated> validated_;
  bool pending_is_new_ = false;   // compiled by the latest prepare(), not warmed up yet
  std::optional<Twin> twin_, pending_twin_;
  struct Tweak {
    Source source;
    std::vector<float> values;
    std::vector<std::string> literals;  // the values as written
  };
  std::optional<Tweak> pending_tweak_;
  bool showing_twin_ = false;
  std::vector<std::string> shown_literals_;  // the numbers the twin shows while it does, as written
  int twin_checked_ = -1;      // the generation prepare_twin() last looked at
  int twin_current_ = -1;      // the generation twin_ was last found to be the twin of
  std::string failed_twins_[2];  // by LiftScope, the code of the skeleton whose twin was rejected
  std::optional<Diagnostic> constants_rejected_;
  Diagnostics pending_diagnostics_;
  void cache(Built built);
  ReloadStatus prepare(const Cancelled& cancelled, bool compile, Link link);
  // glslang's validation of `source`, then (with `link`) the driver's
  // compile and link, each stage timed in `times`; `put_off` is asked before each.
  struct Compiled {
    std::optional<Program> program;
    Diagnostics diagnostics;  // the errors, or else the warnings
    std::string active;       // see active_code()
    bool put_off = false;
  };
  static Compiled compile(const Source& source, ReloadTimes* times, const std::function<bool()>& put_off,
                          bool link = true);
};

}  // namespace rm
