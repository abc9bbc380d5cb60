// rm/render.glsl compiles in only the effects a scene asks for: the render
// path (rmRender, rmDirectLight), as glslang's own preprocessor leaves it,
// calls no shadow, AO, reflection, refraction or fog code unless the scene
// defines the macro for it, and calls exactly that code when it does.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/check.h"
#include "gpu/egl_fixture.h"
#include "gpu/probe.h"
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

// kScene with shaderlib and `defines`, its includes expanded.
Source scene_source(const std::vector<Define>& defines) {
  TempDir dir;
  write_file(dir / "scene.frag", kScene);
  SourceOptions options;
  options.shaderlib_dir = shaderlib_dir();
  options.defines = defines;
  Source source = preprocess(dir / "scene.frag", options);
  EXPECT_TRUE(source.ok()) << join(source.errors);
  return source;
}

// The render path of kScene compiled with `defines`, as the compiler sees it.
std::string render_path(const std::vector<Define>& defines) {
  const Source source = scene_source(defines);
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

// Presets set the knobs together; a knob given on its own wins.
TEST(Quality, PresetsSetTheKnobsAndAnExplicitKnobWins) {
  auto settings = [](const std::vector<Define>& defines) {
    Diagnostics diags;
    const auto text = expand_preprocessor(scene_source(defines), &diags);
    return body_of(text.value_or(""), "RmMarchSettings rmMarchSettings");
  };
  EXPECT_NE(settings({}).find("160"), std::string::npos) << settings({});
  EXPECT_NE(settings({{"RM_QUALITY", "RM_DRAFT"}}).find("64"), std::string::npos);
  EXPECT_NE(settings({{"RM_QUALITY", "RM_REFERENCE"}}).find("2000"), std::string::npos);
  const std::string both = settings({{"RM_QUALITY", "RM_DRAFT"}, {"RM_MAX_STEPS", "300"}});
  EXPECT_NE(both.find("300"), std::string::npos) << both;
  EXPECT_EQ(both.find(" 64,"), std::string::npos) << both;
}

// A knob out of its range is an error at its check in shaderlib that names
// the knob, not a picture of NaN: no rays a pixel, fewer than no lights or
// bounces, AO taps beyond the bits of an int, normal taps that are neither
// method's (5 drew the 4 taps' normals).
TEST(KnobChecks, OutOfRangeIsAnErrorThatNamesTheKnob) {
  struct Bad {
    const char* name;
    const char* value;
    const char* module;
  };
  for (const Bad& bad : {Bad{"RM_SAMPLES", "0", "rm/render.glsl"}, Bad{"RM_LIGHT_COUNT", "-1", "rm/render.glsl"},
                         Bad{"RM_REFLECTIONS", "-1", "rm/render.glsl"}, Bad{"RM_REFRACTION", "-2", "rm/render.glsl"},
                         Bad{"RM_AO_SAMPLES", "-1", "rm/lighting.glsl"}, Bad{"RM_AO_SAMPLES", "33", "rm/lighting.glsl"},
                         Bad{"RM_NORMAL_TAPS", "5", "rm/normals.glsl"}}) {
    const Source source = scene_source({{bad.name, bad.value}});
    ASSERT_TRUE(source.ok());
    const Diagnostics diags = validate(source);
    const bool named = std::any_of(diags.begin(), diags.end(), [&](const Diagnostic& d) {
      return d.severity == Severity::Error && d.path.ends_with(bad.module) && d.line > 0 &&
             d.message.find(std::string(bad.name) + " must") != std::string::npos;
    });
    EXPECT_TRUE(named) << bad.name << "=" << bad.value << ": " << join(diags);
  }
}

// Run-time selection: map() evaluations per pixel, counted by the scene, for
// rays at a mirror sphere (left) and a matte one (right) over a matte floor,
// rendered with and without RM_REFLECTIONS / RM_REFRACTION / shadows. A pixel
// pays for a secondary ray only when its material or its lighting needs one.
class RunTime : public EglTest {
 protected:
  // Rays from (0, 0.5, 6) through 64 points around `aim` (a 8 x 8 grid, 0.02 apart).
  static std::vector<glm::vec4> rays_at(glm::vec3 aim) {
    std::vector<glm::vec4> rays;
    for (int i = 0; i < 64; ++i)
      rays.emplace_back(aim + glm::vec3(0.02f * (i % 8), 0.02f * (i / 8), 0.0f) - glm::vec3(0.0f, 0.5f, 6.0f), 0.0f);
    return rays;
  }

  static std::vector<float> evaluations(const std::string& defines, const std::vector<glm::vec4>& rays,
                                        const std::string& result = "vec4(count(P.xyz))") {
    const std::string prelude = defines + R"(
uniform vec4 iMouse;
uniform vec3 iResolution;
#include <rm/sdf.glsl>
#include <rm/render.glsl>
int evaluations = 0;
float map(vec3 p) {
  ++evaluations;
  return min(min(sdSphere(p - vec3(-1.2, 0.0, 0.0), 1.0), sdSphere(p - vec3(1.2, 0.0, 0.0), 1.0)), p.y + 1.0);
}
RmMaterial material(vec3 p, vec3 n) {
  RmMaterial m = rmMaterial(vec3(0.8));
  if (length(p - vec3(-1.2, 0.0, 0.0)) < 1.01) m.reflectivity = 0.9;  // the left sphere is a mirror
  if (length(p - vec3(1.2, 0.0, 0.0)) < 1.01) m.transparency = 0.0;   // the right one is matte
  return m;
}
float count(vec3 rd) {
  rmRender(vec3(0.0, 0.5, 6.0), normalize(rd), 1e-3);
  return float(evaluations);
}
)";
    std::string error;
    auto got = probe(prelude, result, rays, &error);
    EXPECT_TRUE(got) << error;
    std::vector<float> counts;
    for (const auto& v : got.value_or(std::vector<glm::vec4>(rays.size()))) counts.push_back(v.x);
    return counts;
  }
};

