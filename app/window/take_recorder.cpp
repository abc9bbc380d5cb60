#include "window/take_recorder.h"

#include <utility>

#include "core/capture.h"

namespace rm {

void TakeRecorder::start(const std::filesystem::path& scene, const std::filesystem::path& media,
                         const std::array<std::filesystem::path, 4>& channels, const SourceOptions& source,
                         const Project& project) {
  take_.emplace();
  take_->scene = std::filesystem::absolute(scene).lexically_normal();
  take_->media = media;
  for (size_t c = 0; c < 4; ++c)
    if (!channels[c].empty()) take_->channels[c] = std::filesystem::absolute(channels[c]).lexically_normal();
  take_->include_dirs = source.include_dirs;
  take_->undefines = source.undefines;
  take_->events.push_back({0, source.defines, pass_hashes(project)});
  keys_.clear();
}

void TakeRecorder::frame(const FrameInputs& in) {
  if (!take_) return;
  const auto now = std::chrono::steady_clock::now();
  if (take_->frames.empty()) {
    start_ = now;
    take_->date = date_text(date_of(std::chrono::system_clock::now()));
  }
  TakeFrame f;
  f.wall = std::chrono::duration<double>(now - start_).count();
  f.size = glm::ivec2(in.resolution);
  f.time = in.time;
  f.frame = in.frame;
  f.mouse = in.mouse;
  f.cursor = in.cursor;
  f.keys = std::exchange(keys_, {});
  f.uniforms = in.uniforms;
  take_->frames.push_back(std::move(f));
}

void TakeRecorder::key(int code, bool down) {
  if (take_) keys_.push_back({code, down});
}

void TakeRecorder::reloaded(const SourceOptions& source, const Project& project) {
  if (take_) take_->events.push_back({frames(), source.defines, pass_hashes(project)});
}

std::optional<std::filesystem::path> TakeRecorder::stop(std::string* error) {
  std::optional<Take> take = std::exchange(take_, std::nullopt);
  if (!take || take->frames.empty()) {
    *error = "the take has no frames (nothing was drawn while it recorded); no file written";
    return std::nullopt;
  }
  const std::filesystem::path path =
      take->scene.parent_path() / (take->scene.stem().string() + "-" + file_timestamp() + ".take.json");
  return write_take(path, *take, error);
}

}  // namespace rm
