// Number tweaks: most live edits change a number. A save that changes only
// float literals of the user's own files is shown at once by a twin program,
// built in the background, that reads those literals from a uniform array
// (rm_Tweak) instead of having them compiled in. The exact program is then
// compiled behind it.
//
// Where a literal may be lifted, by scope:
// - FunctionBodies: where any expression may stand, in a function body
//   outside `const` declarations.
// - WithConstants: also the values of float constants and globals, of
//   #defines, and of -D options (the knobs the window's controls set). The
//   twin makes them plain variables: a local `const float` loses its
//   `const`, and a global float declaration's initialiser moves into
//   main(). A constant that an integer constant, an array size or a
//   global's initialiser needs then makes glslang reject the twin, and
//   the scene falls back to the FunctionBodies twin.
// Never: the bundled shaderlib, ints, doubles, hex, #if lines.
#pragma once
#include <string>
#include <vector>

#include "core/source.h"

namespace rm {

inline constexpr char kTweakUniform[] = "rm_Tweak";
// More literals than this and the scene gets no twin: the array must fit the
// driver's uniform space (GL 4.5 guarantees 1024 fragment components).
inline constexpr size_t kMaxTweaks = 512;

enum class LiftScope { FunctionBodies, WithConstants };

struct LiftedLiterals {
  LiftScope scope = LiftScope::FunctionBodies;
  // The text, comments blanked, with each lifted literal replaced by a mark:
  // two texts whose skeletons have the same code (lexing::code_only) differ
  // only in those literals, comments and blanks.
  std::string skeleton;
  std::vector<float> values;  // the lifted literals, in order
  std::vector<std::string> literals;  // the same, as written
  bool ok = true;             // false: too many, or one not finite
  std::vector<size_t> main_bodies;  // skeleton offsets just inside each main()'s '{'
  // WithConstants only:
  size_t constants = 0;  // values lifted that FunctionBodies leaves (0: the two twins are one)
  std::vector<size_t> dropped_consts;  // skeleton offsets of `const` words the twin leaves out
  struct MovedInitialiser {
    size_t from, to;     // skeleton [from, to): "= value" of a global declarator
    std::string target;  // its name: main() sets it to the value
  };
  std::vector<MovedInitialiser> moved;
};
LiftedLiterals lift_literals(const Source& source, const fs::path& shaderlib_dir,
                             LiftScope scope = LiftScope::FunctionBodies);

// The twin's source: the skeleton with a global rm_Tweak_i for literal i,
// set from rm_Tweak[i] as main() begins (then the moved initialisers, in
// order), and the declarations before the user's first line (a host line,
// so the user's lines keep their numbers).
// llvmpipe loads a uniform again at each use, in every turn of a loop: read
// in place, the array made gallery's frames 2.3 times as slow, the globals
// 1.2 times.
Source twin_source(const Source& source, const LiftedLiterals& lifted);

// `text` from the twin (its preprocessor's output, say) with the name it
// gives literal i written as literals[i]: what the exact program has there.
std::string with_literals(const std::string& text, const std::vector<std::string>& literals);
// Whether `text` is one of the twin's names, alone: a knob whose value it is
// reads a lifted literal.
bool is_lifted_name(const std::string& text);

}  // namespace rm
