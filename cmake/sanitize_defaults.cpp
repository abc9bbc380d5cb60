// Linked into every program when RM_SANITIZE is on, so a sanitized build runs
// the same way from ctest, a shell or a script, without environment variables.
// When leak checking is turned on (see below), LeakSanitizer reads the
// suppressions at the end: they name the system libraries whose one-time
// allocations (Mesa's driver and LLVM JIT, X11, fontconfig) live until exit
// by design. A leak in our own code has none of these in its stack and is
// still reported.

extern "C" {

// Leak checking is off by default: GCC 12's LeakSanitizer tracer reads a
// garbage dynamic-TLS range of Mesa's threads at exit and dies ("Tracer caught
// signal 11"), failing tests that passed, depending only on memory layout (the
// same test failed in one checkout and passed in another). use_tls=0 avoids the
// crash but reports glslang's thread pools as leaks. ASAN_OPTIONS=detect_leaks=1
// turns it on again, with the suppressions below.
const char* __asan_default_options() { return "detect_leaks=0:strict_string_checks=1:check_initialization_order=1"; }

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
