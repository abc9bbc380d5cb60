// shaderlib's accuracy knobs as a scene's preprocessor sees them: those its
// modules define, their values after the scene's #defines, -D and the preset,
// and none for a scene without shaderlib.
#include <gtest/gtest.h>

#include <map>

#include "core/data_paths.h"
#include "core/knobs.h"
#include "support.h"

namespace rm {
namespace {

std::map<std::string, std::string> knobs_of(const std::string& text, std::vector<Define> defines = {}) {
  test::TempDir dir;
  test::write_file(dir / "s.frag", text + "void mainImage(out vec4 c, in vec2 f) { c = vec4(0); }\n");
  SourceOptions options;
  options.shaderlib_dir = shaderlib_dir();
  options.defines = std::move(defines);
  const Source source = preprocess(dir / "s.frag", options);
  EXPECT_TRUE(source.ok()) << join(source.errors);
  std::map<std::string, std::string> out;
  for (const KnobValue& k : knob_values(source)) out[k.knob->name] = k.value;
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
