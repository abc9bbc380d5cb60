#include "window/take_recorder.h"

#include <cstdio>
#include <ctime>
#include <utility>

namespace rm {

namespace {

// iDate as `render --date` reads it: local YYYY-MM-DDTHH:MM:SS.sss.
std::string date_text(std::chrono::system_clock::time_point when) {
  const glm::vec4 d = date_of(when);
  const double seconds = d.w;
  const int whole = static_cast<int>(seconds);
  char out[64];
  std::snprintf(out, sizeof out, "%04d-%02d-%02dT%02d:%02d:%06.3f", static_cast<int>(d.x), static_cast<int>(d.y) + 1,
                static_cast<int>(d.z), whole / 3600, whole / 60 % 60, seconds - whole / 60 * 60);
  return out;
}

// To the millisecond, as the screenshots' names: two takes never share one.
std::string stamp() {
  const auto now = std::chrono::system_clock::now();
  const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
  std::tm local{};
  localtime_r(&seconds, &local);
  char day[32], out[48];
  std::strftime(day, sizeof day, "%Y%m%d-%H%M%S", &local);
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  std::snprintf(out, sizeof out, "%s-%03d", day, static_cast<int>(ms));
  return out;
}

}  // namespace

void TakeRecorder::start(const std::filesystem::path& scene, const std::filesystem::path& media,
                         const SourceOptions& source, const Project& project) {
  take_.emplace();
  take_->scene = std::filesystem::absolute(scene).lexically_normal();
  take_->media = media;
  take_->include_dirs = source.include_dirs;
  take_->events.push_back({0, source.defines, pass_hashes(project)});
  keys_.clear();
}

void TakeRecorder::frame(const FrameInputs& in) {
  if (!take_) return;
  const auto now = std::chrono::steady_clock::now();
  if (take_->frames.empty()) {
    start_ = now;
    take_->date = date_text(std::chrono::system_clock::now());
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
      take->scene.parent_path() / (take->scene.stem().string() + "-" + stamp() + ".take.json");
  return write_take(path, *take, error);
}

}  // namespace rm