TEST_F(RunTime, OnlyMirrorPixelsPayForReflectionRays) {
  auto rays = rays_at({-1.3f, 0.2f, 0.9f});                   // the mirror's face
  const auto matte = rays_at({1.1f, 0.2f, 0.9f});              // the matte sphere's face
  rays.insert(rays.end(), matte.begin(), matte.end());
  const auto plain = evaluations("", rays);
  const auto reflective = evaluations("#define RM_REFLECTIONS 2\n#define RM_REFRACTION 2\n", rays);
  ASSERT_EQ(plain.size(), 128u);
  ASSERT_EQ(reflective.size(), 128u);
  for (size_t i = 0; i < 64; ++i) EXPECT_GT(reflective[i], plain[i]) << "mirror pixel " << i << " traced no reflection";
  for (size_t i = 64; i < 128; ++i) EXPECT_EQ(reflective[i], plain[i]) << "matte pixel " << i << " paid for a secondary ray";
}

// The default sun (no iMouse) shines from above, in front and to the right.
// Its shadow rays start only where a surface faces it.
TEST_F(RunTime, ShadowRaysOnlyWhereTheSurfaceFacesTheLight) {
  auto rays = rays_at({1.1f, 0.55f, 0.6f});                    // the matte sphere's top: lit
  const auto dark = rays_at({1.0f, -0.8f, 0.4f});               // its underside: facing away
  rays.insert(rays.end(), dark.begin(), dark.end());
  const auto plain = evaluations("", rays);
  const auto shadowed = evaluations("#define RM_SHADOWS 1\n", rays);
  ASSERT_EQ(shadowed.size(), 128u);
  for (size_t i = 0; i < 64; ++i) EXPECT_GT(shadowed[i], plain[i]) << "lit pixel " << i << " traced no shadow ray";
  for (size_t i = 64; i < 128; ++i) EXPECT_EQ(shadowed[i], plain[i]) << "dark pixel " << i << " traced a shadow ray";
}

