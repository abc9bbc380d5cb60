// shaderlib's exact primitives agree with a C++ (GLM) reference, evaluated on
// the GPU through the probe harness at thousands of points.
#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "egl_fixture.h"
#include "probe.h"

namespace rm {
namespace {

using glm::vec3;

class Sdf : public test::EglTest {
 protected:
  // Random points in [-3, 3]^3.
  static std::vector<glm::vec4> points(int n) {
    std::mt19937 rng(1234);
    std::uniform_real_distribution<float> u(-3.0f, 3.0f);
    std::vector<glm::vec4> out;
    for (int i = 0; i < n; ++i) out.emplace_back(u(rng), u(rng), u(rng), 0.0f);
    return out;
  }

  void expect_matches(const std::string& glsl, const std::function<double(glm::dvec3)>& reference) {
    const auto ps = points(4096);
    std::string error;
    auto got = test::probe("#include <rm/sdf.glsl>", "vec4(" + glsl + ", 0.0, 0.0, 0.0)", ps, &error);
    ASSERT_TRUE(got) << error;
    double worst = 0.0;
    for (size_t i = 0; i < ps.size(); ++i) {
      const double want = reference(glm::dvec3(ps[i]));
      const double err = std::abs((*got)[i].x - want) / std::max(1.0, std::abs(want));
      worst = std::max(worst, err);
    }
    EXPECT_LT(worst, 1e-5) << glsl;
  }
};

TEST_F(Sdf, SphereIsExact) {
  expect_matches("sdSphere(P.xyz, 1.3)", [](glm::dvec3 p) { return glm::length(p) - 1.3; });
}

TEST_F(Sdf, BoxIsExact) {
  expect_matches("sdBox(P.xyz, vec3(1.0, 0.5, 2.0))", [](glm::dvec3 p) {
    const glm::dvec3 q = glm::abs(p) - glm::dvec3(1.0, 0.5, 2.0);
    return glm::length(glm::max(q, 0.0)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0);
  });
}

TEST_F(Sdf, PlaneIsExact) {
  expect_matches("sdPlane(P.xyz, vec3(0.0, 1.0, 0.0), 0.5)", [](glm::dvec3 p) { return p.y + 0.5; });
}

TEST_F(Sdf, TorusIsExact) {
  expect_matches("sdTorus(P.xyz, vec2(1.5, 0.4))", [](glm::dvec3 p) {
    return glm::length(glm::dvec2(glm::length(glm::dvec2(p.x, p.z)) - 1.5, p.y)) - 0.4;
  });
}

TEST_F(Sdf, CapsuleIsExact) {
  expect_matches("sdCapsule(P.xyz, vec3(-1.0, 0.0, 0.0), vec3(1.0, 1.0, 0.5), 0.3)", [](glm::dvec3 p) {
    const glm::dvec3 a(-1, 0, 0), b(1, 1, 0.5), pa = p - a, ba = b - a;
    const double h = glm::clamp(glm::dot(pa, ba) / glm::dot(ba, ba), 0.0, 1.0);
    return glm::length(pa - ba * h) - 0.3;
  });
}

TEST_F(Sdf, ProbeReportsABrokenExpression) {
  std::string error;
  EXPECT_FALSE(test::probe("#include <rm/sdf.glsl>", "vec4(sdNothing(P.xyz))", points(4), &error));
  EXPECT_NE(error.find("sdNothing"), std::string::npos);
}

}  // namespace
}  // namespace rm
