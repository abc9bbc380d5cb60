#include "window/shared_context.h"

#include <epoxy/gl.h>
#include <epoxy/glx.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <vector>

#include "window/display_lost.h"

namespace rm {

namespace {

// Made current with no drawable, which GLX allows a context of OpenGL 3.0
// or later (GLX_ARB_create_context): a builder draws into framebuffer
// objects only.
class GlxContext final : public SharedContext {
 public:
  GlxContext(Display* display, GLXContext context) : display_(display), context_(context) {}
  ~GlxContext() override { glXDestroyContext(display_, context_); }
  void make_current() const override { glXMakeContextCurrent(display_, None, None, context_); }
  void release() const override { glXMakeContextCurrent(display_, None, None, nullptr); }
  bool direct() const override { return true; }

 private:
  Display* display_;
  GLXContext context_;
};

class HiddenWindow final : public SharedContext {
 public:
  explicit HiddenWindow(GLFWwindow* window) : window_(window) {}
  ~HiddenWindow() override { glfwDestroyWindow(window_); }
  void make_current() const override { glfwMakeContextCurrent(window_); }
  void release() const override { glfwMakeContextCurrent(nullptr); }
  bool direct() const override { return false; }

 private:
  GLFWwindow* window_;
};

// An X error in the calls below (a driver that refuses the attributes)
// would otherwise end the process in Xlib's default handler.
bool x_error_seen = false;
int note_x_error(Display*, XErrorEvent*) {
  x_error_seen = true;
  return 0;
}

// A context of `window`'s own config, version and profile that shares its
// objects, or nullptr where its context is not GLX's or GLX cannot make one.
GLXContext glx_context_like(GLFWwindow* window, Display** display) {
  if (glfwGetWindowAttrib(window, GLFW_CONTEXT_CREATION_API) != GLFW_NATIVE_CONTEXT_API) return nullptr;
  const GLXContext shared = glXGetCurrentContext();
  *display = glXGetCurrentDisplay();
  if (!shared || !*display || !epoxy_has_glx_extension(*display, DefaultScreen(*display), "GLX_ARB_create_context_profile"))
    return nullptr;
  int config_id = 0;
  if (glXQueryContext(*display, shared, GLX_FBCONFIG_ID, &config_id) != Success) return nullptr;
  const int wanted[] = {GLX_FBCONFIG_ID, config_id, None};
  int count = 0;
  GLXFBConfig* configs = glXChooseFBConfig(*display, DefaultScreen(*display), wanted, &count);
  if (!configs) return nullptr;
  const GLXFBConfig config = count > 0 ? configs[0] : nullptr;
  XFree(configs);
  if (!config) return nullptr;

  int flags = 0;
  if (glfwGetWindowAttrib(window, GLFW_OPENGL_FORWARD_COMPAT)) flags |= GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB;
  if (glfwGetWindowAttrib(window, GLFW_OPENGL_DEBUG_CONTEXT)) flags |= GLX_CONTEXT_DEBUG_BIT_ARB;
  std::vector<int> attributes = {GLX_CONTEXT_MAJOR_VERSION_ARB, glfwGetWindowAttrib(window, GLFW_CONTEXT_VERSION_MAJOR),
                                 GLX_CONTEXT_MINOR_VERSION_ARB, glfwGetWindowAttrib(window, GLFW_CONTEXT_VERSION_MINOR),
                                 GLX_CONTEXT_FLAGS_ARB, flags};
  const int profile = glfwGetWindowAttrib(window, GLFW_OPENGL_PROFILE);
  if (profile != GLFW_OPENGL_ANY_PROFILE)
    attributes.insert(attributes.end(),
                      {GLX_CONTEXT_PROFILE_MASK_ARB, profile == GLFW_OPENGL_CORE_PROFILE
                                                         ? GLX_CONTEXT_CORE_PROFILE_BIT_ARB
                                                         : GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB});
  attributes.push_back(None);

  XSync(*display, False);
  x_error_seen = false;
  auto* const previous = XSetErrorHandler(note_x_error);
  GLXContext context = glXCreateContextAttribsARB(*display, config, shared, True, attributes.data());
  XSync(*display, False);
  XSetErrorHandler(previous);
  if (context && x_error_seen) {
    glXDestroyContext(*display, context);
    context = nullptr;
  }
  return context;
}

}  // namespace

std::unique_ptr<SharedContext> SharedContext::make(GLFWwindow* window, const char* name) {
  const ContextMadeWhileDisplayMayGo guard;
  Display* display = nullptr;
  if (GLXContext context = glx_context_like(window, &display)) return std::make_unique<GlxContext>(display, context);
  // A hidden window whose context is made as the window's was (a context of
  // another API or version would not share its objects).
  glfwDefaultWindowHints();
  for (const int hint : {GLFW_CLIENT_API, GLFW_CONTEXT_CREATION_API, GLFW_CONTEXT_VERSION_MAJOR,
                         GLFW_CONTEXT_VERSION_MINOR, GLFW_OPENGL_PROFILE, GLFW_OPENGL_FORWARD_COMPAT,
                         GLFW_OPENGL_DEBUG_CONTEXT})
    glfwWindowHint(hint, glfwGetWindowAttrib(window, hint));
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  GLFWwindow* hidden = glfwCreateWindow(1, 1, name, nullptr, window);
  glfwDefaultWindowHints();
  if (!hidden) return nullptr;
  return std::make_unique<HiddenWindow>(hidden);
}

}  // namespace rm
