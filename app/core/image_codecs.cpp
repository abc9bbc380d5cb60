#include "core/image_codecs.h"

#include <dlfcn.h>
#include <unistd.h>

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
  std::uint64_t fingerprint(std::string_view) const override { return 0; }
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
  // some 240 libraries are mapped, do not. Nothing can return from there, so
  // the process ends with one line and status 2, not an abort.
  terminated_while_loading = "raymarching: error: cannot load the image module" + within_address_space_limit() +
                             ": a library it needs could not start a thread (out of memory or of threads)\n";
  const fs::path path = module_path();
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
