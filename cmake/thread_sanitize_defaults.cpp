// Linked into every program when RM_SANITIZE_THREAD is on, so that a
// ThreadSanitizer build runs the same way from ctest, a shell or a script.
// Any report in our code fails the run (exit status 66). The suppressions are
// for system libraries that are not built with ThreadSanitizer: it cannot see
// how Mesa's driver and LLVM synchronise their own threads (fences, queues),
// so every free, lock and wait they make would be reported; and the lock
// orders and mutexes it reports inside X11, xcb, GLX, GLFW and libgcc's frame
// registry (LLVM's JIT) are those libraries' own.

extern "C" {

const char* __tsan_default_options() { return "exitcode=66:second_deadlock_stack=1"; }

const char* __tsan_default_suppressions() {
  return "called_from_lib:swrast_dri.so\n"
         "called_from_lib:libgallium\n"
         "called_from_lib:libLLVM\n"
         "called_from_lib:libglapi.so\n"
         "called_from_lib:libGLX_mesa.so\n"
         "called_from_lib:libEGL_mesa.so\n"
         "deadlock:libX11.so\n"
         "deadlock:libGLX.so\n"
         "mutex:libX11.so\n"
         "mutex:libxcb.so\n"
         "mutex:libglfw.so\n"
         "mutex:libgcc_s.so\n";
}

}
