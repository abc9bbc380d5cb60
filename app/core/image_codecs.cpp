#include "core/image_codecs.h"

#include <dlfcn.h>
#include <sys/resource.h>

#include <mutex>
#include <system_error>
#include <thread>

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

// nullptr with *why when the module cannot be loaded now.
const ImageCodecs* load(std::string* why) {
  // Libraries under OpenImageIO (log4cplus) start a thread as they load, and
  // abort the process if it cannot start: the one thing a module cannot
  // report. Starting one first turns that into a message.
  try {
    std::thread([] {}).join();
  } catch (const std::system_error& e) {
    *why = std::string("a thread could not be started: ") + e.what() + " (out of memory or of threads)";
    return nullptr;
  }
  const fs::path path = module_path();
  void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!module) {
    const char* error = dlerror();
    // Under an address-space limit a library cannot be mapped, and the
    // loader's words ("failed to map segment") do not say why.
    struct rlimit space {};
    const bool limited = getrlimit(RLIMIT_AS, &space) == 0 && space.rlim_cur != RLIM_INFINITY;
    *why = "cannot load the image module" +
           (limited ? " within this process's address-space limit (ulimit -v " + std::to_string(space.rlim_cur / 1024) + " KiB)"
                    : std::string()) +
           ": " + std::string(error ? error : path.string());
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
