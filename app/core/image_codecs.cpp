#include "core/image_codecs.h"

#include <dlfcn.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>

#include "core/address_space.h"
#include "core/data_paths.h"

namespace rm {

namespace {

namespace fs = std::filesystem;

// Installed, the module lives in <prefix>/lib/raymarching, else it is the
// one built beside this program.
fs::path module_path() { return installed_or_built(RM_IMAGE_MODULE_INSTALLED, RM_IMAGE_MODULE_BUILT); }

// Codecs that could not be loaded: every call says why.
class Unavailable final : public ImageCodecs {
 public:
  explicit Unavailable(std::string why) : why_(std::move(why)) {}
  std::optional<DecodedImage> read(const fs::path&, const HeaderCheck&, bool, std::string* error) const override {
    *error = why_;
    return std::nullopt;
  }
  bool can_encode(const fs::path&) const override { return false; }
  std::vector<std::string> encodable_extensions() const override { return {}; }
  bool encode(const fs::path&, const PixelsToEncode&, const Metadata&, std::vector<unsigned char>*,
              std::string* error) const override {
    *error = why_;
    return false;
  }
  Metadata metadata(const fs::path&) const override { return {}; }
  std::optional<std::string> unavailable() const override { return why_; }

 private:
  std::string why_;
};

std::mutex loading;
std::shared_ptr<const ImageCodecs> loaded;  // under `loading`; the module stays for the process's life

// The line the process ends with if a library's initialiser terminates it
// during the load; written before the load, since the handler may not allocate.
std::string terminated_while_loading;

[[noreturn]] void on_terminate_while_loading() {
  const std::string& line = terminated_while_loading;
  [[maybe_unused]] const ssize_t written = write(STDERR_FILENO, line.data(), line.size());
  _exit(2);
}

// Address space the trial load leaves free, so that the real load, whose
// threads start a little sooner or later, passes where the trial did.
constexpr size_t kTrialSpare = 64u << 20;

// Loads the module in a child process, which has this one's address space
// and limit: why it could not be loaded, or nothing when it could. Near an
// address-space limit a library under OpenImageIO that cannot start all its
// threads may end the process (log4cplus calls std::terminate) or wait for
// ever (it waits on a thread pool it started only in part). Only the child
// is lost then. It costs a second load (about 0.5 s), so it is tried only
// under a limit.
std::optional<std::string> trial_load(const fs::path& path) {
  int words[2];
  if (pipe2(words, O_CLOEXEC) != 0) return std::nullopt;  // no trial: the load itself then says
  const pid_t child = fork();
  if (child < 0) {
    close(words[0]);
    close(words[1]);
    return std::nullopt;
  }
  if (child == 0) {
    const int quiet = open("/dev/null", O_WRONLY);
    if (quiet >= 0) dup2(quiet, STDERR_FILENO);  // an abort's own words would make a second line
    if (mmap(nullptr, kTrialSpare, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0) == MAP_FAILED) {
      const char why[] = "no room left for it";
      [[maybe_unused]] const ssize_t written = write(words[1], why, sizeof why - 1);
      _exit(1);
    }
    if (dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL)) _exit(0);
    const char* error = dlerror();
    if (error) {
      [[maybe_unused]] const ssize_t written = write(words[1], error, std::strlen(error));
    }
    _exit(1);
  }
  close(words[1]);
  // A load takes well under a second here, seconds on a loaded machine.
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(15);
  int status = 0;
  pid_t ended = 0;
  while ((ended = waitpid(child, &status, WNOHANG)) == 0 && std::chrono::steady_clock::now() < give_up)
    usleep(5000);
  std::string said;
  if (ended == 0) {
    kill(child, SIGKILL);
    waitpid(child, &status, 0);
    close(words[0]);
    return std::string("a library it needs waited for ever as it loaded (it could not start all its threads)");
  }
  char buffer[512];
  for (ssize_t n; (n = read(words[0], buffer, sizeof buffer)) > 0;) said.append(buffer, static_cast<size_t>(n));
  close(words[0]);
  if (ended < 0 || (WIFEXITED(status) && WEXITSTATUS(status) == 0)) return std::nullopt;
  if (WIFSIGNALED(status))
    return "a library it needs ended the process as it loaded (" + std::string(strsignal(WTERMSIG(status))) +
           "; it could not start a thread)";
  return said.empty() ? std::string("it could not be loaded") : said;
}

// nullptr with *why when the module cannot be loaded now.
const ImageCodecs* load(std::string* why) {
  // Libraries under OpenImageIO (log4cplus) start threads as they load, and
  // call std::terminate if one cannot start. Starting one first turns the
  // usual case, no thread to be had, into a message that the caller reports.
  try {
    std::thread([] {}).join();
  } catch (const std::system_error& e) {
    *why = std::string("a thread could not be started: ") + e.what() + " (out of memory or of threads)";
    return nullptr;
  }
  // Near an address-space limit the probe's thread starts and theirs, once
  // some 240 libraries are mapped, do not. The trial load below finds that
  // out in a child; should this load still meet it, nothing can return from
  // there, so the process ends with one line and status 2, not an abort.
  terminated_while_loading = "raymarching: error: cannot load the image module" + within_address_space_limit() +
                             ": a library it needs could not start a thread (out of memory or of threads)\n";
  const fs::path path = module_path();
  if (address_space_limit_kib())
    if (const auto failed = trial_load(path)) {
      *why = "cannot load the image module" + within_address_space_limit() + ": " + *failed;
      return nullptr;
    }
  const std::terminate_handler previous = std::set_terminate(on_terminate_while_loading);
  void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  std::set_terminate(previous);
  if (!module) {
    const char* error = dlerror();
    *why = "cannot load the image module" + within_address_space_limit() + ": " + (error ? error : path.string());
    return nullptr;
  }
  using Entry = const ImageCodecs* (*)();
  const auto entry = reinterpret_cast<Entry>(dlsym(module, "rm_image_codecs"));
  if (!entry) {
    *why = "cannot load the image module: '" + path.string() + "' has no rm_image_codecs";
    return nullptr;
  }
  return entry();
}

}  // namespace

std::shared_ptr<const ImageCodecs> image_codecs() {
  std::lock_guard<std::mutex> lock(loading);
  if (loaded) return loaded;
  std::string why;
  if (const ImageCodecs* codecs = load(&why)) {
    loaded = std::shared_ptr<const ImageCodecs>(codecs, [](const ImageCodecs*) {});  // the module's own
    return loaded;
  }
  // Not kept: a thread that could not start now may start later.
  return std::make_shared<Unavailable>(why);
}

}  // namespace rm
