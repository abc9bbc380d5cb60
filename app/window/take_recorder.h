// The window's side of a take (core/take.h): F9 starts recording the inputs
// of every frame the window starts, F9 again (or quitting) writes them to a
// take file next to the scene.
#pragma once
#include <array>
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/project.h"
#include "core/take.h"

namespace rm {

class TakeRecorder {
 public:
  bool recording() const { return take_.has_value(); }
  int frames() const { return recording() ? static_cast<int>(take_->frames.size()) : 0; }
  // The recorded frame a screenshot now shows: the latest one.
  int current_frame() const { return frames() - 1; }

  void start(const std::filesystem::path& scene, const std::filesystem::path& media,
             const std::array<std::filesystem::path, 4>& channels, const SourceOptions& source, const Project& project);
  // A frame the window starts, with the inputs it draws with (at the window's size).
  void frame(const FrameInputs& in);
  void key(int code, bool down);  // the keyboard a project reads (core/keyboard.h)
  // A new program from the next frame on (a save, a knob).
  void reloaded(const SourceOptions& source, const Project& project);
  // Writes the take beside the scene as SCENE-TIME.take.json; the path
  // written, or nullopt with *error. Nothing is written for a take of no frames.
  std::optional<std::filesystem::path> stop(std::string* error);

 private:
  std::optional<Take> take_;
  std::chrono::steady_clock::time_point start_;
  std::vector<KeyEvent> keys_;  // since the last frame
};

}  // namespace rm
