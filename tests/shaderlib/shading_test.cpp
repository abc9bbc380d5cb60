// rm/camera.glsl, rm/optics.glsl and rm/lighting.glsl against their
// definitions: field of view and aspect, Snell's law with total internal
// reflection, Fresnel, Beer, Blinn-Phong, shadows, AO, spot cones, mouse light.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "gpu/egl_fixture.h"
#include "gpu/probe.h"

namespace rm::test {
namespace {

using glm::dvec3;

// Evaluates one vec4 expression per sample (P, Q as in probe.h).
std::vector<glm::vec4> eval(const std::string& prelude, const std::string& expression,
                            const std::vector<glm::vec4>& ps = {glm::vec4(0)}, const std::vector<glm::vec4>& qs = {}) {
  std::string error;
  auto got = probe(prelude, expression, ps, &error, qs);
  EXPECT_TRUE(got) << error;
  return got.value_or(std::vector<glm::vec4>(ps.size(), glm::vec4(NAN)));
}

double angle_between(glm::vec3 a, glm::vec3 b) {
  return std::acos(std::clamp(glm::dot(glm::normalize(glm::dvec3(a)), glm::normalize(glm::dvec3(b))), -1.0, 1.0));
}

class Camera : public EglTest {};

TEST_F(Camera, RaysSpanTheFieldOfViewWithTheRightAspect) {
  const std::string prelude = "#include <rm/camera.glsl>\n";
  const std::string ray = "vec4(rmCameraRay(rmLookAt(vec3(0.0, 0.0, 5.0), vec3(0.0), 1.0), P.xy, Q.xyz), 0.0)";
  // fragCoord, resolution (z = pixel aspect)
  const std::vector<glm::vec4> at = {{80, 45, 0, 0}, {80, 90, 0, 0}, {160, 45, 0, 0}, {160, 45, 0, 0}};
  const std::vector<glm::vec4> res = {{160, 90, 1, 0}, {160, 90, 1, 0}, {160, 90, 1, 0}, {160, 90, 2, 0}};
  const auto got = eval(prelude, ray, at, res);
  const glm::vec3 forward(0, 0, -1);
  EXPECT_NEAR(angle_between(glm::vec3(got[0]), forward), 0.0, 1e-3);
  EXPECT_NEAR(angle_between(glm::vec3(got[1]), forward), 0.5, 1e-5);  // top edge: half the vertical fov
  EXPECT_GT(got[1].y, 0.0f);
  EXPECT_NEAR(angle_between(glm::vec3(got[2]), forward), std::atan(std::tan(0.5) * 160.0 / 90.0), 1e-5);
  EXPECT_GT(got[2].x, 0.0f);  // right is +x when looking down -z with +y up
  EXPECT_NEAR(angle_between(glm::vec3(got[3]), forward), std::atan(std::tan(0.5) * 320.0 / 90.0), 1e-5);
}

// The cone is half a pixel's footprint per unit of t along the central ray.
TEST_F(Camera, PixelConeIsHalfAPixelPerUnitDistance) {
  const auto got = eval("#include <rm/camera.glsl>\n",
                        "vec4(rmPixelCone(rmLookAt(vec3(0.0, 0.0, 5.0), vec3(0.0), 1.0), vec3(160.0, 90.0, 1.0)))");
  const double pixel = 2.0 * std::tan(0.5) / 90.0;  // the image is 2 tan(fov / 2) tall at t = 1
  EXPECT_NEAR(got[0].x, pixel / 2.0, 1e-8);
}

TEST_F(Camera, BasisIsOrthonormalAndOrbitKeepsItsDistance) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-10, 10);
  std::vector<glm::vec4> eyes, targets;
  for (int i = 0; i < 1024; ++i) eyes.emplace_back(u(rng), u(rng), u(rng), 0), targets.emplace_back(u(rng), u(rng), u(rng), 0);
  eyes.emplace_back(0, 5, 0, 0), targets.emplace_back(0, 0, 0, 0);  // straight down
  eyes.emplace_back(0, -5, 0, 0), targets.emplace_back(0, 0, 0, 0);  // straight up
  const std::string prelude =
      "#include <rm/camera.glsl>\nvec4 check(vec3 eye, vec3 target) {\n"
      "  mat3 b = rmLookAt(eye, target, 1.0).basis;\n"
      "  mat3 e = transpose(b) * b - mat3(1.0);\n"
      "  float worst = max(max(length(e[0]), length(e[1])), length(e[2]));\n"
      "  return vec4(worst, determinant(b), dot(b[2], normalize(target - eye)),\n"
      "              length(rmOrbit(target, 3.0, eye.x, eye.y) - target));\n}\n";
  const auto got = eval(prelude, "check(P.xyz, Q.xyz)", eyes, targets);
  for (size_t i = 0; i < got.size(); ++i) {
    EXPECT_LT(got[i].x, 1e-5) << i;
    EXPECT_NEAR(got[i].y, -1.0, 1e-5) << i;  // (right, up, forward): forward is a right-handed frame's -z
    EXPECT_NEAR(got[i].z, 1.0, 1e-5) << i;  // looks at the target
    EXPECT_NEAR(got[i].w, 3.0, 1e-5) << i;
  }
}

