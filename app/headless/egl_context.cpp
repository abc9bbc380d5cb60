#include "headless/egl_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <dlfcn.h>

#include <string>
#include <vector>

#include "core/address_space.h"
#include "core/driver_ready.h"
#include "core/files.h"
#include "core/gl_debug.h"

namespace rm {

namespace {

EGLContext make_context(EGLDisplay display) {
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) return EGL_NO_CONTEXT;
  if (!eglBindAPI(EGL_OPENGL_API)) return EGL_NO_CONTEXT;
  const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  eglChooseConfig(display, config_attribs, &config, 1, &count);
  // The driver is mapped by now; Mesa would crash making the context in the
  // little room a limit may leave (core/address_space.h).
  if (!room_for_driver()) {
    eglTerminate(display);
    return EGL_NO_CONTEXT;
  }
  const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                    EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                    EGL_NONE};
  EGLContext context = eglCreateContext(display, count > 0 ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, context_attribs);
  if (context == EGL_NO_CONTEXT) {
    eglTerminate(display);
    return EGL_NO_CONTEXT;
  }
  // Surfaceless: all rendering goes to framebuffer objects.
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    eglDestroyContext(display, context);
    eglTerminate(display);
    return EGL_NO_CONTEXT;
  }
  return context;
}

std::vector<EGLDisplay> candidate_displays() {
  std::vector<EGLDisplay> out;
  if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless"))
    out.push_back(eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
  if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_device")) {
    EGLDeviceEXT devices[8];
    EGLint count = 0;
    if (eglQueryDevicesEXT(8, devices, &count))
      for (EGLint i = 0; i < count; ++i)
        out.push_back(eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr));
  }
  out.push_back(eglGetDisplay(EGL_DEFAULT_DISPLAY));
  return out;
}

}  // namespace

std::unique_ptr<EglContext> EglContext::create(std::string* error) {
  // libepoxy opens libEGL at the first EGL call and the GL library at the
  // first GL call, and aborts if it cannot (under an address-space limit,
  // once the driver is mapped; with no file descriptor left): opened first
  // here, as epoxy would, that is a message. Epoxy's own opens then find
  // them loaded.
  const auto cannot_load = [&](const std::string& names, const char* package) {
    const std::string why = dlerror();  // dlopen just failed: never null
    const bool missing = why.find("No such file") != std::string::npos && !address_space_limit_kib();
    *error = "cannot load " + names + within_address_space_limit() + ": " + why +
             (missing ? " (is " + std::string(package) + " installed?)" : "");
    return nullptr;
  };
  if (!dlopen("libEGL.so.1", RTLD_LAZY | RTLD_LOCAL)) return cannot_load("libEGL.so.1", "libegl1");
  if (!dlopen("libOpenGL.so.0", RTLD_LAZY | RTLD_LOCAL) && !dlopen("libGL.so.1", RTLD_LAZY | RTLD_LOCAL))
    return cannot_load("libOpenGL.so.0 or libGL.so.1", "libopengl0");
  for (EGLDisplay display : candidate_displays()) {
    if (display == EGL_NO_DISPLAY) continue;
    EGLContext context = make_context(display);
    if (context == EGL_NO_CONTEXT) continue;
    auto out = std::unique_ptr<EglContext>(new EglContext());
    out->display_ = display;
    out->context_ = context;
    report_gl_errors();
    if (const auto missing = driver_cannot_draw()) {
      *error = *missing;
      out.release();  // tearing the context down would wait for that draw for ever; the process ends
      return nullptr;
    }
    return out;
  }
  // Under an address-space limit Mesa cannot map its driver, and says the
  // file is missing: the limit is the likelier cause then.
  if (const auto kib = address_space_limit_kib()) {
    *error = "no EGL display offers an OpenGL 4.5 core context within this process's address-space limit (ulimit -v " +
             std::to_string(*kib) + " KiB; with Mesa's llvmpipe a render needs about 1 GiB)";
    return nullptr;
  }
  // Nor does Mesa say that it found no file descriptor to open its driver with.
  if (const std::string limit = within_open_file_limit(); !limit.empty()) {
    *error = "no EGL display offers an OpenGL 4.5 core context" + limit;
    return nullptr;
  }
  *error = "no EGL display offers an OpenGL 4.5 core context (is Mesa's libegl-mesa0 installed?)";
  return nullptr;
}

EglContext::~EglContext() {
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
  eglTerminate(display_);
}

}  // namespace rm
