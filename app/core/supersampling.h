// Supersampling: a picture can be drawn more than once, each time with
// gl_FragCoord moved by a sub-pixel offset, and the draws averaged. The
// window refines a picture at rest this way (--refine), and `render
// --samples` draws the same sequence, so that the two give the same still.
#pragma once
#include <glm/glm.hpp>

namespace rm {

// The most samples a picture takes: past this, the running mean in a float
// target gains nothing visible.
constexpr int kMaxSamples = 1024;

// Where sample `index` of each pixel lies, from the pixel's centre, in
// [-0.5, 0.5): sample 0 is the centre (a one-sample picture is the ordinary
// one), then the Halton (2, 3) sequence, which covers the pixel evenly for
// any count (a box filter).
glm::vec2 sample_offset(int index);

// The weight a sample has in the running mean of the samples before it
// and itself: 1 for sample 0 (it replaces what was there), 1/(k+1) for k.
float sample_weight(int index);

}  // namespace rm
