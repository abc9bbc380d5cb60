// The window's panels, built with Dear ImGui each frame from a UiModel: the
// error overlay, the HUD, and the controls (time, the shader's own uniforms,
// shaderlib's accuracy knobs). What the person changed comes back as
// UiChanges; the window applies them. The panels know nothing of GLFW, the
// project or the graph.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "core/diagnostics.h"
#include "core/inputs.h"
#include "core/knobs.h"
#include "core/user_uniforms.h"

namespace rm {

class Ui;

struct HudFigures {
  double cpu_ms = 0;  // drawing the frame, on the CPU's clock (with the driver's work on llvmpipe)
  double gpu_ms = 0;  // GL_TIME_ELAPSED over every pass
  double fps = 0;     // frames presented per second, lately
  glm::ivec2 resolution{0};
  float time = 0;
  int frame = 0;
  bool paused = false;
  bool animated = false;  // false: a static picture, drawn only on change
  double scale = 1;       // the frame budget's, per axis
  int tiles = 1;          // the picture was drawn in this many tiles
  int samples = 0;        // supersamples of the picture at rest (--refine); 0: moving
  struct Pass {
    std::string name;
    glm::ivec2 size{0};  // of its target (a cube's face): a buffer may have a size of its own
    double gpu_ms = 0;
  };
  std::vector<Pass> passes;  // in draw order
};

// The HUD's lines of text, as the window shows them.
std::vector<std::string> hud_lines(const HudFigures& figures);

struct KnobControl {
  KnobValue value;        // as the compiler sees it now
  bool overridden = false;  // set from the panel (or -D)
  float edit = 0;         // the slider's value while it is dragged
  bool live = false;      // a change is a tweak, shown at once: applied while dragged, not on release
  bool held = false;      // its slider is being dragged: `edit` is the person's, not the program's
};

struct UiModel {
  Diagnostics errors;    // of the latest save that failed (errors only); empty once a save builds
  Diagnostics warnings;  // that do not block; shown until dismissed
  bool has_picture = false;  // a last good picture to show under the errors
  bool hud = false;
  std::optional<bool> open_controls;  // a request for the panel's next frame; it starts folded
  HudFigures figures;
  UserUniforms uniforms;              // the controls the shader asks for
  std::vector<UniformValue>* values;  // their values, which the controls change
  std::vector<KnobControl> knobs;     // the knobs the scene uses
  std::string preset;                 // "" for the scene's own, or a --quality name
  double time = 0;
  bool paused = false;
  double speed = 1;
};

struct UiChanges {
  bool uniforms = false;  // a value in *model.values changed
  std::optional<std::pair<std::string, std::string>> knob;  // NAME, VALUE; VALUE "" goes back to the scene's
  std::optional<std::string> preset;
  bool toggle_pause = false, restart = false, dismiss_warnings = false;
  int step = 0;  // frames forward (+) or back (-)
  std::optional<double> seek, speed;
};

// Hands the texts of the panels to ui.want_letters(), before ui.begin():
// the paths and messages that may hold letters the fonts lack.
void want_letters(Ui& ui, const UiModel& model);
// Builds every panel of this frame (inside ui.begin() and ui.end()).
UiChanges draw_panels(Ui& ui, UiModel& model);

}  // namespace rm