class Optics : public EglTest {};

// Snell's law across y = 0 (ior 1.5 below), entering from above and leaving
// from below, over the whole range of angles; past the critical angle the ray
// is reflected.
TEST_F(Optics, RefractionFollowsSnellAndFallsBackToReflection) {
  const double ior = 1.5, critical = std::asin(1.0 / ior);
  std::vector<glm::vec4> ps;
  std::vector<double> angles;
  for (int i = 0; i < 2000; ++i) {
    const double a = (i + 0.5) / 2000.0 * (M_PI / 2 - 1e-3);
    if (std::abs(a - critical) < 1e-3) continue;
    const double turn = i * 0.37;
    const dvec3 tangent(std::cos(turn), 0, std::sin(turn));
    angles.push_back(a);
    ps.emplace_back(glm::vec3(std::sin(a) * tangent + dvec3(0, -std::cos(a), 0)), 0);  // entering
    ps.emplace_back(glm::vec3(std::sin(a) * tangent + dvec3(0, std::cos(a), 0)), 0);   // leaving
  }
  const auto got = eval("#include <rm/optics.glsl>\nvec4 go(vec3 rd) { bool tir; vec3 r = rmRefract(rd, "
                        "vec3(0.0, 1.0, 0.0), 1.5, tir); return vec4(r, tir ? 1.0 : 0.0); }\n",
                        "go(P.xyz)", ps);
  for (size_t i = 0; i < angles.size(); ++i) {
    const double a = angles[i];
    const glm::vec4 in = got[2 * i], out = got[2 * i + 1];
    const dvec3 in_dir(ps[2 * i]), out_dir(ps[2 * i + 1]);
    EXPECT_EQ(in.w, 0.0f);
    EXPECT_LT(in.y, 0.0f);
    EXPECT_NEAR(glm::length(glm::dvec2(in.x, in.z)), std::sin(a) / ior, 1e-5) << "entering at " << a;
    if (a < critical) {
      EXPECT_EQ(out.w, 0.0f) << a;
      EXPECT_GT(out.y, 0.0f);
      EXPECT_NEAR(glm::length(glm::dvec2(out.x, out.z)), std::sin(a) * ior, 1e-4) << "leaving at " << a;
    } else {
      EXPECT_EQ(out.w, 1.0f) << "total internal reflection at " << a;
      EXPECT_NEAR(out.x, out_dir.x, 1e-6);
      EXPECT_NEAR(out.y, -out_dir.y, 1e-6);
      EXPECT_NEAR(out.z, out_dir.z, 1e-6);
    }
  }
}

TEST_F(Optics, FresnelAndBeer) {
  const auto got = eval("#include <rm/optics.glsl>\n",
                        "vec4(rmFresnel(vec3(0.0, -1.0, 0.0), vec3(0.0, 1.0, 0.0), 1.5), "
                        "rmFresnel(normalize(vec3(1.0, 0.5, 0.0)), vec3(0.0, 1.0, 0.0), 1.5), "
                        "rmFresnel(normalize(vec3(1.0, -0.1, 0.0)), vec3(0.0, 1.0, 0.0), 1.5), rmBeer(vec3(0.5), 2.0).x)");
  EXPECT_NEAR(got[0].x, 0.04, 1e-6);           // normal incidence: ((n - 1) / (n + 1))^2
  EXPECT_EQ(got[0].y, 1.0f);                    // leaving at 63 degrees: past the critical angle
  EXPECT_GT(got[0].z, 0.5f);                    // grazing entry reflects most light
  EXPECT_NEAR(got[0].w, std::exp(-1.0), 1e-6);
}

class Lighting : public EglTest {};

const char* kLightingPrelude = R"(#include <rm/lighting.glsl>
#include <rm/sdf.glsl>
float map(vec3 p) { return min(sdSphere(p - vec3(0.0, 0.6, 0.0), 0.5), p.y); }  // 0.1 above the ground
)";

