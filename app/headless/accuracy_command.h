// `raymarching accuracy SCENE`: what each accuracy knob costs and buys, for a
// scene that renders with shaderlib. It renders a reference at the reference
// preset, then every knob setting on its own, the presets and a textbook
// marcher; for each it measures GPU time (GL_TIME_ELAPSED), map() calls per
// pixel, and the error against the reference. It prints a table and writes
// accuracy.csv, accuracy.svg (error against time, a curve per knob),
// reference.png and steps.png into the output directory.
#pragma once
#include <filesystem>

#include <glm/glm.hpp>

#include "core/source.h"

namespace rm {

struct AccuracyRequest {
  std::filesystem::path scene;
  SourceOptions source;
  glm::ivec2 size{320, 180};
  double time = 1.0;
  std::filesystem::path out;  // default: accuracy-<scene name>
};

int accuracy_command(const AccuracyRequest& request);

}  // namespace rm
