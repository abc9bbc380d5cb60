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

ReloadStatus Scene::prepare(const Cancelled& cancelled) {
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
  // while a tweak shows (its exact program is still to be built).
  if (program_ && !showing_twin_ && count_errors(diagnostics_) == 0 &&
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
  if (put_off()) return ReloadStatus::Unchanged;
  std::string active;
  start = std::chrono::steady_clock::now();
  Diagnostics diags = validate(source, &active, knob_probes());
  times_.validate = ms_since(start);
  if (count_errors(diags) > 0) {
    diagnostics_ = std::move(diags);
    return ReloadStatus::Failed;
  }
  if (put_off()) return ReloadStatus::Unchanged;
  Diagnostics driver;
  start = std::chrono::steady_clock::now();
  std::optional<Program> built = Program::build(source, &driver);
  times_.driver = ms_since(start);
  if (!built) {
    diagnostics_ = std::move(driver);
    return ReloadStatus::Failed;
  }
  if (put_off()) return ReloadStatus::Unchanged;
  std::string text = source.text;
  pending_ = Built{std::move(text), std::move(*built), std::move(source), std::move(active)};
  pending_is_new_ = true;
  pending_diagnostics_ = std::move(diags);  // warnings only
  return ReloadStatus::Swapped;
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
  auto give_up = [&] {
    twin_checked_ = -1;  // wanted still
    return false;
  };
  twin_checked_ = generation_;
  if (!program_ || showing_twin_) return false;
  // The twin that lifts the constants too, unless the driver rejects it (a
  // constant some other constant needs): then the one of the function bodies.
  for (const LiftScope scope : {LiftScope::WithConstants, LiftScope::FunctionBodies}) {
    LiftedLiterals lifted = lift_literals(good_source_, options_.shaderlib_dir, scope);
    const bool constants = scope == LiftScope::WithConstants;
    if (constants && lifted.constants == 0) {  // the same as the other
      constants_rejected_.reset();
      continue;
    }
    // Skeletons compared as code: a twin serves every text of the same tokens.
    std::string code = lexing::code_only(lifted.skeleton);
    std::string& failed = failed_twins_[static_cast<int>(scope)];
    if (!lifted.ok || lifted.values.empty() || code == failed) continue;
    if (twin_ && twin_->scope == scope && twin_->code == code) {
      twin_current_ = generation_;
      return false;
    }
    if (cancelled && cancelled()) return give_up();
    // The exact program built: a twin the driver rejects is only not there.
    Diagnostics rejected;
    const Source twin = twin_source(good_source_, lifted);
    std::optional<Program> built = Program::build(twin, &rejected);
    if (!built) {
      failed = code;
      if (constants) {
        const auto error = std::find_if(rejected.begin(), rejected.end(),
                                        [](const Diagnostic& d) { return d.severity == Severity::Error; });
        constants_rejected_ = error != rejected.end() ? *error : Diagnostic{Severity::Error, "", 0, 0, "rejected"};
      }
      continue;
    }
    if (constants) constants_rejected_.reset();
    if (cancelled && cancelled()) return give_up();
    if (on_built) on_built(path_, *built, twin);
    // A knob's #define or -D may hold a lifted number (a constant): its
    // value is then the tweak's, which the twin's preprocessor gives by name.
    std::vector<KnobValue> knobs;
    if (constants) {
      if (cancelled && cancelled()) return give_up();
      knobs = knob_values(twin);
    }
    pending_twin_ = Twin{scope, std::move(code), std::move(*built), std::move(knobs)};
    return true;
  }
  return false;
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
