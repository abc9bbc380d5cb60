// GL census: how many objects of each kind the driver holds for this context,
// asked of the driver itself (glIs*), so an object leaked by any code path is
// counted, not only those our wrappers own. For leak checks and `-v`.
#pragma once
#include <string>

namespace rm {

struct GlCensus {
  int programs = 0, shaders = 0, textures = 0, buffers = 0;
  int framebuffers = 0, renderbuffers = 0, vertex_arrays = 0, queries = 0;
  int total() const;
  bool operator==(const GlCensus&) const = default;
};

// Needs a current GL context. Cost: a few thousand glIs* calls (well under a
// millisecond on llvmpipe), so it is for diagnostics, not for every frame.
GlCensus take_gl_census();

// "programs 2, shaders 0, textures 1, ..." on one line.
std::string to_string(const GlCensus& census);

}  // namespace rm
