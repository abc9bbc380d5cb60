// The signals that ask a program to stop: Ctrl-C's SIGINT, SIGTERM (kill,
// Slurm's scancel and time limit) and SIGHUP (the terminal closed). While a
// StopSignals lives, the first of them does not end the process: it makes
// fd() readable, so that the program ends in its own time and leaves no half
// file (render, headless/run_guard.h) or writes what it holds (the window's
// take). A second one ends the process as if nothing were caught, in case
// the first is not seen. A signal ignored when the program began (nohup's
// SIGHUP, a script's background job's SIGINT) stays ignored, as in any Unix
// tool. One at a time per process; each uses the one pipe of the process,
// which prepare() makes at the program's start.
#pragma once
#include <string>

namespace rm {

class StopSignals {
 public:
  // Makes the pipe now, while file descriptors are to be had: a window that
  // later runs near its ulimit -n still ends in its own time, its take
  // written. main() calls it first; a StopSignals makes it if none has.
  static void prepare();

  StopSignals();
  ~StopSignals();  // signals act as before it
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // Readable once a signal came; -1 if none can be caught (no pipe).
  int fd() const { return pipe_[0]; }
  // The signal that came (SIGINT, ...), read from fd(); 0 if none has.
  int received();
  // Makes fd() readable with no signal, so that a thread waiting on it ends:
  // received() then gives 0.
  void wake();

 private:
  int pipe_[2] = {-1, -1};  // the process's pipe (not this object's), or -1 without one
  int signal_ = 0;
};

// "SIGINT" for SIGINT.
std::string signal_name(int signal);

}  // namespace rm
