// Linked into every program when RM_SANITIZE is on, so a sanitized build runs
// the same way from ctest, a shell or a script, without environment variables.
// LeakSanitizer reads the suppressions below: they name the system libraries
// whose one-time allocations (Mesa's driver and LLVM JIT, glslang's
// process-wide tables, X11, fontconfig) live until exit by design. A leak in
// our own code has none of these in its stack and is still reported.

#include <cstdlib>

// Mesa writes its shader disk cache from a thread of its own. When that
// thread is alive at exit, the leak check of GCC 12's LeakSanitizer reads a
// garbage dynamic-TLS range and dies ("Tracer caught signal 11"), failing a
// test that passed. Suites that filled an empty cache (as on every fresh
// machine) lost a test this way in 3 runs of 3, and none with the cache off.
// A sanitized binary does not use the disk cache; MESA_SHADER_CACHE_DISABLE
// set by the user still wins.
__attribute__((constructor)) static void no_mesa_disk_cache() { setenv("MESA_SHADER_CACHE_DISABLE", "true", 0); }

extern "C" {

// Libraries stay loaded until exit: Mesa unloads its driver at eglTerminate,
// and a leak report cannot name (or suppress) code that is no longer mapped.
int dlclose(void*) { return 0; }

const char* __asan_default_options() { return "detect_leaks=1:strict_string_checks=1:check_initialization_order=1"; }

const char* __ubsan_default_options() { return "print_stacktrace=1:halt_on_error=1"; }

const char* __lsan_default_suppressions() {
  return "leak:libgallium\n"
         "leak:swrast_dri\n"
         "leak:libLLVM\n"
         "leak:libEGL_mesa\n"
         "leak:libGLX_mesa\n"
         "leak:libglapi\n"
         "leak:libX11\n"
         "leak:libxcb\n"
         "leak:libfontconfig\n"
         "leak:libdbus\n";
}

}
