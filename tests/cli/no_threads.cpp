// Preloaded (LD_PRELOAD) by a test: once main() has begun, every thread
// fails to start, as it does when a process is out of memory for stacks or
// past its limit of threads. Threads that libraries start as they load
// (log4cplus, under OpenImageIO) still start: their failure is theirs.
#include <dlfcn.h>
#include <errno.h>
#include <pthread.h>

namespace {

using Main = int (*)(int, char**, char**);
Main real_main = nullptr;
bool main_begun = false;

int flagged_main(int argc, char** argv, char** env) {
  main_begun = true;
  return real_main(argc, argv, env);
}

}  // namespace

extern "C" int __libc_start_main(Main main, int argc, char** argv, void (*init)(), void (*fini)(),
                                 void (*rtld_fini)(), void* stack_end) {
  using Start = int (*)(Main, int, char**, void (*)(), void (*)(), void (*)(), void*);
  real_main = main;
  const auto start = reinterpret_cast<Start>(dlsym(RTLD_NEXT, "__libc_start_main"));
  return start(flagged_main, argc, argv, init, fini, rtld_fini, stack_end);
}

extern "C" int pthread_create(pthread_t* thread, const pthread_attr_t* attr, void* (*run)(void*), void* arg) {
  if (main_begun) return EAGAIN;
  using Create = int (*)(pthread_t*, const pthread_attr_t*, void* (*)(void*), void*);
  static const auto create = reinterpret_cast<Create>(dlsym(RTLD_NEXT, "pthread_create"));
  return create(thread, attr, run, arg);
}