TEST_F(Lighting, BlinnPhongPeaksWhenLightViewAndNormalAgree) {
  const auto got = eval(kLightingPrelude,
                        "vec4(rmBlinnPhong(vec3(0.0, 1.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(1.0), "
                        "rmMaterial(vec3(0.5, 0.25, 0.0))), "
                        "rmBlinnPhong(vec3(0.0, 1.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, -1.0, 0.0), vec3(1.0), "
                        "rmMaterial(vec3(0.5))).x)");
  EXPECT_NEAR(got[0].x, 0.5 + 0.3, 1e-6);  // albedo * 1 + specular strength 0.3
  EXPECT_NEAR(got[0].y, 0.25 + 0.3, 1e-6);
  EXPECT_EQ(got[0].w, 0.0f);  // lit from behind: nothing
}

TEST_F(Lighting, ShadowsSeeTheSphereAndNotTheOpenSky) {
  // From the ground under the sphere toward the sky (blocked), far from it
  // (open: the distance doubles every step there), and just beside it.
  const auto got = eval(kLightingPrelude,
                        "vec4(rmHardShadow(vec3(0.0, 0.01, 0.0), vec3(0.0, 1.0, 0.0), 0.01, 10.0), "
                        "rmSoftShadow(vec3(0.0, 0.01, 0.0), vec3(0.0, 1.0, 0.0), 0.01, 10.0, 16.0), "
                        "rmSoftShadowImproved(vec3(3.0, 0.01, 0.0), vec3(0.0, 1.0, 0.0), 0.01, 10.0, 16.0), "
                        "rmSoftShadowImproved(vec3(0.52, 0.01, 0.0), vec3(0.0, 1.0, 0.0), 0.01, 10.0, 16.0))");
  EXPECT_EQ(got[0].x, 0.0f);
  EXPECT_EQ(got[0].y, 0.0f);
  EXPECT_EQ(got[0].z, 1.0f);
  EXPECT_GT(got[0].w, 0.0f);  // passing 0.02 beside the sphere: penumbra
  EXPECT_LT(got[0].w, 1.0f);
}

TEST_F(Lighting, AmbientOcclusionIsOpenOnAPlaneAndDarkUnderTheSphere) {
  const auto got = eval(kLightingPrelude,
                        "vec4(rmAmbientOcclusion(vec3(3.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0)), "
                        "rmAmbientOcclusion(vec3(0.2, 0.0, 0.0), vec3(0.0, 1.0, 0.0)), 0.0, 0.0)");
  EXPECT_NEAR(got[0].x, 1.0, 1e-6);
  EXPECT_LT(got[0].y, 0.9f);
}

TEST_F(Lighting, SpotConeAndInverseSquareFalloff) {
  const auto got = eval(kLightingPrelude,
                        "vec4(rmLightRadiance(rmSpotLight(vec3(0.0, 2.0, 0.0), vec3(0.0, -1.0, 0.0), vec3(1.0), 0.3, 0.5), vec3(0.0)).x, "
                        "rmLightRadiance(rmSpotLight(vec3(0.0, 2.0, 0.0), vec3(0.0, -1.0, 0.0), vec3(1.0), 0.3, 0.5), vec3(2.0, 0.0, 0.0)).x, "
                        "rmLightRadiance(rmPointLight(vec3(0.0, 2.0, 0.0), vec3(1.0)), vec3(0.0)).x, "
                        "rmLightDirection(rmDirectionalLight(vec3(0.0, 2.0, 0.0), vec3(1.0)), vec3(5.0)).y)");
  EXPECT_NEAR(got[0].x, 0.25, 1e-6);  // on the axis: 1 / 2^2
  EXPECT_EQ(got[0].y, 0.0f);          // 45 degrees off: outside the 0.5 rad cone
  EXPECT_NEAR(got[0].z, 0.25, 1e-6);
  EXPECT_NEAR(got[0].w, 1.0, 1e-6);
}

// Dragging to the top of the window raises the light; across turns it around.
TEST_F(Lighting, MouseDragMovesTheLight) {
  const std::vector<glm::vec4> mice = {{80, 90, 80, 90}, {80, 0, -80, -90}, {0, 45, 1, 1}, {40, 45, 1, 1}};
  const auto got = eval(kLightingPrelude, "vec4(rmMouseLightDirection(P, vec2(160.0, 90.0), vec3(1.0)), 0.0)", mice);
  EXPECT_NEAR(got[0].y, std::sin(1.45), 1e-5);
  EXPECT_NEAR(got[1].y, std::sin(0.1), 1e-5);  // still there after release (z < 0)
  EXPECT_GT(angle_between(glm::vec3(got[2]), glm::vec3(got[3])), 1.0);
  for (const auto& v : got) EXPECT_NEAR(glm::length(glm::vec3(v)), 1.0, 1e-5);
}

class Texture : public EglTest {};

