// Supersampling: a picture can be drawn more than once, each time with
// gl_FragCoord moved by a sub-pixel offset, and the draws averaged. The
// window refines a picture at rest this way (--refine), and `render
// --samples` draws the same sequence, so that the two give the same still.
#pragma once
#include <functional>

#include <glm/glm.hpp>

#include "core/inputs.h"

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

// Motion blur: a frame's samples spread over the time its shutter is open,
// `shutter` of the frame interval centred on the frame's time, in `steps`
// even steps. Each spatial sample is taken at every step, so a picture of N
// supersamples takes N x steps draws of its image pass.
struct MotionBlur {
  double shutter = 0;  // 0 to 1 of the frame interval; 0: none
  int steps = 1;       // render --motion-samples
  double fps = 60;     // the frame interval is 1 / fps
  // Moves a frame's inputs `seconds` along the time line; empty: iTime
  // alone moves. A take (core/take.h) moves the mouse and uniforms too.
  std::function<void(FrameInputs& in, double seconds)> move;
  int draws(int samples) const { return samples * steps; }
};

// How far sample `index` lies from the frame's time, in seconds: steps at
// the middles of `steps` equal parts of the open shutter, in turn.
double motion_offset(int index, const MotionBlur& motion);

}  // namespace rm
