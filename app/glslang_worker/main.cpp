// raymarching-glslang: the process in which the host runs glslang. It reads
// requests on the socket the host gave it as stdin and stdout, and answers
// each, until the host closes the socket (or exits): then at once, even in
// the middle of a shader that would take glslang seconds.
//
// Why a process of its own: each shader is parsed in a child made by fork(),
// so that one which makes glslang loop, allocate without end or crash costs
// an error, not the host. A fork from the host itself copies only the
// forking thread, and a lock another thread held at that moment (the
// sanitizer's allocator while the window draws) stays locked in the child
// for good. This process has one thread, and its forks are safe; it also
// keeps glslang's built-in symbols from one shader to the next.
#include <glslang/Public/ShaderLang.h>
#include <signal.h>

#include "glslang_worker/glslang_work.h"
#include "glslang_worker/protocol.h"

int main() {
  signal(SIGPIPE, SIG_IGN);  // a host that went away ends the loop below
  // Slurm's scancel and its time limit signal every process of a job. The
  // host stops on SIGTERM, SIGINT and SIGHUP and closes the socket, which ends
  // this process and its child; had they died first, the host would report the
  // signal as glslang crashing on the shader. (The child inherits this.)
  for (int stop : {SIGTERM, SIGINT, SIGHUP}) signal(stop, SIG_IGN);
  glslang::InitializeProcess();
  while (const auto request = rm::read_request(0)) {
    const auto reply = rm::serve(*request, 0);
    if (!reply || !rm::write_reply(1, *reply)) break;
  }
  glslang::FinalizeProcess();
  return 0;
}
