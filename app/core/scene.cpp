#include "core/scene.h"

#include "core/check.h"

namespace rm {

Source check_scene(const fs::path& path, const SourceOptions& options, Diagnostics* diags) {
  Source source = preprocess(path, options);
  if (!source.ok()) {
    *diags = source.errors;
    return source;
  }
  *diags = validate(source);
  return source;
}

Scene::Scene(fs::path path, SourceOptions options, FileSystem files)
    : path_(std::move(path)), options_(std::move(options)), files_(std::move(files)) {}

ReloadStatus Scene::reload() {
  Diagnostics diags;
  Source source = preprocess(path_, options_, files_);
  watch_ = source.watch;
  if (source.ok() && attempted_ && source.text == attempted_text_) return ReloadStatus::Unchanged;
  attempted_ = source.ok();
  attempted_text_ = source.ok() ? source.text : std::string();
  if (!source.ok()) {
    diagnostics_ = source.errors;
    return ReloadStatus::Failed;
  }
  auto keep_running_program = [this] {
    if (!program_) return;
    cache_.push_back({good_source_.text, std::move(*program_), std::move(good_source_)});
    program_.reset();
    if (cache_.size() > kCacheSize) cache_.erase(cache_.begin());
  };
  for (auto it = cache_.begin(); it != cache_.end(); ++it) {
    if (it->text != source.text) continue;
    Built cached = std::move(*it);
    cache_.erase(it);
    keep_running_program();
    program_ = std::move(cached.program);
    good_source_ = std::move(cached.source);
    diagnostics_.clear();
    ++generation_;
    return ReloadStatus::Swapped;
  }
  diags = validate(source);
  if (count_errors(diags) > 0) {
    diagnostics_ = std::move(diags);
    return ReloadStatus::Failed;
  }
  Diagnostics driver;
  std::optional<Program> built = Program::build(source, &driver);
  if (!built) {
    diagnostics_ = std::move(driver);
    return ReloadStatus::Failed;
  }
  keep_running_program();
  program_ = std::move(built);
  good_source_ = std::move(source);
  diagnostics_ = std::move(diags);  // warnings only
  ++generation_;
  return ReloadStatus::Swapped;
}

}  // namespace rm