// The light rmDirectLight gives a point on the floor under a sun straight
// overhead, with `defines` ahead of shaderlib and, with `ball`, a ball 3
// units up.
float floor_light(const std::string& defines, bool ball) {
  const std::string prelude = "#define RM_SHADOWS 1\n#define RM_LIGHT_COUNT 1\n" + defines + R"(
#include <rm/sdf.glsl>
#include <rm/render.glsl>
RmLight light(int i) { return rmDirectionalLight(vec3(0.0, 1.0, 0.0), vec3(1.0)); }
float map(vec3 p) { return min(p.y, )" + (ball ? "sdSphere(p - vec3(0.0, 3.0, 0.0), 1.0)" : "1e9") + R"(); }
RmMaterial material(vec3 p, vec3 n) { return rmMaterial(vec3(0.5)); }
)";
  std::string error;
  auto got = probe(prelude, "vec4(rmDirectLight(vec3(0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 1.0, 0.0), "
                            "rmMaterial(vec3(0.5)), 1e-3), 0.0)", {glm::vec4(0)}, &error);
  EXPECT_TRUE(got) << error;
  return got ? (*got)[0].x : -1.0f;
}

// RM_SHADOW_REACH: a point on the floor under a sun straight overhead, with a
// ball 3 units up. The ball shades the point while the reach passes it, and
// no longer once the reach stops short of it (the point then looks as lit as
// with no ball at all).
TEST_F(EglTest, ShadowReachDecidesWhichOccludersCount) {
  const float open = floor_light("", false);
  EXPECT_LT(floor_light("", true), 0.5f * open) << "the ball casts no shadow with the default reach";
  EXPECT_LT(floor_light("#define RM_SHADOW_REACH 2.5\n", true), 0.5f * open) << "the ball is within the reach";
  EXPECT_EQ(floor_light("#define RM_SHADOW_REACH 1.5\n", true), open) << "the ball is beyond the reach";
}

// Zero of a count means none, as the controls panel's range allows:
// RM_AO_SAMPLES 0 takes no taps and leaves a point open (the light of a scene
// without RM_AO), and RM_LIGHT_COUNT 0 leaves the ambient term alone. A
// point on the floor just under a ball, lit from straight above.
TEST_F(EglTest, ZeroAoTapsAndZeroLightsMeanNone) {
  auto at_floor = [](const std::string& defines) {
    const std::string prelude = defines + R"(
#include <rm/sdf.glsl>
#include <rm/render.glsl>
RmLight light(int i) { return rmDirectionalLight(vec3(0.0, 1.0, 0.0), vec3(1.0)); }
float map(vec3 p) { return min(p.y, sdSphere(p - vec3(0.0, 0.6, 0.0), 0.5)); }
RmMaterial material(vec3 p, vec3 n) { return rmMaterial(vec3(0.5)); }
)";
    std::string error;
    auto got = probe(prelude,
                     "vec4(rmDirectLight(vec3(0.2, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 1.0, 0.0), "
                     "rmMaterial(vec3(0.5)), 1e-3).x, rmAmbientOcclusion(vec3(0.2, 0.0, 0.0), vec3(0.0, 1.0, 0.0)), 0.0, 0.0)",
                     {glm::vec4(0)}, &error);
    EXPECT_TRUE(got) << defines << error;
    return got ? glm::vec2((*got)[0]) : glm::vec2(-1.0f);
  };
  const glm::vec2 occluded = at_floor("#define RM_LIGHT_COUNT 1\n#define RM_AO\n");
  EXPECT_LT(occluded.y, 0.9f) << "the ball does not occlude the point: the test proves nothing";
  const glm::vec2 no_taps = at_floor("#define RM_LIGHT_COUNT 1\n#define RM_AO\n#define RM_AO_SAMPLES 0\n");
  EXPECT_EQ(no_taps.y, 1.0f);
  EXPECT_EQ(no_taps.x, at_floor("#define RM_LIGHT_COUNT 1\n").x) << "not the light without RM_AO";
  const float ambient = 0.5f * 0.12f;  // albedo x RM_AMBIENT, facing straight up, nothing occluding
  EXPECT_NEAR(at_floor("#define RM_LIGHT_COUNT 0\n").x, ambient, 1e-6);
  EXPECT_GT(at_floor("#define RM_LIGHT_COUNT 1\n").x, ambient + 0.4f);
}

