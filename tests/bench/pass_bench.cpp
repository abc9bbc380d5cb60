// Benchmark behind the "Pass graph" section of docs/performance.md, headless
// through EGL at 640x360 (wall clock around draw + glFinish).
//   pass_bench --single SCENE... --projects IMAGE...
// 1. The cost of the graph: each single-pass scene drawn through the frame
//    graph and straight through the renderer (what the host did before it
//    had a graph), alternating in one run, 5 rounds of 10 frames after 3
//    warm-up frames; the lowest round median of each.
// 2. Each project's frame, pass by pass: the wall clock of each pass with
//    glFinish after it, and GL_TIME_ELAPSED (which llvmpipe under-reports),
//    the median of 10 frames after 3.
// Prints two markdown tables.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/data_paths.h"
#include "core/frame_graph.h"
#include "core/project.h"
#include "core/renderer.h"
#include "headless/egl_context.h"
#include "frame_timing.h"

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

constexpr int kWidth = 640, kHeight = 360, kWarmUp = 3, kFrames = 10;

rm::FrameInputs inputs(int i) {
  rm::FrameInputs in;
  in.resolution = glm::vec3(kWidth, kHeight, 1.0f);
  in.time = 1.0f + i / 60.0f;
  in.frame = 60 + i;
  in.mouse = glm::vec4(420, 300, 0, 0);
  return in;
}

template <typename Draw>
double median_ms(Draw draw) {
  return bench::median_frame_ms(draw, kWarmUp, kFrames);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<fs::path> singles, projects;
  std::vector<fs::path>* list = nullptr;
  for (int a = 1; a < argc; ++a) {
    if (!std::strcmp(argv[a], "--single")) list = &singles;
    else if (!std::strcmp(argv[a], "--projects")) list = &projects;
    else if (list) list->push_back(argv[a]);
  }
  if (!list) {
    std::fprintf(stderr, "usage: pass_bench --single SCENE... --projects IMAGE...\n");
    return 2;
  }
  std::string error;
  auto context = rm::EglContext::create(&error);
  if (!context) {
    std::fprintf(stderr, "pass_bench: %s\n", error.c_str());
    return 2;
  }
  std::fprintf(stderr, "renderer: %s\n", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  rm::SourceOptions options;
  options.shaderlib_dir = rm::shaderlib_dir();
  rm::Renderer renderer;
  rm::RenderTarget target(kWidth, kHeight);
  auto load = [&](const fs::path& path, rm::Project* project, rm::FrameGraph* graph) {
    if (project->reload() != rm::ReloadStatus::Swapped || !graph->update(*project, &error)) {
      std::fprintf(stderr, "pass_bench: %s does not build\n", path.c_str());
      std::exit(1);
    }
  };

  std::printf("| scene | through the graph, ms | straight to the renderer, ms | difference |\n|---|---:|---:|---:|\n");
  for (const fs::path& path : singles) {
    rm::Project project(path, options);
    rm::FrameGraph graph(renderer);
    load(path, &project, &graph);
    double graph_ms = 1e30, direct_ms = 1e30;
    for (int round = 0; round < 5; ++round) {
      graph_ms = std::min(graph_ms, median_ms([&](int i) {
                            graph.draw(project, inputs(i), {kWidth, kHeight}, target.framebuffer());
                          }));
      direct_ms = std::min(direct_ms, median_ms([&](int i) {
                             glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer());
                             renderer.draw(*project.image_program(), inputs(i), rm::ChannelInputs{}, {kWidth, kHeight});
                           }));
    }
    std::printf("| %s | %.2f | %.2f | %+.1f%% |\n", path.stem().c_str(), graph_ms, direct_ms,
                100.0 * (graph_ms - direct_ms) / direct_ms);
  }

  std::printf("\n| project | pass | wall ms | GPU query ms |\n|---|---|---:|---:|\n");
  for (const fs::path& path : projects) {
    rm::Project project(path, options);
    rm::FrameGraph graph(renderer);
    load(path, &project, &graph);
    graph.time_passes(true, /*finish*/ true);
    std::map<fs::path, std::vector<double>> wall, gpu;
    std::vector<fs::path> order;
    std::vector<double> frame;
    for (int i = 0; i < kWarmUp + kFrames; ++i) {
      const auto start = Clock::now();
      graph.draw(project, inputs(i), {kWidth, kHeight}, target.framebuffer());
      glFinish();
      const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
      if (i < kWarmUp) continue;
      frame.push_back(ms);
      order.clear();
      for (const auto& t : graph.pass_times()) {
        order.push_back(t.pass);
        wall[t.pass].push_back(t.wall_ms);
        gpu[t.pass].push_back(t.gpu_ms);
      }
    }
    const std::string name = path.parent_path().filename().string();
    for (const fs::path& pass : order)
      std::printf("| %s | %s | %.2f | %.2f |\n", name.c_str(), pass.filename().c_str(), median(wall[pass]),
                  median(gpu[pass]));
    std::printf("| %s | **whole frame** | %.2f | |\n", name.c_str(), median(frame));
  }
  return 0;
}
