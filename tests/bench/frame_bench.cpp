// Benchmark behind docs/examples.md: the frame time of each scene given on the
// command line, headless through EGL at 640x360 (each frame: draw, then
// glFinish; wall clock). Three rounds over all scenes, each the median of 10
// frames after 3 warm-up frames; the lowest round median is reported, so a
// burst of other work on the machine does not count against a scene.
//   frame_bench SCENE... > table.md
// Prints one markdown row per scene: | name | ms | min ms | max ms |
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/frame_graph.h"
#include "core/project.h"
#include "core/data_paths.h"
#include "core/renderer.h"
#include "headless/egl_context.h"
#include "frame_timing.h"

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  constexpr int kWidth = 640, kHeight = 360, kWarmUp = 3, kFrames = 10, kRounds = 3;
  std::string error;
  auto context = rm::EglContext::create(&error);
  if (!context) {
    std::fprintf(stderr, "frame_bench: %s\n", error.c_str());
    return 2;
  }
  rm::SourceOptions options;
  options.shaderlib_dir = rm::shaderlib_dir();
  rm::Renderer renderer;
  rm::RenderTarget target(kWidth, kHeight);
  std::fprintf(stderr, "renderer: %s\n", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  struct Timed {
    fs::path path;
    std::unique_ptr<rm::Project> project;
    std::unique_ptr<rm::FrameGraph> graph;
    double best_median = 1e30, min = 1e30, max = 0;
  };
  std::vector<Timed> scenes;
  for (int a = 1; a < argc; ++a) {
    Timed t{argv[a], std::make_unique<rm::Project>(argv[a], options), std::make_unique<rm::FrameGraph>(renderer)};
    if (t.project->reload() != rm::ReloadStatus::Swapped) {
      std::fprintf(stderr, "frame_bench: %s does not build\n", argv[a]);
      return 1;
    }
    if (!t.graph->update(*t.project, &error)) {
      std::fprintf(stderr, "frame_bench: %s\n", error.c_str());
      return 2;
    }
    scenes.push_back(std::move(t));
  }
  for (int round = 0; round < kRounds; ++round) {
    for (Timed& t : scenes) {
      const std::vector<double> ms = bench::frame_times_ms(
          [&](int i) {
            rm::FrameInputs in;
            in.resolution = glm::vec3(kWidth, kHeight, 1.0f);
            in.time = 1.0f + i / 60.0f;
            in.frame = 60 + i;
            in.mouse = glm::vec4(420, 300, 0, 0);
            t.graph->draw(*t.project, in, {kWidth, kHeight}, target.framebuffer());
          },
          kWarmUp, kFrames);
      t.best_median = std::min(t.best_median, ms[ms.size() / 2]);
      t.min = std::min(t.min, ms.front());
      t.max = std::max(t.max, ms.back());
    }
  }
  std::printf("| scene | ms | min ms | max ms |\n|---|---|---|---|\n");
  for (const Timed& t : scenes)
    std::printf("| %s | %.1f | %.1f | %.1f |\n", t.path.stem().c_str(), t.best_median, t.min, t.max);
  return 0;
}
