// Linked into both sanitizer builds (RM_SANITIZE, RM_SANITIZE_THREAD):
// libraries stay loaded until exit. Mesa unloads its driver at eglTerminate;
// a leak report cannot name (or suppress) code that is no longer mapped, and
// ThreadSanitizer ends a program that unloads a library named in a
// called_from_lib suppression ("is unloaded", status 66).
extern "C" int dlclose(void*) { return 0; }