// RM_BOUNDING_BOX_MIN/MAX: all of map()'s surface lies in the box. A ray
// that misses it calls map() not once, one that hits draws the same colour
// as without the box, and a shadow ray stops where it leaves the box.
TEST_F(EglTest, ABoundingBoxSkipsWhatLiesOutsideIt) {
  const std::string box = "#define RM_BOUNDING_BOX_MIN vec3(-1.1, -1.1, -1.1)\n"
                          "#define RM_BOUNDING_BOX_MAX vec3(1.1, 1.1, 1.1)\n";
  auto trace = [](const std::string& defines, const std::vector<glm::vec4>& rays) {
    const std::string prelude = defines + R"(
uniform vec4 iMouse;
uniform vec3 iResolution;
#include <rm/sdf.glsl>
#include <rm/render.glsl>
int evaluations = 0;
float map(vec3 p) { ++evaluations; return sdSphere(p, 1.0); }
RmMaterial material(vec3 p, vec3 n) { return rmMaterial(vec3(0.8)); }
)";
    std::string error;
    auto got = probe(prelude, "vec4(rmRender(vec3(0.0, 0.0, 5.0), normalize(P.xyz), 1e-3).xy, 0.0, float(evaluations))",
                     rays, &error);
    EXPECT_TRUE(got) << error;
    return got.value_or(std::vector<glm::vec4>(rays.size()));
  };
  const std::vector<glm::vec4> rays = {{0.0f, 0.0f, -1.0f, 0.0f}, {0.1f, 0.15f, -1.0f, 0.0f}, {0.0f, 1.0f, -0.2f, 0.0f}};
  const auto plain = trace("", rays), boxed = trace(box, rays);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_GT(boxed[i].w, 0.0f) << "ray " << i << " hits the sphere";
    EXPECT_NEAR(boxed[i].x, plain[i].x, 1e-5f) << "ray " << i;
    EXPECT_NEAR(boxed[i].y, plain[i].y, 1e-5f) << "ray " << i;
  }
  EXPECT_GT(plain[2].w, 0.0f) << "without the box, a ray up into the sky marches";
  EXPECT_EQ(boxed[2].w, 0.0f) << "with it, the ray misses the box and calls map() not once";

  // A point on the floor under a sun overhead, a ball 3 units up: a box
  // that holds the ball lets it shade the point; one that stops below it
  // (breaking the contract, to show the clipping) leaves the point lit.
  const float shaded = floor_light("", true), open = floor_light("#define RM_SHADOW_REACH 1.5\n", true);
  EXPECT_LT(shaded, 0.5f * open);
  EXPECT_EQ(floor_light("#define RM_BOUNDING_BOX_MIN vec3(-5.0, -1.0, -5.0)\n#define RM_BOUNDING_BOX_MAX vec3(5.0, 4.5, 5.0)\n",
                        true), shaded) << "the box holds the ball";
  EXPECT_EQ(floor_light("#define RM_BOUNDING_BOX_MIN vec3(-5.0, -1.0, -5.0)\n#define RM_BOUNDING_BOX_MAX vec3(5.0, 1.5, 5.0)\n",
                        true), open) << "the shadow ray stops where it leaves the box";
}

// The analytic ground (RM_GROUND) is not in map(): ambient occlusion at a
// point on it measures the objects' distances from the ground itself. Under
// ambient light alone, the ground far from a ball resting on it is open (it
// was black: map() there, the distance to the ball, was subtracted from every
// tap), and the ground where the ball touches it is darker.
TEST_F(EglTest, AmbientOcclusionOnTheAnalyticGroundIsOpenAwayFromObjects) {
  const std::string prelude = R"(#define RM_AO
#define RM_GROUND 0.0
#define RM_AMBIENT 1.0
#define RM_LIGHT_COUNT 1
uniform vec4 iMouse;
uniform vec3 iResolution;
#include <rm/sdf.glsl>
#include <rm/render.glsl>
RmLight light(int i) { return rmDirectionalLight(vec3(0.0, 1.0, 0.0), vec3(0.0)); }
float map(vec3 p) { return sdSphere(p - vec3(0.0, 0.5, 0.0), 0.5); }
RmMaterial material(vec3 p, vec3 n) { return rmMaterial(vec3(0.5)); }
RmMaterial groundMaterial(vec3 p) { return rmMaterial(vec3(0.5)); }
)";
  std::string error;
  // Onto the ground at x = P.x, from above and to the right: clear of the ball.
  auto got = probe(prelude, "vec4(rmRender(vec3(P.x + 3.0, 3.0, 0.0), normalize(vec3(-1.0, -1.0, 0.0)), 1e-3), 0.0)",
                   {glm::vec4(5.0f, 0, 0, 0), glm::vec4(0.45f, 0, 0, 0)}, &error);
  ASSERT_TRUE(got) << error;
  EXPECT_NEAR((*got)[0].x, 0.5f, 1e-4f) << "albedo 0.5 under the whole ambient light, far from the ball";
  EXPECT_LT((*got)[1].x, 0.4f) << "under the ball's side, 0.28 below it, occluded";
  EXPECT_GT((*got)[1].x, 0.05f) << "but not closed";
}

