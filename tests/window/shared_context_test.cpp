// SharedContext under Xvfb: a context made for a builder's thread shares the
// window's objects, whichever API GLFW made the window's context with; with
// GLX it is made from the window's own config, not as a hidden window.
#include "window/shared_context.h"

#include <gtest/gtest.h>

#include <array>
#include <thread>

#include "core/gl.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace rm {
namespace {

// GLFW holds its display connection for the whole suite: Xvfb resets when
// its last client leaves, and a glfwInit() just after a glfwTerminate()
// once found no display (CI, the sanitized build).
class SharedContextTest : public ::testing::TestWithParam<int> {
 protected:
  static void SetUpTestSuite() { glfw_ = glfwInit(); }
  static void TearDownTestSuite() {
    if (glfw_) glfwTerminate();
  }
  void SetUp() override {
    ASSERT_TRUE(glfw_) << "no display: run under xvfb-run";
    glfwWindowHint(GLFW_CONTEXT_CREATION_API, GetParam());
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    window_ = glfwCreateWindow(64, 64, "shared context test", nullptr, nullptr);
    glfwDefaultWindowHints();
    ASSERT_NE(window_, nullptr);
    glfwMakeContextCurrent(window_);
  }
  void TearDown() override {
    if (window_) glfwDestroyWindow(window_);
  }
  static inline bool glfw_ = false;
  GLFWwindow* window_ = nullptr;
};

TEST_P(SharedContextTest, ItsThreadDrawsIntoTheWindowsTexture) {
  std::unique_ptr<SharedContext> context = SharedContext::make(window_, "builder");
  ASSERT_NE(context, nullptr);
  EXPECT_EQ(context->direct(), GetParam() == GLFW_NATIVE_CONTEXT_API);  // GLX on X11: no hidden window
  GLuint texture = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &texture);
  glTextureStorage2D(texture, 1, GL_RGBA8, 4, 4);
  glFinish();

  GLint major = 0, profile = 0;
  std::thread builder([&] {
    context->make_current();
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    GLuint framebuffer = 0;
    glCreateFramebuffers(1, &framebuffer);
    glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, texture, 0);
    const float red[4] = {1, 0, 0, 1};
    glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, red);
    glDeleteFramebuffers(1, &framebuffer);
    glFinish();
    context->release();
  });
  builder.join();
  EXPECT_EQ(major, 4);  // the window's version and profile
  EXPECT_EQ(profile, GL_CONTEXT_CORE_PROFILE_BIT);

  std::array<unsigned char, 4 * 4 * 4> pixels{};
  glGetTextureImage(texture, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels.size(), pixels.data());
  EXPECT_EQ(pixels[0], 255);
  EXPECT_EQ(pixels[1], 0);
  EXPECT_EQ(pixels[pixels.size() - 1], 255);
  glDeleteTextures(1, &texture);
}

INSTANTIATE_TEST_SUITE_P(Apis, SharedContextTest, ::testing::Values(GLFW_NATIVE_CONTEXT_API, GLFW_EGL_CONTEXT_API),
                         [](const auto& info) { return info.param == GLFW_NATIVE_CONTEXT_API ? "Glx" : "Egl"; });

}  // namespace
}  // namespace rm
