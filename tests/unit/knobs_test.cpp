// shaderlib's accuracy knobs as a scene's preprocessor sees them: those its
// modules define, their values after the scene's #defines, -D and the preset,
// and none for a scene without shaderlib.
#include <gtest/gtest.h>

#include <map>

#include "core/check.h"
#include "core/data_paths.h"
#include "core/knobs.h"
#include "support.h"

namespace rm {
namespace {

std::map<std::string, std::string> knobs_of(const std::string& text, std::vector<Define> defines = {},
                                            bool from_validation = false) {
  test::TempDir dir;
  test::write_file(dir / "s.frag", text + "void mainImage(out vec4 c, in vec2 f) { c = vec4(0); }\n");
  SourceOptions options;
  options.shaderlib_dir = shaderlib_dir();
  options.defines = std::move(defines);
  const Source source = preprocess(dir / "s.frag", options);
  EXPECT_TRUE(source.ok()) << join(source.errors);
  std::map<std::string, std::string> out;
  std::string active;
  if (from_validation) {
    EXPECT_TRUE(validate(source, &active, knob_probes()).empty());
  }
  for (const KnobValue& k : knob_values(source, from_validation ? &active : nullptr)) out[k.knob->name] = k.value;
  return out;
}

TEST(Knobs, ThoseTheModulesDefineAtTheirDefaults) {
  const auto knobs = knobs_of("#include <rm/march.glsl>\n");
  EXPECT_EQ(knobs.at("RM_MAX_STEPS"), "160");
  EXPECT_EQ(knobs.at("RM_HIT_PIXELS"), "1.0");
  EXPECT_EQ(knobs.at("RM_OMEGA"), "1.0");
  EXPECT_EQ(knobs.count("RM_SHADOW_STEPS"), 0u);  // lighting.glsl is not included
}

TEST(Knobs, TheScenesOwnDefinesThenDThenThePreset) {
  EXPECT_EQ(knobs_of("#define RM_MAX_STEPS 90\n#include <rm/march.glsl>\n").at("RM_MAX_STEPS"), "90");
  EXPECT_EQ(knobs_of("#include <rm/march.glsl>\n", {{"RM_MAX_STEPS", "33"}}).at("RM_MAX_STEPS"), "33");
  EXPECT_EQ(knobs_of("#include <rm/march.glsl>\n", {{"RM_QUALITY", preset_macro("draft")}}).at("RM_MAX_STEPS"), "64");
}

// glslang writes no space between a word and a parenthesis: a knob set to
// an expression in parentheses is still one.
TEST(Knobs, AValueInParentheses) {
  const auto knobs = knobs_of("#define RM_OMEGA (1.0 + 0.25)\n#define RM_REFLECTIONS 3\n#include <rm/render.glsl>\n"
                              "float map(vec3 p) { return length(p) - 1.0; }\n"
                              "RmMaterial material(vec3 p, vec3 n) { return rmMaterial(vec3(1.0)); }\n");
  EXPECT_EQ(knobs.at("RM_OMEGA"), "(1.0 + 0.25)");
  EXPECT_EQ(knobs.at("RM_HIT_EPSILON"), "1e-4");  // probe 1, not probe 10, 11 or 12
  EXPECT_EQ(knobs.at("RM_REFLECTIONS"), "3");
}

// The window reads them from its validation's child: one fork per reload.
TEST(Knobs, TheSameFromValidation) {
  const std::string scene = "#define RM_SHADOW_STEPS 12\n#include <rm/render.glsl>\n"
                            "float map(vec3 p) { return length(p) - 1.0; }\n"
                            "RmMaterial material(vec3 p, vec3 n) { return rmMaterial(vec3(1.0)); }\n";
  const auto knobs = knobs_of(scene, {{"RM_OMEGA", "1.3"}}, true);
  EXPECT_EQ(knobs, knobs_of(scene, {{"RM_OMEGA", "1.3"}}));
  EXPECT_EQ(knobs.at("RM_SHADOW_STEPS"), "12");
  EXPECT_EQ(knobs.at("RM_OMEGA"), "1.3");
}

// The accuracy command's yardstick: every knob the reference preset sets, at
// its value, and none it leaves to the modules' defaults (RM_OMEGA).
TEST(Knobs, ThoseAPresetSets) {
  std::map<std::string, std::string> knobs;
  for (const Define& d : preset_knobs("reference", shaderlib_dir())) knobs[d.name] = d.value;
  const std::map<std::string, std::string> expected = {
      {"RM_HIT_PIXELS", "0.05"}, {"RM_HIT_EPSILON", "1e-6"}, {"RM_MAX_STEPS", "2000"}, {"RM_SHADOW_STEPS", "512"},
      {"RM_AO_SAMPLES", "16"},   {"RM_NORMAL_TAPS", "6"},    {"RM_SAMPLES", "4"}};
  EXPECT_EQ(knobs, expected);
  // As -D's they win over a scene's own lowered knob.
  std::vector<Define> defines = preset_knobs("reference", shaderlib_dir());
  EXPECT_EQ(knobs_of("#define RM_SHADOW_STEPS 8\n#include <rm/render.glsl>\n", defines).at("RM_SHADOW_STEPS"), "512");
  EXPECT_TRUE(preset_knobs("reference", "/nonexistent").empty());
}

// A control gives only values its knob takes: RM_NORMAL_TAPS 4 or 6 (5 is
// an error in rm/normals.glsl), integers on integers, all within the range.
TEST(Knobs, ControlsStayOnTheirStepsAndInTheirRange) {
  auto knob = [](const std::string& name) {
    for (const Knob& k : knob_table())
      if (name == k.name) return k;
    ADD_FAILURE() << name;
    return Knob{};
  };
  const Knob taps = knob("RM_NORMAL_TAPS"), steps = knob("RM_MAX_STEPS"), omega = knob("RM_OMEGA");
  EXPECT_EQ(knob_snapped(taps, 4.4f), 4.0f);
  EXPECT_EQ(knob_snapped(taps, 5.0f), 6.0f);
  EXPECT_EQ(knob_snapped(taps, 3.0f), 4.0f);
  EXPECT_EQ(knob_snapped(taps, 9.0f), 6.0f);
  EXPECT_EQ(knob_snapped(steps, 37.4f), 37.0f);
  EXPECT_EQ(knob_snapped(steps, 5000.0f), 2000.0f);
  EXPECT_EQ(knob_snapped(omega, 1.37f), 1.37f);  // a float knob keeps its value
  EXPECT_EQ(knob_snapped(omega, 3.0f), 2.0f);
}

TEST(Knobs, NoneWithoutShaderlib) { EXPECT_TRUE(knobs_of("#define RM_MAX_STEPS 5\n").empty()); }

TEST(Knobs, WithDefineReplacesAndRemoves) {
  std::vector<Define> d = {{"A", "1"}, {"RM_OMEGA", "1.2"}};
  d = with_define(d, "RM_OMEGA", "1.4");
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[1].value, "1.4");
  d = with_define(d, "RM_OMEGA", "");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].name, "A");
}

}  // namespace
}  // namespace rm
