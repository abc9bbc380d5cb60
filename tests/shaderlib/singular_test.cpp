// Every shaderlib function gives finite values at its singular points: centres,
// zero-size and zero-length parameters, smooth blends with k = 0, huge and
// negative distances, rays with zero direction components, t = 0 and h = 0.
#include <gtest/gtest.h>

#include <cmath>

#include "gpu/egl_fixture.h"
#include "gpu/probe.h"

namespace rm::test {
namespace {

struct Case {
  std::string name;
  std::string expression;  // a vec4; every component must be finite
  glm::vec4 expected{NAN};  // when not NaN: each component within 1e-5 of this
};

std::ostream& operator<<(std::ostream& out, const Case& c) { return out << c.name; }

const char* kPrelude = R"(#include <rm/sdf.glsl>
#include <rm/ops.glsl>
#include <rm/transforms.glsl>
#include <rm/fractals.glsl>
#include <rm/camera.glsl>
#include <rm/march.glsl>
#include <rm/normals.glsl>
#include <rm/lighting.glsl>
#include <rm/optics.glsl>
#include <rm/texture.glsl>
float map(vec3 p) { return sdSphere(p, 1.0); }
vec4 polar(vec2 p) { float cell; vec2 q = opRepeatPolar(p, 5.0, cell); return vec4(q, cell, 0.0); }
vec4 polarMirror(vec2 p, int n) { return vec4(opRepeatPolarMirror(p, n), 0.0, 0.0); }
vec4 march(vec3 ro, vec3 rd) {
  RmMarchSettings s = rmMarchSettings();
  s.boundBox = true; s.boundMin = vec3(-1.0); s.boundMax = vec3(1.0);
  s.ground = true; s.groundHeight = ro.y;
  RmMarch m = rmMarch(ro, rd, s);
  return vec4(m.t, float(m.steps), float(m.outcome), m.tolerance);
}
vec4 camera(vec3 eye, vec3 target) {
  RmCamera c = rmLookAt(eye, target, 1.0);
  return vec4(c.basis[0] + c.basis[1] + c.basis[2], determinant(c.basis));
}
vec4 refracted(vec3 rd, vec3 n, float ior) { bool tir; return vec4(rmRefract(rd, n, ior, tir), tir ? 1.0 : 0.0); }
)";

std::vector<Case> cases() {
  return {
      {"EllipsoidCentre", "vec4(sdEllipsoid(vec3(0.0), vec3(1.0, 0.5, 2.0)))", glm::vec4(-0.5f)},
      {"EllipsoidFlatAxis", "vec4(sdEllipsoid(vec3(0.3, 0.0, 0.1), vec3(1.0, 0.5, 2.0)))"},
      {"SphereCentre", "vec4(sdSphere(vec3(0.0), 1.0))", glm::vec4(-1.0f)},
      {"BoxCentreAndMedialAxis", "vec4(sdBox(vec3(0.0), vec3(1.0)), sdBox(vec3(0.5, 0.5, 0.0), vec3(1.0)), 0.0, 0.0)",
       glm::vec4(-1.0f, -0.5f, 0.0f, 0.0f)},
      {"CapsuleOfZeroLength", "vec4(sdCapsule(vec3(0.2), vec3(0.2), vec3(0.2), 0.5))", glm::vec4(-0.5f)},
      {"SegmentOfZeroLength", "vec4(sdSegment(vec2(1.0, 0.0), vec2(0.0), vec2(0.0)))", glm::vec4(1.0f)},
      {"RoundConeOfZeroHeight", "vec4(sdRoundCone(vec3(0.1), 0.5, 0.2, 0.0))"},
      {"RoundConeSwallowed", "vec4(sdRoundCone(vec3(0.0, 0.5, 0.0), 1.0, 0.2, 0.5))", glm::vec4(-0.5f)},
      {"CappedConeOfZeroHeight", "vec4(sdCappedCone(vec3(0.3), 0.0, 0.5, 0.5))"},
      {"CutSphereAtItsTop", "vec4(sdCutSphere(vec3(0.0, 1.0, 0.0), 1.0, 1.0))"},
      {"CappedTorusOnItsRing", "vec4(sdCappedTorus(vec3(0.0, 0.9, 0.0), vec2(sin(1.0), cos(1.0)), 0.9, 0.2))",
       glm::vec4(-0.2f)},
      {"OctahedronCentre", "vec4(sdOctahedron(vec3(0.0), 1.0))"},
      {"PyramidApexAndBase", "vec4(sdPyramid(vec3(0.0, 1.0, 0.0), 1.0), sdPyramid(vec3(0.0), 1.0), 0.0, 0.0)",
       glm::vec4(0.0f)},
      {"HexagonCentre", "vec4(sdHexagon(vec2(0.0), 1.0))", glm::vec4(-1.0f)},
      {"SmoothUnionWithZeroK", "vec4(opSmoothUnionBlend(0.3, -0.2, 0.0), opSmoothIntersection(0.3, -0.2, 0.0), 0.0)",
       glm::vec4(-0.2f, 1.0f, 0.3f, 0.0f)},
      {"SmoothOpsOnHugeDistances",
       "vec4(opSmoothUnion(1e6, -1e6, 0.5), opSmoothUnion(1e6, 1e6, 0.5), opSmoothSubtraction(-1e6, 1e6, 0.5), "
       "opSmoothIntersection(-1e6, -1e6, 0.5))"},
      {"SmoothUnionOfNegatives", "vec4(opSmoothUnionBlend(-0.4, -0.45, 0.2), opSmoothUnion(-1e6, -1e6, 1.0), 0.0)"},
      {"ChamferAndRoundWithZeroRadius",
       "vec4(opChamferUnion(0.3, 0.5, 0.0), opRoundUnion(0.3, 0.5, 0.0), opRoundIntersection(0.3, 0.5, 0.0), "
       "opRoundSubtraction(0.3, -0.5, 0.0))",
       // outside both, r = 0 gives the distance to a right-angled edge: length(a, b)
       glm::vec4(0.3f, 0.3f, 0.5830952f, 0.5830952f)},
      {"PolarRepetitionAtTheCentre", "polar(vec2(0.0))", glm::vec4(0.0f)},
      {"MirroredPolarRepetitionAtTheCentre", "polarMirror(vec2(0.0), 8)", glm::vec4(0.0f)},
      {"MirroredPolarRepetitionOfNoCopies", "polarMirror(vec2(-0.5, -0.25), 0)", glm::vec4(-0.5f, 0.25f, 0, 0)},
      {"RotationAboutAZeroAxis", "vec4(rmRotationAxis(vec3(0.0), 1.0) * vec3(1.0, 2.0, 3.0), 0.0)",
       glm::vec4(1.0f, 2.0f, 3.0f, 0.0f)},
      {"RotationAboutAZeroAxisWithoutAMatrix", "vec4(opRotateAxis(vec3(1.0, 2.0, 3.0), vec3(0.0), 1.0), 0.0)",
       glm::vec4(1.0f, 2.0f, 3.0f, 0.0f)},
      {"TwistAndBendOnTheAxis", "vec4(opTwist(vec3(0.0), 5.0), opBend(vec3(0.0), 5.0).x)", glm::vec4(0.0f)},
      {"SafeNormalizeOfZero", "vec4(rmSafeNormalize(vec3(0.0), vec3(0.0, 1.0, 0.0)), 0.0)",
       glm::vec4(0.0f, 1.0f, 0.0f, 0.0f)},
      {"NormalAtTheSphereCentre", "vec4(rmNormal(vec3(0.0), 1e-3), length(rmNormalCentral(vec3(0.0), 1e-3)))",
       glm::vec4(0.0f, 1.0f, 0.0f, 1.0f)},
      {"RayAlongAFaceOfTheBounds", "march(vec3(-1.0, 0.0, 3.0), vec3(0.0, 0.0, -1.0))"},
      {"RayOnAFaceWithZeroComponents", "march(vec3(1.0, 1.0, 3.0), vec3(0.0, 0.0, -1.0))"},
      {"GroundRayParallelToTheGround", "march(vec3(0.0, 0.0, 3.0), vec3(1.0, 0.0, 0.0))"},
      {"RayBoxOriginOnTheSlab", "vec4(rmRayBox(vec3(1.0, 0.0, 0.0), vec3(0.0, 0.0, 1.0), vec3(-1.0), vec3(1.0)), 0.0, 0.0)"},
      {"GroundDistanceOfAParallelRay", "vec4(rmRayGround(vec3(0.0), vec3(1.0, 0.0, 0.0), 0.0))", glm::vec4(-1.0f)},
      {"CameraLookingStraightDown", "camera(vec3(0.0, 5.0, 0.0), vec3(0.0))"},
      {"CameraLookingAtItself", "camera(vec3(1.0), vec3(1.0))"},
      {"SoftShadowsAtTZero",
       "vec4(rmSoftShadow(vec3(0.0, 1.0, 0.0), vec3(0.0, 1.0, 0.0), 0.0, 5.0, 16.0), "
       "rmSoftShadowImproved(vec3(0.0, 1.0, 0.0), vec3(0.0, 1.0, 0.0), 0.0, 5.0, 16.0), "
       "rmHardShadow(vec3(0.0, 1.0, 0.0), vec3(0.0, 1.0, 0.0), 0.0, 5.0), 0.0)"},
      {"SoftShadowsFromInside",
       "vec4(rmSoftShadow(vec3(0.0), vec3(0.0, 1.0, 0.0), 0.0, 5.0, 16.0), "
       "rmSoftShadowImproved(vec3(0.0), vec3(0.0, 1.0, 0.0), 0.0, 5.0, 16.0), 0.0, 0.0)",
       glm::vec4(0.0f)},
      {"AmbientOcclusionAtTheCentre", "vec4(rmAmbientOcclusion(vec3(0.0), vec3(0.0, 1.0, 0.0)))"},
      {"LightsAtTheShadedPoint",
       "vec4(rmLightRadiance(rmPointLight(vec3(0.0), vec3(1.0)), vec3(0.0)).x, "
       "rmLightRadiance(rmSpotLight(vec3(0.0), vec3(0.0), vec3(1.0), 0.2, 0.1), vec3(0.0)).x, "
       "rmLightDirection(rmPointLight(vec3(0.0), vec3(1.0)), vec3(0.0)).y, 0.0)"},
      {"BlinnPhongLookingAlongTheLight",
       "vec4(rmBlinnPhong(vec3(0.0, 1.0, 0.0), vec3(0.0, -1.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(1.0), "
       "rmMaterial(vec3(0.5))), 0.0)"},
      {"MouseLightBeforeAnyClickAndWithoutResolution",
       "vec4(rmMouseLightDirection(vec4(0.0), vec2(0.0), vec3(0.0)), length(rmMouseLightDirection(vec4(5.0, 5.0, -1.0, 0.0), vec2(0.0), vec3(1.0))))",
       glm::vec4(0.0f, 1.0f, 0.0f, 1.0f)},
      {"ToneMappingOfHugeAndNegative",
       "vec4(rmToneMapACES(vec3(1e30, -1.0, 0.0)).xy, rmToneMapReinhard(vec3(1e30)).x, rmLinearToSrgb(vec3(-1.0)).x)"},
      {"RefractionAtGrazingIncidence", "refracted(vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), 1.5)"},
      {"FresnelAtGrazingExit", "vec4(rmFresnel(normalize(vec3(1.0, 1e-7, 0.0)), vec3(0.0, 1.0, 0.0), 1.5))",
       glm::vec4(1.0f)},
      {"BeerOverNegativeDistance", "vec4(rmBeer(vec3(1.0), -5.0), 0.0)", glm::vec4(1.0f, 1.0f, 1.0f, 0.0f)},
      {"MandelbulbAtTheCentre", "vec4(sdMandelbulb(vec3(0.0), 8.0, 12), sdMandelbulb(vec3(1e-20), 8.0, 64), 0.0, 0.0)"},
      {"MandelbulbDeepIterations", "vec4(sdMandelbulb(vec3(0.5, 0.3, 0.2), 8.0, 200))"},
      {"MengerAtFourteenLevels", "vec4(sdMenger(vec3(0.1, 0.2, 0.3), 14), sdMenger(vec3(0.0), 14), 0.0, 0.0)"},
      {"SierpinskiAtTheCentre", "vec4(sdSierpinski(vec3(0.0), 30))"},
      {"HashOfNegativeZeroAndHugeValues",
       "vec4(rmHash(-0.0) - rmHash(0.0), rmHash(vec3(1e30)), rmValueNoise(vec3(-1e6)), rmFbm(vec3(1e5), 0))"},
  };
}

class Singular : public EglTest, public ::testing::WithParamInterface<Case> {};

TEST_P(Singular, StaysFinite) {
  const Case& c = GetParam();
  std::string error;
  auto got = probe(kPrelude, c.expression, {glm::vec4(0)}, &error);
  ASSERT_TRUE(got) << error;
  const glm::vec4 v = (*got)[0];
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(std::isfinite(v[i])) << c.expression << " component " << i << " = " << v[i];
  if (!std::isnan(c.expected.x)) {
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(v[i], c.expected[i], 1e-5) << c.expression << " component " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(Shaderlib, Singular, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

}  // namespace
}  // namespace rm::test