// Triplanar mapping reads any sampler2D (iChannelN in a scene; here the
// probe's second input, filled with one colour): its three projections are
// weighted to sum to 1 for every normal, so a uniform texture comes back as is.
TEST_F(Texture, TriplanarWeightsSumToOne) {
  std::mt19937 rng(9);
  std::normal_distribution<float> normal;
  std::vector<glm::vec4> ps = {{1, 0, 0, 0}, {0, -1, 0, 0}, {0, 0, 1, 0}, {1e-20f, 0, 0, 0}};
  while (ps.size() < 1024) ps.emplace_back(normal(rng), normal(rng), normal(rng), 0);  // fills the texture: no zero padding
  const std::vector<glm::vec4> colour(ps.size(), glm::vec4(0.25f, 0.5f, 0.75f, 1.0f));
  const auto got = eval("#include <rm/common.glsl>\n#include <rm/texture.glsl>\n",
                        "rmTriplanar(extras, P.xyz * 3.7, rmSafeNormalize(P.xyz, vec3(0.0, 1.0, 0.0)), 0.5, 4.0)", ps,
                        colour);
  for (size_t i = 0; i < got.size(); ++i)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[i][c], colour[i][c], 1e-5) << "normal " << i;
}

// -0 and +0 are one lattice point, so every hash must agree on them, also
// when the zero is only known at run time (round(-0.3) gives -0): compilers
// fold `x + 0.0` to x, so that cannot be the fix.
TEST_F(Texture, HashesTreatMinusZeroAsZero) {
  const std::vector<glm::vec4> minus_zero = {{-0.0f, -0.0f, -0.0f, -0.3f}}, zero = {{0.0f, 0.0f, 0.0f, 0.3f}};
  const auto got = eval("#include <rm/texture.glsl>\n",
                        "vec4(rmHash(P.x) - rmHash(Q.x), rmHash(P.xy) - rmHash(Q.xy), rmHash(P.xyz) - rmHash(Q.xyz), "
                        "length(rmHash3(vec3(round(P.w))) - rmHash3(vec3(round(Q.w)))))",
                        minus_zero, zero);
  EXPECT_EQ(got[0], glm::vec4(0.0f));
}

// The integer lattice's hash (pcg3d) spreads a 16x16x16 block of cells,
// negative ones included, evenly over [0, 1) in each of its three values,
// with no correlation between the values or between neighbouring cells: an
// index-like hash (fract(cell * k)) fails the neighbours, one output reused
// fails the pairs.
TEST_F(Texture, CellHashIsUniformAndUncorrelated) {
  std::vector<glm::vec4> cells;
  for (int z = -8; z < 8; ++z)
    for (int y = -8; y < 8; ++y)
      for (int x = -8; x < 8; ++x) cells.emplace_back(x, y, z, 0);
  const auto got = eval("#include <rm/texture.glsl>\n", "vec4(rmHash3(ivec3(P.xyz)), 0.0)", cells);
  ASSERT_EQ(got.size(), cells.size());
  auto correlation = [&](auto a, auto b, int skip) {
    double sa = 0, sb = 0, sab = 0, saa = 0, sbb = 0;
    const double n = static_cast<double>(got.size() - skip);
    for (size_t i = 0; i + skip < got.size(); ++i) {
      const double u = a(got[i]), v = b(got[i + skip]);
      sa += u, sb += v, sab += u * v, saa += u * u, sbb += v * v;
    }
    return (sab / n - sa / n * sb / n) / std::sqrt((saa / n - sa / n * sa / n) * (sbb / n - sb / n * sb / n));
  };
  for (int c = 0; c < 3; ++c) {
    std::array<int, 8> bins{};
    double sum = 0;
    for (const glm::vec4& v : got) {
      ASSERT_GE(v[c], 0.0f);
      ASSERT_LT(v[c], 1.0f);
      sum += v[c];
      ++bins[static_cast<size_t>(v[c] * 8.0f)];
    }
    EXPECT_NEAR(sum / got.size(), 0.5, 0.02) << "value " << c;  // 4 sigma for 4096 cells
    for (int b : bins) EXPECT_NEAR(b, 512, 100) << "value " << c;  // 5 sigma
    auto value = [c](const glm::vec4& v) { return double(v[c]); };
    auto next = [c](const glm::vec4& v) { return double(v[(c + 1) % 3]); };
    EXPECT_LT(std::abs(correlation(value, next, 0)), 0.06) << "values " << c << " and " << (c + 1) % 3;
    for (int skip : {1, 16, 256})  // the neighbour along x, y and z
      EXPECT_LT(std::abs(correlation(value, value, skip)), 0.06) << "value " << c << ", cells " << skip << " apart";
  }
}

}  // namespace
}  // namespace rm::test