// RM_MAP_BOUND: a slab (cheap, given exactly by mapBound) and a ball (costly,
// bound by a sphere 0.05 larger), lit by a sun with soft shadows and AO. The
// picture is the one without the bound (the rays' steps differ, so shadows may
// move by a sample's worth), map() runs far less often, and rays that never
// come near the ball, whether they end in the sky or on the slab, call it only
// for the hit point's normal. With hard, classic and improved shadows.
TEST_F(EglTest, AMapBoundGivesThePictureWithFarFewerMapCalls) {
  auto trace = [](const std::string& defines, const std::vector<glm::vec4>& rays) {
    const std::string prelude = defines + R"(
#define RM_AO
#define RM_LIGHT_COUNT 1
uniform vec4 iMouse;
uniform vec3 iResolution;
#include <rm/sdf.glsl>
#include <rm/render.glsl>
int costly = 0;
float slab(vec3 p) { return sdBox(p + vec3(0.0, 0.5, 0.0), vec3(3.0, 0.5, 3.0)); }
float ball(vec3 p) { ++costly; return sdSphere(p - vec3(0.0, 0.8, 0.0), 0.8); }
float map(vec3 p) { return min(slab(p), ball(p)); }
vec2 mapBound(vec3 p) { return vec2(slab(p), length(p - vec3(0.0, 0.8, 0.0)) - 0.85); }
RmLight light(int i) { return rmDirectionalLight(vec3(0.6, 0.7, 0.3), vec3(1.0)); }
RmMaterial material(vec3 p, vec3 n) { return rmMaterial(vec3(0.8)); }
)";
    std::string error;
    auto got = probe(prelude, "vec4(rmRender(vec3(0.0, 2.5, 6.0), normalize(P.xyz), 1e-3), float(costly))", rays,
                     &error);
    EXPECT_TRUE(got) << error;
    return got.value_or(std::vector<glm::vec4>(rays.size(), glm::vec4(NAN)));
  };
  // A fan of 16 x 12 rays over the ball, its shadow on the slab and the sky;
  // then two that stay far from the ball: into the sky, and onto the slab's far
  // side, where the shadow ray leaves toward the sun, away from the ball.
  std::vector<glm::vec4> rays;
  for (int i = 0; i < 16 * 12; ++i)
    rays.emplace_back(-0.5f + (i % 16) / 15.0f, 0.1f - 0.7f * (i / 16) / 11.0f, -1.0f, 0.0f);
  rays.emplace_back(0.3f, 0.5f, -1.0f, 0.0f);
  rays.emplace_back(0.55f, -0.5f, -1.0f, 0.0f);
  for (const char* shadows : {"1", "2", "3"}) {
    SCOPED_TRACE(std::string("RM_SHADOWS ") + shadows);
    const std::string effects = std::string("#define RM_SHADOWS ") + shadows + "\n";
    const auto plain = trace(effects, rays), bounded = trace(effects + "#define RM_MAP_BOUND\n", rays);
    double calls_plain = 0, calls_bounded = 0, worst = 0, sum = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
      calls_plain += plain[i].w;
      calls_bounded += bounded[i].w;
      const double diff = glm::length(glm::dvec3(bounded[i]) - glm::dvec3(plain[i]));
      if (!(diff <= worst)) worst = diff;  // NaN makes it NaN
      sum += diff;
    }
    std::printf("[map bound] RM_SHADOWS %s: map() calls %.0f -> %.0f, colour difference mean %.2g, worst %.2g\n",
                shadows, calls_plain, calls_bounded, sum / rays.size(), worst);
    EXPECT_LT(sum / rays.size(), 2e-3);
    EXPECT_LT(worst, 0.1);
    EXPECT_LT(calls_bounded, 0.5 * calls_plain);
    const size_t sky = rays.size() - 2, corner = rays.size() - 1;
    EXPECT_GT(plain[sky].w, 0.0f) << "without the bound the ray into the sky marches through map()";
    EXPECT_EQ(bounded[sky].w, 0.0f) << "the ray into the sky";
    EXPECT_EQ(bounded[corner].w, 4.0f) << "the far side of the slab: its normal's four taps, nothing more";
  }
}

