#include "core/knobs.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "core/check.h"

namespace rm {

const std::vector<Knob>& knob_table() {
  static const std::vector<Knob> table = {
      {"RM_HIT_PIXELS", "hit threshold, in half pixels", false, 0.0f, 16.0f, false},
      {"RM_HIT_EPSILON", "smallest hit threshold", false, 1e-7f, 1e-1f, true},
      {"RM_MAX_STEPS", "most map() calls per ray", true, 8.0f, 2000.0f, true},
      {"RM_MAX_DISTANCE", "farthest distance along a ray", false, 1.0f, 1000.0f, true},
      {"RM_OMEGA", "over-relaxation (1: plain)", false, 1.0f, 2.0f, false},
      {"RM_NORMAL_TAPS", "normal taps: 4 or 6", true, 4.0f, 6.0f, false, 2},
      {"RM_NORMAL_EPSILON", "smallest normal step", false, 1e-7f, 1e-1f, true},
      {"RM_SHADOW_STEPS", "most map() calls per shadow ray", true, 1.0f, 512.0f, true},
      {"RM_SHADOW_SHARPNESS", "soft shadow k: larger is sharper", false, 1.0f, 128.0f, true},
      {"RM_AO_SAMPLES", "ambient occlusion samples", true, 0.0f, 32.0f, false},
      {"RM_REFLECTIONS", "mirror bounces", true, 0.0f, 8.0f, false},
      {"RM_REFRACTION", "refraction segments", true, 0.0f, 16.0f, false},
      {"RM_SAMPLES", "supersampling, N x N rays", true, 1.0f, 8.0f, false},
  };
  return table;
}

float knob_snapped(const Knob& knob, float value) {
  value = std::clamp(value, knob.min, knob.max);
  if (!knob.integer) return value;
  const float step = static_cast<float>(std::max(knob.step, 1));
  const float snapped = knob.min + step * std::round((value - knob.min) / step);
  return snapped > knob.max ? snapped - step : snapped;  // the last step, not max itself, where max is off the steps
}

const std::vector<const char*>& quality_presets() {
  static const std::vector<const char*> presets = {"draft", "interactive", "final", "reference"};
  return presets;
}

std::string preset_macro(const std::string& preset) {
  std::string name = "RM_" + preset;
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::toupper(c); });
  return name;
}

const std::string& knob_probes() {
  static const std::string probes = [] {
    std::string text;
    for (size_t i = 0; i < knob_table().size(); ++i)
      text += "rm_knob_probe_" + std::to_string(i) + " " + knob_table()[i].name + ";\n";
    return text;
  }();
  return probes;
}

std::vector<KnobValue> knob_values(const Source& source, const std::string* given) {
  std::vector<KnobValue> out;
  if (source.text.find("RM_QUALITY_GLSL") == std::string::npos) return out;  // no shaderlib module with knobs
  // An undefined knob comes out of the preprocessor as its own name.
  const auto& table = knob_table();
  const auto active = given && !given->empty() ? std::optional<std::string>(*given)
                                               : active_code(source.text + "\n" + knob_probes(), source.version_line);
  if (!active) return out;
  for (size_t i = 0; i < table.size(); ++i) {
    // "rm_knob_probe_4 160;", or "rm_knob_probe_4(1.0 + 0.25);": glslang
    // writes no space before a parenthesis.
    const std::string marker = "rm_knob_probe_" + std::to_string(i);
    size_t at = active->rfind(marker);
    while (at != std::string::npos && at + marker.size() < active->size() &&
           std::isdigit(static_cast<unsigned char>((*active)[at + marker.size()])))  // probe_14, not probe_1
      at = at == 0 ? std::string::npos : active->rfind(marker, at - 1);
    if (at == std::string::npos) continue;
    const size_t begin = at + marker.size();
    const size_t end = active->find(';', begin);
    if (end == std::string::npos) continue;
    std::string value = active->substr(begin, end - begin);
    while (!value.empty() && value.back() == ' ') value.pop_back();
    while (!value.empty() && value.front() == ' ') value.erase(0, 1);
    if (value == table[i].name) continue;  // not defined: the scene does not use it
    out.push_back({&table[i], value});
  }
  return out;
}

std::vector<Define> preset_knobs(const std::string& preset, const fs::path& shaderlib_dir) {
  // A scene of one line that includes the presets, read from memory (the
  // preprocessor reads the scene by its absolute path).
  const fs::path scene = fs::absolute(shaderlib_dir / "<preset>").lexically_normal();
  FileSystem files = disk_file_system();
  files.read = [scene, disk = files.read](const fs::path& path, Diagnostic* why) -> std::optional<std::string> {
    if (path == scene) return std::string("#include <rm/quality.glsl>\nvoid mainImage(out vec4 c, in vec2 f) {}\n");
    return disk(path, why);
  };
  SourceOptions options;
  options.shaderlib_dir = shaderlib_dir;
  options.defines = {{"RM_QUALITY", preset_macro(preset)}};
  std::vector<Define> out;
  for (const KnobValue& k : knob_values(preprocess(scene, options, files))) out.push_back({k.knob->name, k.value});
  return out;
}

std::vector<Define> with_define(std::vector<Define> defines, const std::string& name, const std::string& value) {
  defines.erase(std::remove_if(defines.begin(), defines.end(), [&](const Define& d) { return d.name == name; }),
                defines.end());
  if (!value.empty()) defines.push_back({name, value});
  return defines;
}

}  // namespace rm
