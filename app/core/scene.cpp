#include "core/scene.h"

#include <algorithm>
#include <chrono>

#include "core/check.h"
#include "core/knobs.h"
#include "core/lexing.h"
#include "core/tweak.h"

namespace rm {

Source check_scene(const fs::path& path, const SourceOptions& options, Diagnostics* diags, const FileSystem& files,
                   std::string* active) {
  Source source = preprocess(path, options, files);
  if (!source.ok()) {
    *diags = source.errors;
    return source;
  }
  *diags = validate(source, active);
  return source;
}

Scene::Scene(fs::path path, SourceOptions options, FileSystem files)
    : path_(std::move(path)), options_(std::move(options)), files_(std::move(files)) {}

ReloadStatus Scene::reload() {
  const ReloadStatus status = prepare();
  if (status == ReloadStatus::Swapped) commit();
  return status;
}

void Scene::cache(Built built) {
  cache_.push_back(std::move(built));
  if (cache_.size() > kCacheSize) cache_.erase(cache_.begin());
}

namespace {

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

ReloadStatus Scene::prepare(const Cancelled& cancelled, Link link) { return prepare(cancelled, true, link); }

ReloadStatus Scene::prepare_without_compiling() { return prepare({}, false, Link::Now); }

Scene::Compiled Scene::compile(const Source& source, ReloadTimes* times, const std::function<bool()>& put_off,
                               bool link) {
  Compiled out;
  auto start = std::chrono::steady_clock::now();
  out.diagnostics = validate(source, &out.active, knob_probes());
  times->validate = ms_since(start);
  if (count_errors(out.diagnostics) > 0 || !link) return out;
  if (put_off && put_off()) {
    out.put_off = true;
    return out;
  }
  Diagnostics driver;
  start = std::chrono::steady_clock::now();
  out.program = Program::build(source, &driver);
  times->driver = ms_since(start);
  if (!out.program) out.diagnostics = std::move(driver);
  return out;
}

ReloadStatus Scene::prepare(const Cancelled& cancelled, bool compile_allowed, Link link) {
  auto put_off = [&] {
    if (!showing_twin_ || !cancelled || !cancelled()) return false;
    attempted_ = false;  // the next prepare() builds it
    return true;
  };
  discard();
  times_ = {};
  auto start = std::chrono::steady_clock::now();
  Source source = preprocess(path_, options_, files_);
  times_.preprocess = ms_since(start);
  watch_ = source.watch;
  // The same text as the tweak on screen: now its exact program is built.
  if (source.ok() && attempted_ && source.text == attempted_text_ && !showing_twin_) return ReloadStatus::Unchanged;
  attempted_ = source.ok();
  attempted_text_ = source.ok() ? source.text : std::string();
  if (!source.ok()) {
    diagnostics_ = source.errors;
    return ReloadStatus::Failed;
  }
  // Only comments changed: the program would be the one on screen, so it and
  // its picture stay. Not after a failed save (its errors are on screen), nor
  // while a tweak shows (its exact program is still to be built), nor when a
  // comment changed what a channel reads (glslViewer's buffer sizes).
  if (program_ && !showing_twin_ && count_errors(diagnostics_) == 0 && source.channels == good_source_.channels &&
      lexing::code_only(source.text) == lexing::code_only(good_source_.text))
    return ReloadStatus::Unchanged;
  for (auto it = cache_.begin(); it != cache_.end(); ++it) {
    if (it->text != source.text) continue;
    pending_ = std::move(*it);
    cache_.erase(it);
    pending_diagnostics_.clear();
    return ReloadStatus::Swapped;
  }
  if (twin_ && source.text != good_source_.text) {
    LiftedLiterals lifted = lift_literals(source, options_.shaderlib_dir, twin_->scope);
    // The same tokens: comments and blanks may differ (a comment-only save
    // left the twin's text behind).
    if (lifted.ok && lexing::code_only(lifted.skeleton) == twin_->code) {
      pending_tweak_ = Tweak{std::move(source), std::move(lifted.values), std::move(lifted.literals)};
      pending_diagnostics_.clear();  // not the last attempt's errors
      return ReloadStatus::Swapped;
    }
  }
  if (!compile_allowed) {
    // The text of the tweak on screen: its exact program is the background build's.
    if (showing_twin_ && source.text == good_source_.text) return ReloadStatus::Unchanged;
    attempted_ = false;  // the build that follows compiles it
    return ReloadStatus::NeedsCompile;
  }
  if (put_off()) return ReloadStatus::Unchanged;
  const bool link_now = link == Link::Now || showing_twin_;
  Compiled built = compile(source, &times_, put_off, link_now);
  if (built.put_off) return ReloadStatus::Unchanged;
  if (count_errors(built.diagnostics) > 0 || (link_now && !built.program)) {
    diagnostics_ = std::move(built.diagnostics);
    return ReloadStatus::Failed;
  }
  if (!link_now) {
    validated_ = Validated{std::move(source), std::move(built.active)};
    pending_diagnostics_ = std::move(built.diagnostics);  // warnings only
    return ReloadStatus::Swapped;
  }
  if (put_off()) return ReloadStatus::Unchanged;
  std::string text = source.text;
  pending_ = Built{std::move(text), std::move(*built.program), std::move(source), std::move(built.active)};
  pending_is_new_ = true;
  pending_diagnostics_ = std::move(built.diagnostics);  // warnings only
  return ReloadStatus::Swapped;
}

std::optional<Scene::ExactJob> Scene::exact_job() const {
  if (!showing_twin_) return std::nullopt;
  return ExactJob{path_, good_source_, generation_};
}

Scene::ExactResult Scene::build_exact(const ExactJob& job, const OnBuilt& on_built, const Cancelled& cancelled) {
  const auto begun = std::chrono::steady_clock::now();
  ExactResult out;
  out.path = job.path;
  out.generation = job.generation;
  auto put_off = [&] { return out.put_off = cancelled && cancelled(); };
  if (put_off()) return out;
  Compiled built = compile(job.source, &out.times, put_off);  // put_off() marks `out` put off
  out.diagnostics = std::move(built.diagnostics);
  if (!built.program || put_off()) return out;
  const auto start = std::chrono::steady_clock::now();
  if (on_built) on_built(job.path, *built.program, job.source);
  out.times.warm = ms_since(start);
  out.times.wall = ms_since(begun);
  out.built = Built{job.source.text, std::move(*built.program), job.source, std::move(built.active)};
  return out;
}

ReloadStatus Scene::take_exact(ExactResult result) {
  times_ = result.times;
  if (result.put_off) return ReloadStatus::Unchanged;
  // Shown meanwhile: a tweak, another program, or a save that failed.
  const bool stale = result.generation != generation_ || !showing_twin_ || !attempted_ ||
                     attempted_text_ != good_source_.text;
  if (stale) {
    if (result.built) cache(std::move(*result.built));
    return ReloadStatus::Unchanged;
  }
  if (!result.built) {
    diagnostics_ = std::move(result.diagnostics);
    return ReloadStatus::Failed;
  }
  pending_ = std::move(result.built);
  pending_is_new_ = false;  // warmed up by the build
  pending_diagnostics_ = std::move(result.diagnostics);
  return ReloadStatus::Swapped;
}

bool Scene::link() {
  if (!validated_) return true;
  Validated checked = std::move(*validated_);
  validated_.reset();
  Diagnostics driver;
  const auto start = std::chrono::steady_clock::now();
  std::optional<Program> program = Program::build(checked.source, &driver);
  times_.driver = ms_since(start);
  if (!program) {
    pending_diagnostics_.clear();
    diagnostics_ = std::move(driver);
    return false;
  }
  std::string text = checked.source.text;
  pending_ = Built{std::move(text), std::move(*program), std::move(checked.source), std::move(checked.active)};
  pending_is_new_ = true;
  return true;
}

void Scene::warm_up(const OnBuilt& on_built) {
  if (!pending_ || !pending_is_new_ || !on_built) return;
  pending_is_new_ = false;
  const auto start = std::chrono::steady_clock::now();
  on_built(path_, pending_->program, pending_->source);
  times_.warm = ms_since(start);
}

void Scene::commit() {
  if (pending_tweak_) {
    twin_->program.set_floats(kTweakUniform, pending_tweak_->values);
    shown_literals_ = std::move(pending_tweak_->literals);
    std::string active = good_active_;  // the exact program's: knobs() reads the twin's
    if (program_) cache({good_source_.text, std::move(*program_), std::move(good_source_), std::move(good_active_)});
    program_.reset();
    good_source_ = std::move(pending_tweak_->source);
    good_active_ = std::move(active);
    pending_tweak_.reset();
    diagnostics_ = std::move(pending_diagnostics_);
    pending_diagnostics_.clear();
    showing_twin_ = true;
    ++generation_;
    twin_current_ = generation_;  // it shows the tweak
    return;
  }
  if (!pending_) return;
  if (program_) cache({good_source_.text, std::move(*program_), std::move(good_source_), std::move(good_active_)});
  showing_twin_ = false;
  program_ = std::move(pending_->program);
  good_source_ = std::move(pending_->source);
  good_active_ = std::move(pending_->active);
  pending_.reset();
  diagnostics_ = std::move(pending_diagnostics_);
  pending_diagnostics_.clear();
  ++generation_;
}

void Scene::discard() {
  pending_is_new_ = false;
  if (validated_) {
    validated_.reset();
    attempted_ = false;
  }
  if (pending_tweak_) {
    pending_tweak_.reset();
    attempted_ = false;
  }
  if (!pending_) return;
  cache(std::move(*pending_));
  pending_.reset();
  attempted_ = false;  // the next prepare() builds it again (from the cache)
}

bool Scene::prepare_twin(const OnBuilt& on_built, const Cancelled& cancelled) {
  std::optional<TwinJob> job = twin_job();
  return job && take_twin(build_twin(*job, on_built, cancelled));
}

std::optional<Scene::TwinJob> Scene::twin_job() {
  twin_checked_ = generation_;
  if (!program_ || showing_twin_) return std::nullopt;
  TwinJob job{path_, good_source_, options_.shaderlib_dir, std::nullopt, "", {failed_twins_[0], failed_twins_[1]},
              generation_};
  if (twin_) job.scope = twin_->scope, job.code = twin_->code;
  return job;
}

Scene::TwinResult Scene::build_twin(const TwinJob& job, const OnBuilt& on_built, const Cancelled& cancelled) {
  TwinResult out;
  out.path = job.path;
  out.generation = job.generation;
  out.failed[0] = job.failed[0];
  out.failed[1] = job.failed[1];
  auto give_up = [&] { return out.gave_up = cancelled && cancelled(); };
  auto note_rejected = [&](std::optional<Diagnostic> why) {
    out.rejected_known = true;
    out.rejected = std::move(why);
  };
  // The twin that lifts the constants too, unless glslang or the driver
  // rejects it (a constant some other constant needs): then the one of the
  // function bodies.
  for (const LiftScope scope : {LiftScope::WithConstants, LiftScope::FunctionBodies}) {
    LiftedLiterals lifted = lift_literals(job.source, job.shaderlib_dir, scope);
    const bool constants = scope == LiftScope::WithConstants;
    if (constants && lifted.constants == 0) {  // the same as the other
      note_rejected(std::nullopt);
      continue;
    }
    // Skeletons compared as code: a twin serves every text of the same tokens.
    std::string code = lexing::code_only(lifted.skeleton);
    std::string& failed = out.failed[static_cast<int>(scope)];
    if (!lifted.ok || lifted.values.empty() || code == failed) continue;
    if (job.scope == scope && job.code == code) {
      out.current = true;
      return out;
    }
    if (give_up()) return out;
    // Built as every text is (compile(): glslang, then the driver): a twin
    // that either rejects is only not there. The same glslang request gives
    // the knobs' values.
    const Source twin = twin_source(job.source, lifted);
    ReloadTimes times;  // a twin's are not reported
    Compiled built = compile(twin, &times, give_up);
    if (built.put_off) return out;
    if (!built.program) {
      failed = code;
      const Diagnostics& rejected = built.diagnostics;
      if (constants) {
        const auto error = std::find_if(rejected.begin(), rejected.end(),
                                        [](const Diagnostic& d) { return d.severity == Severity::Error; });
        note_rejected(error != rejected.end() ? *error : Diagnostic{Severity::Error, "", 0, 0, "rejected"});
      }
      continue;
    }
    if (constants) note_rejected(std::nullopt);
    if (give_up()) return out;
    if (on_built) on_built(job.path, *built.program, twin);
    // A knob's #define or -D may hold a lifted number (a constant): its
    // value is then the tweak's, which the twin's preprocessor gives by name.
    std::vector<KnobValue> knobs;
    if (constants) knobs = knob_values(twin, &built.active);
    out.twin = Twin{scope, std::move(code), std::move(*built.program), std::move(knobs)};
    return out;
  }
  return out;
}

bool Scene::take_twin(TwinResult result) {
  failed_twins_[0] = std::move(result.failed[0]);  // what is rejected holds whatever runs now
  failed_twins_[1] = std::move(result.failed[1]);
  // Another program runs meanwhile (or a tweak): wants_twin() asks again.
  if (result.generation != generation_ || !program_ || showing_twin_) return false;
  if (result.rejected_known) constants_rejected_ = std::move(result.rejected);
  if (result.gave_up) {
    twin_checked_ = -1;  // wanted still
    return false;
  }
  if (result.current) twin_current_ = generation_;
  if (!result.twin) return false;
  pending_twin_ = std::move(result.twin);
  return true;
}

std::vector<KnobValue> Scene::knobs() const {
  // The function bodies' twin lifts no knob: its tweaks leave them as they are.
  if (!showing_twin_ || twin_->scope != LiftScope::WithConstants) return knob_values(good_source_, &good_active_);
  std::vector<KnobValue> out = twin_->knobs;
  for (KnobValue& k : out) k.value = with_literals(k.value, shown_literals_);
  return out;
}

void Scene::commit_twin() {
  if (pending_twin_) {
    twin_ = std::move(pending_twin_);
    twin_current_ = generation_;
  }
  pending_twin_.reset();
}

bool Scene::tweaks_knob(const std::string& name) const {
  if (!twin_ || twin_->scope != LiftScope::WithConstants || twin_current_ != generation_) return false;
  return std::any_of(twin_->knobs.begin(), twin_->knobs.end(),
                     [&](const KnobValue& k) { return k.knob->name == name && is_lifted_name(k.value); });
}

}  // namespace rm
