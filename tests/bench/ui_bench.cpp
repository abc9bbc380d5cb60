// Benchmark behind the "The window's interface" section of
// docs/performance.md: what Dear ImGui and the kept picture cost a frame, in
// a real GLFW window (run under xvfb-run) at 640x360.
//   ui_bench SCENE...   (a project by its image.frag)
// For each scene, alternating in 5 rounds of 10 frames after 3 warm-up
// frames (the lowest round median of each, wall clock through glFinish and
// the swap):
//   - straight into the window, as the window drew before it had an
//     interface (it no longer does: see docs/performance.md);
//   - the kept picture alone: drawn into a texture and copied to the window,
//     how the window draws with the interface hidden (F2);
//   - the interface shown as it opens: the folded panel's title bar;
//   - with the HUD: every pass timed (GL_TIME_ELAPSED and glFinish);
//   - with the HUD and the panel open (time, uniforms, knobs);
//   - the interface alone over the kept picture: what a hover costs a
//     scene that is not drawn again.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/gl.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "core/data_paths.h"
#include "core/frame_graph.h"
#include "core/knobs.h"
#include "core/project.h"
#include "core/renderer.h"
#include "window/kept_picture.h"
#include "window/panels.h"
#include "window/ui.h"
#include "frame_timing.h"

namespace fs = std::filesystem;

namespace {

constexpr int kWidth = 640, kHeight = 360, kWarmUp = 3, kFrames = 10, kRounds = 5;

double median_ms(const std::function<void(int)>& frame) { return bench::median_frame_ms(frame, kWarmUp, kFrames); }

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: ui_bench SCENE...   (needs a display: run under xvfb-run)\n");
    return 2;
  }
  if (!glfwInit()) return 2;
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  GLFWwindow* window = glfwCreateWindow(kWidth, kHeight, "ui_bench", nullptr, nullptr);
  if (!window) return 2;
  glfwMakeContextCurrent(window);
  glfwSwapInterval(0);
  std::fprintf(stderr, "renderer: %s\n", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  {
    rm::SourceOptions options;
    options.shaderlib_dir = rm::shaderlib_dir();
    rm::Renderer renderer;
    rm::KeptPicture picture;
    rm::Ui ui(window);
    const glm::ivec2 size{kWidth, kHeight};
    std::printf("| scene | straight into the window (not done) | hidden (F2): kept picture, copied | shown: folded panel | "
                "+ HUD | + HUD and open panel | the interface alone over the kept picture |\n"
                "|---|---:|---:|---:|---:|---:|---:|\n");
    for (int a = 1; a < argc; ++a) {
      const fs::path path = argv[a];
      rm::Project project(path, options);
      rm::FrameGraph graph(renderer);
      std::string error;
      if (project.reload() != rm::ReloadStatus::Swapped || !graph.update(project, &error)) {
        std::fprintf(stderr, "ui_bench: %s does not build\n", path.c_str());
        return 1;
      }
      rm::FrameInputs in;
      in.resolution = glm::vec3(size, 1.0f);
      rm::UiModel model;
      model.values = &in.uniforms;
      model.uniforms = project.user_uniforms();
      in.uniforms = rm::uniform_values(model.uniforms, {}, &error).value_or(std::vector<rm::UniformValue>{});
      for (const rm::KnobValue& k : rm::knob_values(project.image_source(), &project.image().scene->active_code())) model.knobs.push_back({k, false, 1.0f});

      auto scene = [&](int i, GLuint target) {
        in.time = 1.0f + i / 60.0f;
        in.frame = 60 + i;
        graph.draw(project, in, size, target);
      };
      auto present = [&](bool interface) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, kWidth, kHeight);
        picture.present(size);
        if (interface) {
          ui.begin();
          rm::draw_panels(ui, model);
          ui.end();
        }
        glfwSwapBuffers(window);
        glfwPollEvents();
      };
      auto kept = [&](bool interface, bool hud) {
        return [&, interface, hud](int i) {
          graph.time_passes(hud, true);
          model.hud = hud;
          scene(i, picture.target(size));
          picture.mark_drawn();
          if (hud) graph.pass_times();
          present(interface);
        };
      };
      std::vector<double> best(6, 1e30);
      for (int round = 0; round < kRounds; ++round) {
        best[0] = std::min(best[0], median_ms([&](int i) {
                             graph.time_passes(false);
                             scene(i, 0);
                             glfwSwapBuffers(window);
                             glfwPollEvents();
                           }));
        model.open_controls = false;
        best[1] = std::min(best[1], median_ms(kept(false, false)));
        best[2] = std::min(best[2], median_ms(kept(true, false)));
        best[3] = std::min(best[3], median_ms(kept(true, true)));
        model.open_controls = true;
        best[4] = std::min(best[4], median_ms(kept(true, true)));
        best[5] = std::min(best[5], median_ms([&](int) { present(true); }));  // with the panel open
      }
      // A project is named by its folder (examples/paint/image.frag: paint).
      const fs::path name = path.stem() == "image" ? path.parent_path().filename() : path.stem();
      std::printf("| %s |", name.c_str());
      for (double ms : best) std::printf(" %.2f ms |", ms);
      std::printf("\n");
    }
  }
  glfwDestroyWindow(window);
  glfwTerminate();
  return 0;
}
