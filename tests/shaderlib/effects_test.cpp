// rm/render.glsl compiles in only the effects a scene asks for: the render
// path (rmRender, rmDirectLight), as glslang's own preprocessor leaves it,
// calls no shadow, AO, reflection, refraction or fog code unless the scene
// defines the macro for it, and calls exactly that code when it does.
#include <gtest/gtest.h>

#include "core/check.h"
#include "core/data_paths.h"
#include "core/source.h"
#include "support.h"

namespace rm::test {
namespace {

const char* kScene = R"(#include <rm/sdf.glsl>
#include <rm/render.glsl>
float map(vec3 p) { return sdSphere(p, 1.0); }
RmMaterial material(vec3 p, vec3 n) { return rmMaterial(vec3(1.0)); }
void mainImage(out vec4 c, in vec2 f) { c = vec4(rmRender(vec3(0.0, 0.0, 3.0), vec3(0.0, 0.0, -1.0), 1e-3), 1.0); }
)";

// The body of function `name` in the compiler's text, braces matched.
std::string body_of(const std::string& text, const std::string& name) {
  const size_t start = text.find(name + "(");
  const size_t open = text.find('{', start);
  if (start == std::string::npos || open == std::string::npos) return "";
  int depth = 0;
  for (size_t i = open; i < text.size(); ++i) {
    depth += text[i] == '{' ? 1 : text[i] == '}' ? -1 : 0;
    if (depth == 0) return text.substr(open, i - open + 1);
  }
  return "";
}

// The render path of kScene compiled with `defines`, as the compiler sees it.
std::string render_path(const std::vector<Define>& defines) {
  TempDir dir;
  write_file(dir / "scene.frag", kScene);
  SourceOptions options;
  options.shaderlib_dir = shaderlib_dir();
  options.defines = defines;
  const Source source = preprocess(dir / "scene.frag", options);
  EXPECT_TRUE(source.ok()) << join(source.errors);
  Diagnostics diags;
  const auto text = expand_preprocessor(source, &diags);
  EXPECT_TRUE(text) << join(diags);
  return body_of(text.value_or(""), "vec3 rmRender") + body_of(text.value_or(""), "vec3 rmDirectLight");
}

// Calls that belong to one effect each.
const std::vector<std::pair<std::string, std::string>> kEffectCode = {
    {"hard shadows", "rmHardShadow("},     {"soft shadows", "rmSoftShadow("},
    {"improved soft shadows", "rmSoftShadowImproved("}, {"ambient occlusion", "rmAmbientOcclusion("},
    {"reflection", "reflect("},            {"refraction", "rmRefract("},
    {"Fresnel", "rmFresnel("},             {"absorption", "rmBeer("},
    {"fog", "rmFog("},
};

struct Case {
  std::string name;
  std::vector<Define> defines;
  std::vector<std::string> present;  // effect names whose code must be there; all others must not
};

std::ostream& operator<<(std::ostream& out, const Case& c) { return out << c.name; }

class Effects : public ::testing::TestWithParam<Case> {};

TEST_P(Effects, OnlyWhatTheSceneAsksForIsCompiledIn) {
  const Case& c = GetParam();
  const std::string path = render_path(c.defines);
  ASSERT_NE(path.find("rmMarch("), std::string::npos) << "the render path was not found";
  for (const auto& [effect, call] : kEffectCode) {
    const bool wanted = std::find(c.present.begin(), c.present.end(), effect) != c.present.end();
    EXPECT_EQ(path.find(call) != std::string::npos, wanted) << effect << " (" << call << ")";
  }
}

INSTANTIATE_TEST_SUITE_P(
    Render, Effects,
    ::testing::Values(Case{"Nothing", {}, {}},
                      Case{"HardShadows", {{"RM_SHADOWS", "1"}}, {"hard shadows"}},
                      Case{"SoftShadows", {{"RM_SHADOWS", "2"}}, {"soft shadows"}},
                      Case{"ImprovedSoftShadows", {{"RM_SHADOWS", "3"}}, {"improved soft shadows"}},
                      Case{"AmbientOcclusion", {{"RM_AO", ""}}, {"ambient occlusion"}},
                      Case{"Reflections", {{"RM_REFLECTIONS", "2"}}, {"reflection"}},
                      Case{"Refraction", {{"RM_REFRACTION", "3"}}, {"reflection", "refraction", "Fresnel", "absorption"}},
                      Case{"Fog", {{"RM_FOG", "0.1"}}, {"fog"}},
                      Case{"Everything",
                           {{"RM_SHADOWS", "3"}, {"RM_AO", ""}, {"RM_REFLECTIONS", "1"}, {"RM_REFRACTION", "1"},
                            {"RM_FOG", "0.1"}},
                           {"improved soft shadows", "ambient occlusion", "reflection", "refraction", "Fresnel",
                            "absorption", "fog"}}),
    [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

}  // namespace
}  // namespace rm::test
