// The window front end: shows a scene in a GLFW window, reloads it when its
// files change, maps the mouse and keys onto the shader's inputs, and takes
// screenshots.
#pragma once
#include <array>
#include <filesystem>
#include <string>

#include <glm/glm.hpp>

#include "core/source.h"
#include "core/watch.h"

namespace rm {

struct WindowOptions {
  std::filesystem::path scene;
  SourceOptions source;
  glm::ivec2 size{800, 450};          // in screen coordinates
  std::filesystem::path shot_dir = ".";
  std::string shot_format = "png";    // png | exr
  int shot_scale = 1;
  std::array<std::filesystem::path, 4> channels;
  std::filesystem::path media;        // a .json's shadertoy.com media
  WatchBackend watch = WatchBackend::Auto;
  bool verbose = false;               // log reloads and presented frames to stderr
  bool interface = true;              // the interface shown at start (F2 toggles)
  bool hud = false;                   // the HUD shown at start (F3 toggles)
  bool controls = false;              // the controls panel open at start
  double target_fps = 30;             // the frame budget; 0: off (every picture whole, at full size)
  double tile_limit_s = 2;            // a smallest tile slower than this: the shader is too slow
  int refine = 16;                    // supersamples per pixel of a picture at rest; 1: none
};

// Runs until the window closes; returns the process exit status.
int run_window(const WindowOptions& options);

// The list of keys, as F1 and --help print it.
const char* window_keys_help();

}  // namespace rm
