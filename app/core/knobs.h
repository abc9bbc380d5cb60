// shaderlib's accuracy knobs: the RM_* macros that rm/quality.glsl's presets
// set and the modules read (docs/accuracy.md measures each). Which of them a
// scene uses, at what value, and the range a control gives each.
#pragma once
#include <string>
#include <vector>

#include "core/source.h"

namespace rm {

struct Knob {
  const char* name;  // RM_MAX_STEPS
  const char* what;  // what it sets, in a few words
  bool integer;
  float min, max;    // the control's range; -D may go past it
  bool logarithmic;  // thresholds span decades
  int step = 1;      // an integer knob's control: min, min + step, ... (RM_NORMAL_TAPS: 4 or 6)
};

// Every knob, in the order the panel lists them.
const std::vector<Knob>& knob_table();

// The value of `knob`'s control nearest `value`: within its range and, for
// an integer knob, on its steps.
float knob_snapped(const Knob& knob, float value);

// The presets of --quality, as RM_QUALITY's values: "draft" -> "RM_DRAFT".
const std::vector<const char*>& quality_presets();
std::string preset_macro(const std::string& preset);

struct KnobValue {
  const Knob* knob;
  std::string value;  // as the compiler sees it: "160", "1e-4", "( 100.0 * 0.5 )"
};

// Lines that, appended to a scene and run through glslang's preprocessor,
// show each knob's value ("rm_knob_probe_2 RM_MAX_STEPS;" -> "rm_knob_probe_2 160;").
const std::string& knob_probes();

// The knobs `source` uses (those its code defines), with the values its
// preprocessor gives them after the scene's own #defines, the -D and the
// preset. `active` is that preprocessor's output for source.text followed by
// knob_probes() (validate() makes it); without it, the preprocessor is run
// here. Empty for a scene without shaderlib.
std::vector<KnobValue> knob_values(const Source& source, const std::string* active = nullptr);

// The knobs that `preset` ("reference") sets, at its values, as -D's: what
// rm/quality.glsl gives a scene that defines none of them itself. As -D's
// they win over a scene's own #defines (the accuracy command's reference
// must not take a scene's lowered RM_SHADOW_STEPS). Empty without shaderlib.
std::vector<Define> preset_knobs(const std::string& preset, const fs::path& shaderlib_dir);

// `defines` with NAME set to VALUE: an existing -D of NAME is replaced, and
// an empty VALUE removes it.
std::vector<Define> with_define(std::vector<Define> defines, const std::string& name, const std::string& value);

}  // namespace rm
