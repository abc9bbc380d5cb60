#include "window/ui.h"

#include <optional>

#include "core/gl.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "window/font_loader.h"
#include "window/fonts.h"

namespace rm {

Ui::Ui(GLFWwindow* window) : window_(window) {
  IMGUI_CHECKVERSION();
  fonts_ = std::make_unique<InterfaceFonts>();
  atlas_ = std::make_unique<InterfaceFonts::Atlas>(fonts_->make_atlas());
  ImGui::CreateContext(atlas_->atlas.get());  // ours, so that another can take its place
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini in the person's directory
  loader_ = std::make_unique<FontLoader>(*fonts_, [] { glfwPostEmptyEvent(); });
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window_, false);
  ImGui_ImplOpenGL3_Init("#version 450 core");
}

Ui::~Ui() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  loader_.reset();  // before the fonts it reads
}

ImFont* Ui::small_font() const { return atlas_->small; }

bool Ui::fonts_arrived() const { return visible_ && loader_->ready(); }

bool Ui::covers(glm::vec2 cursor) const {
  if (!visible_) return false;
  if (ImGui::GetIO().WantCaptureMouse) return true;
  for (const glm::vec4& r : rects_)
    if (cursor.x >= r.x && cursor.y >= r.y && cursor.x < r.x + r.z && cursor.y < r.y + r.w) return true;
  return false;
}

bool Ui::wants_keyboard() const { return visible_ && ImGui::GetIO().WantTextInput; }
bool Ui::dragging() const { return visible_ && ImGui::IsAnyItemActive(); }

void Ui::on_mouse_button(int button, int action, int mods) {
  ImGui_ImplGlfw_MouseButtonCallback(window_, button, action, mods);
}
void Ui::on_key(int key, int scancode, int action, int mods) {
  ImGui_ImplGlfw_KeyCallback(window_, key, scancode, action, mods);
}
void Ui::on_char(unsigned int codepoint) { ImGui_ImplGlfw_CharCallback(window_, codepoint); }
void Ui::on_scroll(double x, double y) { ImGui_ImplGlfw_ScrollCallback(window_, x, y); }
void Ui::on_cursor_enter(bool entered) { ImGui_ImplGlfw_CursorEnterCallback(window_, entered ? 1 : 0); }
void Ui::on_focus(bool focused) { ImGui_ImplGlfw_WindowFocusCallback(window_, focused ? 1 : 0); }

void Ui::want_letters(std::string_view text) { loader_->ask(fonts_->unasked(text)); }

void Ui::begin() {
  if (!visible_) return;
  if (std::optional<InterfaceFonts::Atlas> built = loader_->take()) {
    ImGuiIO& io = ImGui::GetIO();
    const bool uploaded = io.Fonts->TexID != ImTextureID{};  // else the backend's first frame uploads it
    if (uploaded) ImGui_ImplOpenGL3_DestroyFontsTexture();
    *atlas_ = std::move(*built);
    io.Fonts = atlas_->atlas.get();
    if (uploaded) ImGui_ImplOpenGL3_CreateFontsTexture();
  }
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  next_rects_.clear();
  in_frame_ = true;
}

void Ui::end() {
  if (!in_frame_) return;
  in_frame_ = false;
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  rects_.swap(next_rects_);
}

void Ui::note_window_rect() {
  const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  next_rects_.emplace_back(pos.x, pos.y, size.x, size.y);
}

}  // namespace rm
