// Number tweaks: most live edits change a number. A save that changes only
// float literals inside the bodies of the user's own functions is shown at
// once by a twin program, built in the background, that reads those literals
// from a uniform array (rm_Tweak) instead of having them compiled in. The
// exact program is then compiled behind it.
//
// A literal is lifted only where any expression may stand: in a function
// body, outside `const` declarations and preprocessor lines, in a file that
// is not the bundled shaderlib. Globals, array sizes and #define values need
// constants, so an edit there is a code edit and compiles as before.
#pragma once
#include <string>
#include <vector>

#include "core/source.h"

namespace rm {

inline constexpr char kTweakUniform[] = "rm_Tweak";
// More literals than this and the scene gets no twin: the array must fit the
// driver's uniform space (GL 4.5 guarantees 1024 fragment components).
inline constexpr size_t kMaxTweaks = 512;

struct LiftedLiterals {
  // The text, comments removed, with each lifted literal replaced by a mark:
  // two texts with the same skeleton differ only in those literals.
  std::string skeleton;
  std::vector<float> values;  // the lifted literals, in order
  bool ok = true;             // false: too many, or one not finite
  std::vector<size_t> main_bodies;  // skeleton offsets just inside each main()'s '{'
};
LiftedLiterals lift_literals(const Source& source, const fs::path& shaderlib_dir);

// The twin's source: the skeleton with a global rm_Tweak_i for literal i,
// set from rm_Tweak[i] as main() begins, and the declarations before the
// user's first line (a host line, so the user's lines keep their numbers).
// llvmpipe loads a uniform again at each use, in every turn of a loop: read
// in place, the array made gallery's frames 2.3 times as slow, the globals
// 1.2 times.
Source twin_source(const Source& source, const LiftedLiterals& lifted);

}  // namespace rm
