// EglContext: an OpenGL 4.5 core context with no window and no display
// server. Tries Mesa's surfaceless platform (llvmpipe on machines with no
// GPU), then EGL devices (NVIDIA headless), then the default display.
#pragma once
#include <memory>
#include <string>

namespace rm {

class EglContext {
 public:
  static std::unique_ptr<EglContext> create(std::string* error);
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

 private:
  EglContext() = default;
  void* display_ = nullptr;
  void* context_ = nullptr;
};

}  // namespace rm
