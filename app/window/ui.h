// Dear ImGui inside the window: one context with the GLFW and OpenGL 3
// backends that Debian ships. It draws over the presented picture only, after
// the graph has drawn, so F12 shots and `render` (which read the graph's own
// targets) never contain it.
#pragma once
#include <memory>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "window/fonts.h"

struct GLFWwindow;
struct ImFont;

namespace rm {

class FontLoader;

class Ui {
 public:
  // The window's own GLFW callbacks forward to the on_* functions below, so
  // the order of the two is ours, not the backend's chaining.
  explicit Ui(GLFWwindow* window);
  ~Ui();
  Ui(const Ui&) = delete;
  Ui& operator=(const Ui&) = delete;

  bool visible() const { return visible_; }
  void set_visible(bool visible) { visible_ = visible; }

  // Whether the pointer at `cursor` (window coordinates) is over a panel, as
  // the last frame laid them out: a press there is the UI's, not iMouse.
  bool covers(glm::vec2 cursor) const;
  bool wants_keyboard() const;  // a text field is being edited
  bool dragging() const;        // a widget holds the mouse

  void on_mouse_button(int button, int action, int mods);
  void on_key(int key, int scancode, int action, int mods);
  void on_char(unsigned int codepoint);
  void on_scroll(double x, double y);
  void on_cursor_enter(bool entered);  // the backend reads the pointer only over its window
  void on_focus(bool focused);

  // A text the next frame shows: letters it holds that the fonts lack are
  // looked up and a font atlas with them is built, both on a thread of the
  // fonts' own (FontLoader), which wakes the window's loop when it is ready.
  void want_letters(std::string_view text);
  // Such an atlas is ready: the next begin() takes it, and the interface
  // should be drawn again to show the letters.
  bool fonts_arrived() const;
  // Starts a frame; widgets go between begin() and end(), which draws them
  // over the bound framebuffer. Both do nothing while hidden.
  void begin();
  void end();
  // Called by the panels inside each of their windows: where it lies.
  void note_window_rect();
  // The font rasterised smaller (for warnings) than the 13 px default.
  ImFont* small_font() const;

 private:
  GLFWwindow* window_;
  bool visible_ = true;
  bool in_frame_ = false;
  std::unique_ptr<InterfaceFonts> fonts_;  // outlives the atlases, which read its bytes
  std::unique_ptr<InterfaceFonts::Atlas> atlas_;  // the context's (io.Fonts)
  std::unique_ptr<FontLoader> loader_;
  std::vector<glm::vec4> rects_, next_rects_;  // x, y, width, height of each panel
};

}  // namespace rm