// RM_COUNT's rmBoundEvaluations counts every mapBound() call the library
// makes (the march, each shadow form, AO), apart from map()'s: it equals the
// count the scene keeps inside mapBound() itself, and leaves rmEvaluations alone.
TEST_F(EglTest, CountingCoversEveryMapBoundCall) {
  std::vector<glm::vec4> rays;
  for (int i = 0; i < 8 * 6; ++i) rays.emplace_back(-0.5f + (i % 8) / 7.0f, 0.1f - 0.7f * (i / 8) / 5.0f, -1.0f, 0.0f);
  for (const char* shadows : {"1", "2", "3"}) {
    SCOPED_TRACE(std::string("RM_SHADOWS ") + shadows);
    const std::string prelude = std::string("#define RM_SHADOWS ") + shadows + R"(
#define RM_COUNT
#define RM_MAP_BOUND
#define RM_AO
#define RM_LIGHT_COUNT 1
uniform vec4 iMouse;
uniform vec3 iResolution;
#include <rm/sdf.glsl>
#include <rm/render.glsl>
int maps = 0, bounds = 0;
float slab(vec3 p) { return sdBox(p + vec3(0.0, 0.5, 0.0), vec3(3.0, 0.5, 3.0)); }
float map(vec3 p) { ++maps; return min(slab(p), sdSphere(p - vec3(0.0, 0.8, 0.0), 0.8)); }
vec2 mapBound(vec3 p) { ++bounds; return vec2(slab(p), length(p - vec3(0.0, 0.8, 0.0)) - 0.85); }
RmLight light(int i) { return rmDirectionalLight(vec3(0.6, 0.7, 0.3), vec3(1.0)); }
RmMaterial material(vec3 p, vec3 n) { return rmMaterial(vec3(0.8)); }
vec4 counts(vec3 rd) {
  rmRender(vec3(0.0, 2.5, 6.0), rd, 1e-3);
  return vec4(float(rmBoundEvaluations - bounds), float(bounds), float(rmEvaluations - maps), float(maps));
}
)";
    std::string error;
    const auto got = probe(prelude, "counts(normalize(P.xyz))", rays, &error);
    ASSERT_TRUE(got) << error;
    float total = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
      EXPECT_EQ((*got)[i].x, 0.0f) << "ray " << i << ": the library's mapBound() count differs from the scene's";
      EXPECT_EQ((*got)[i].z, 0.0f) << "ray " << i << ": mapBound() calls leaked into the map() count";
      EXPECT_GT((*got)[i].y, 0.0f) << "ray " << i;
      total += (*got)[i].y;
    }
    EXPECT_GT(total, 10.0f * rays.size()) << "the shadow and AO taps are counted too";
  }
}

// RM_COUNT's rmEvaluations counts every map() call the library makes: with
// every effect on, it equals the count the scene keeps inside map() itself.
TEST_F(RunTime, CountingCoversEveryCall) {
  auto rays = rays_at({-1.3f, 0.2f, 0.9f});
  const auto matte = rays_at({1.1f, 0.55f, 0.6f});
  rays.insert(rays.end(), matte.begin(), matte.end());
  const std::string all = "#define RM_COUNT\n#define RM_SHADOWS 3\n#define RM_AO\n#define RM_REFLECTIONS 2\n"
                          "#define RM_REFRACTION 2\n#define RM_NORMAL_TAPS 6\n";
  const auto library = evaluations(all, rays, "vec4(count(P.xyz) - float(rmEvaluations))");
  const auto scene = evaluations(all, rays);
  ASSERT_EQ(library.size(), rays.size());
  for (size_t i = 0; i < rays.size(); ++i) {
    EXPECT_GT(scene[i], 20.0f) << "ray " << i;
    EXPECT_EQ(library[i], 0.0f) << "ray " << i << ": the library's count differs from the scene's";
  }
}

}  // namespace
}  // namespace rm::test
