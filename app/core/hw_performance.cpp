#include "core/hw_performance.h"

#include <algorithm>
#include <array>

#include "core/gl.h"
#include "core/knobs.h"

namespace rm {

bool is_software_renderer(std::string_view gl_renderer) {
  // Mesa's llvmpipe and softpipe (and zink or a Vulkan layer over
  // lavapipe, which name it), Google's SwiftShader, Windows' fallbacks.
  constexpr std::array<std::string_view, 6> kSoftware = {"llvmpipe", "softpipe", "lavapipe", "SwiftShader",
                                                         "Microsoft Basic Render", "GDI Generic"};
  return std::any_of(kSoftware.begin(), kSoftware.end(),
                     [&](std::string_view name) { return gl_renderer.find(name) != std::string_view::npos; });
}

SourceOptions for_renderer(SourceOptions options, std::string_view gl_renderer) {
  const bool set = std::any_of(options.defines.begin(), options.defines.end(),
                               [](const Define& d) { return d.name == "HW_PERFORMANCE"; });
  if (!set && is_software_renderer(gl_renderer)) options.defines = with_define(options.defines, "HW_PERFORMANCE", "0");
  return options;
}

std::string current_renderer() {
  const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return name ? name : "unknown";
}

}  // namespace rm
