// rm/ops.glsl and rm/transforms.glsl keep the distance class their comments
// state (see field_contract.h); repetition stays exact far from the origin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "field_contract.h"
#include "geometry.h"
#include "gpu/egl_fixture.h"

namespace rm::test {
namespace {

using glm::dvec2;
using glm::dvec3;
namespace g = geometry;
using K = DistanceClass;

const std::string kPrelude = R"(#include <rm/sdf.glsl>
#include <rm/ops.glsl>
#include <rm/transforms.glsl>
float A(vec3 p) { return sdSphere(p - vec3(0.4, 0.0, 0.0), 0.8); }
float B(vec3 p) { return sdBox(p + vec3(0.3, 0.0, 0.0), vec3(0.6, 0.5, 0.9)); }
float polar(vec3 p) {
  float cell;
  vec2 q = opRepeatPolar(p.xz, 6.0, cell);
  return sdBox(vec3(q.x - 1.0, p.y, q.y), vec3(0.25));
}
float polarMirror(vec3 p) {
  vec2 q = opRepeatPolarMirror(p.xz, 8);
  return sdBox(vec3(q.x - 1.0, p.y, q.y), vec3(0.25, 0.3, 0.15));
}
float grid(vec3 p) {
  vec3 cell;
  return sdSphere(opRepeat(p, vec3(1.0), cell), 0.3);
}
float limited(vec3 p) {
  vec3 cell;
  return sdBox(opRepeatLimited(p, vec3(0.8), vec3(-1.0), vec3(1.0), cell), vec3(0.2));
}
)";

double ref_a(dvec3 p) { return glm::length(p - dvec3(0.4, 0, 0)) - 0.8; }
double ref_b(dvec3 p) { return g::box(p + dvec3(0.3, 0, 0), {0.6, 0.5, 0.9}); }

// Rotation matrix as glm builds it (right-handed, angle in radians).
glm::dmat3 rotation(double angle, dvec3 axis) { return glm::dmat3(glm::rotate(glm::dmat4(1.0), angle, axis)); }

std::vector<Field> fields() {
  const double twist_l = 0.5 * (1.2 * 1.6 * std::sqrt(2.0) + std::sqrt(std::pow(1.2 * 1.6 * std::sqrt(2.0), 2) + 4));
  const double bend_l = 1.0 + 0.8 * 1.6 * std::sqrt(2.0);
  const auto hexagon = g::hexagon(0.8);
  std::vector<Field> list = {
      {"Union", "opUnion(A(p), B(p))", K::ExactOutside, [](dvec3 p) { return std::min(ref_a(p), ref_b(p)); }},
      {"Intersection", "opIntersection(A(p), B(p))", K::Bound},
      {"Subtraction", "opSubtraction(A(p), B(p))", K::Bound},
      {"SmoothUnion", "opSmoothUnion(A(p), B(p), 0.3)", K::Bound},
      {"SmoothUnionWithZeroK", "opSmoothUnion(A(p), B(p), 0.0)", K::ExactOutside,
       [](dvec3 p) { return std::min(ref_a(p), ref_b(p)); }},
      {"SmoothIntersection", "opSmoothIntersection(A(p), B(p), 0.3)", K::Bound},
      {"SmoothSubtraction", "opSmoothSubtraction(A(p), B(p), 0.3)", K::Bound},
      {"HitSmoothUnion", "opSmoothUnion(rmHit(A(p), 1.0), rmHit(B(p), 2.0), 0.3).d", K::Bound},
      {"ChamferUnion", "opChamferUnion(A(p), B(p), 0.2)", K::Approximate, nullptr, std::sqrt(2.0)},
      {"ChamferIntersection", "opChamferIntersection(A(p), B(p), 0.2)", K::Approximate, nullptr, std::sqrt(2.0)},
      {"ChamferSubtraction", "opChamferSubtraction(A(p), B(p), 0.2)", K::Approximate, nullptr, std::sqrt(2.0)},
      {"RoundUnion", "opRoundUnion(A(p), B(p), 0.2)", K::Approximate, nullptr, std::sqrt(2.0)},
      {"RoundIntersection", "opRoundIntersection(A(p), B(p), 0.2)", K::Approximate, nullptr, std::sqrt(2.0)},
      {"RoundSubtraction", "opRoundSubtraction(A(p), B(p), 0.2)", K::Approximate, nullptr, std::sqrt(2.0)},
      {"TranslateRotateAxis",
       "sdBox(opRotate(opTranslate(p, vec3(0.2, -0.1, 0.3)), rmRotationAxis(vec3(1.0, 2.0, 3.0), 0.7)), "
       "vec3(0.6, 0.4, 0.8))",
       K::Exact,
       [](dvec3 p) {
         return g::box(glm::transpose(rotation(0.7, glm::normalize(dvec3(1, 2, 3)))) * (p - dvec3(0.2, -0.1, 0.3)),
                       {0.6, 0.4, 0.8});
       }},
      {"RotateAxisWithoutAMatrix", "sdBox(opRotateAxis(p, vec3(1.0, 2.0, 3.0), 0.7), vec3(0.6, 0.4, 0.8))", K::Exact,
       [](dvec3 p) { return g::box(glm::transpose(rotation(0.7, glm::normalize(dvec3(1, 2, 3)))) * p, {0.6, 0.4, 0.8}); }},
      {"RotateXYZ", "sdBox(opRotate(p, rmRotationX(0.3) * rmRotationY(0.5) * rmRotationZ(0.7)), vec3(0.9, 0.4, 0.6))",
       K::Exact,
       [](dvec3 p) {
         const glm::dmat3 r = rotation(0.3, {1, 0, 0}) * rotation(0.5, {0, 1, 0}) * rotation(0.7, {0, 0, 1});
         return g::box(glm::transpose(r) * p, {0.9, 0.4, 0.6});
       }},
      {"Scale", "opScaleDistance(sdBox(opScale(p, 1.5), vec3(0.6, 0.4, 0.5)), 1.5)", K::Exact,
       [](dvec3 p) { return g::box(p, {0.9, 0.6, 0.75}); }},
      {"Mirror", "sdSphere(opMirror(p, vec3(0.70710678, 0.70710678, 0.0)) - vec3(0.5, 0.5, 0.0), 0.4)", K::Exact,
       [](dvec3 p) { return std::min(glm::length(p - dvec3(0.5, 0.5, 0)), glm::length(p + dvec3(0.5, 0.5, 0))) - 0.4; }},
      {"SymmetryXZ", "sdBox(opSymmetryXZ(p) - vec3(0.7, 0.0, 0.7), vec3(0.3))", K::Exact,
       [](dvec3 p) {
         double d = 1e9;
         for (double sx : {-1.0, 1.0})
           for (double sz : {-1.0, 1.0}) d = std::min(d, g::box(p - dvec3(0.7 * sx, 0, 0.7 * sz), dvec3(0.3)));
         return d;
       }},
      {"RepeatPolar", "polar(p)", K::Exact,
       [](dvec3 p) {
         double d = 1e9;
         for (int i = 0; i < 6; ++i) {
           const glm::dmat3 r = rotation(-2.0 * M_PI * i / 6.0, {0, 1, 0});  // copy i at angle i * 60 deg in xz
           d = std::min(d, g::box(glm::transpose(r) * p - dvec3(1.0, 0, 0), dvec3(0.25)));
         }
         return d;
       }},
      {"RepeatPolarMirror", "polarMirror(p)", K::Exact,  // folds by mirrors, copies as opRepeatPolar places them
       [](dvec3 p) {
         double d = 1e9;
         for (int i = 0; i < 8; ++i) {
           const glm::dmat3 r = rotation(-2.0 * M_PI * i / 8.0, {0, 1, 0});
           d = std::min(d, g::box(glm::transpose(r) * p - dvec3(1.0, 0, 0), dvec3(0.25, 0.3, 0.15)));
         }
         return d;
       }},
      {"Repeat", "grid(p)", K::Exact,
       [](dvec3 p) { return glm::length(p - glm::round(p)) - 0.3; }, 1.0, false},
      {"RepeatLimited", "limited(p)", K::Exact,
       [](dvec3 p) {
         double d = 1e9;
         for (int i = -1; i <= 1; ++i)
           for (int j = -1; j <= 1; ++j)
             for (int k = -1; k <= 1; ++k) d = std::min(d, g::box(p - 0.8 * dvec3(i, j, k), dvec3(0.2)));
         return d;
       }},
      // L for the sampled region: the farthest point from the axis is extent * sqrt(2) away.
      {"Twist", "sdBox(opTwist(p, 1.2), vec3(0.5, 1.0, 0.3))", K::Approximate, nullptr, twist_l},
      // Samples reach |1.2 y| = 1.92: beyond a quarter turn, where the turn holds.
      {"TwistQuarter", "sdBox(opTwistQuarter(p, 1.2), vec3(0.5, 1.0, 0.3))", K::Approximate, nullptr, twist_l},
      {"Bend", "sdBox(opBend(p, 0.8), vec3(1.0, 0.2, 0.4))", K::Approximate, nullptr, bend_l},
      {"Elongate", "sdSphere(opElongate(p, vec3(0.5, 0.2, 0.3)), 0.4)", K::ExactOutside,
       [](dvec3 p) { return g::box(p, {0.5, 0.2, 0.3}) - 0.4; }},
      {"Round", "opRound(sdBox(p, vec3(0.6, 0.4, 0.5)), 0.2)", K::ExactOutside,
       [](dvec3 p) { return g::box(p, {0.6, 0.4, 0.5}) - 0.2; }},
      {"Onion", "opOnion(sdSphere(p, 1.0), 0.1)", K::Exact, [](dvec3 p) { return std::abs(glm::length(p) - 1.0) - 0.1; }},
      {"Extrude", "opExtrude(p, sdHexagon(p.xy, 0.8), 0.5)", K::Exact,
       [=](dvec3 p) { return g::orthogonal_intersection(g::polygon(dvec2(p.x, p.y), hexagon), std::abs(p.z) - 0.5); }},
      {"Revolve", "sdCircle(opRevolve(p, 0.9), 0.3)", K::Exact,
       [](dvec3 p) { return glm::length(dvec2(glm::length(dvec2(p.x, p.z)) - 0.9, p.y)) - 0.3; }},
  };
  for (Field& f : list) f.prelude = kPrelude;
  return list;
}

class Operator : public EglTest, public ::testing::WithParamInterface<Field> {};

TEST_P(Operator, KeepsItsDistanceContract) { check_contract(GetParam()); }

INSTANTIATE_TEST_SUITE_P(OpsAndTransforms, Operator, ::testing::ValuesIn(fields()),
                         [](const ::testing::TestParamInfo<Field>& info) { return info.param.name; });

// opTwistLipschitz and opBendLipschitz give the constants the tests above use.
TEST_F(EglTest, TwistAndBendConstantsMatchTheirFormulas) {
  std::string error;
  auto got = probe("#include <rm/transforms.glsl>", "vec4(opTwistLipschitz(1.2, 2.0), opBendLipschitz(0.8, 2.0), 0.0, 0.0)",
                   {glm::vec4(0)}, &error);
  ASSERT_TRUE(got) << error;
  EXPECT_NEAR((*got)[0].x, 0.5 * (2.4 + std::sqrt(2.4 * 2.4 + 4.0)), 1e-5);
  EXPECT_NEAR((*got)[0].y, 2.6, 1e-5);
}

// rmSinCosQuarter is sin and cos within 4e-6 up to a quarter turn and holds
// there beyond; so opTwistQuarter is opTwist up to a quarter turn, and beyond
// turns by a quarter turn.
TEST_F(EglTest, QuarterTurnPolynomialsMatchSinAndCos) {
  std::vector<glm::vec4> points;
  for (int i = 0; i <= 2000; ++i) {
    const float a = -2.5f + 5.0f * static_cast<float>(i) / 2000.0f;
    points.emplace_back(a, 0.0f, 0.0f, 0.0f);
  }
  std::string error;
  // The point (1.5, y, -0.7) with 0.8 y = a: twisted by a.
  const auto got = probe("#include <rm/transforms.glsl>",
                         "vec4(rmSinCosQuarter(P.x), opTwistQuarter(vec3(1.5, P.x / 0.8, -0.7), 0.8).xz)", points, &error);
  ASSERT_TRUE(got) << error;
  const auto twist = probe("#include <rm/transforms.glsl>",
                           "vec4(opTwist(vec3(1.5, P.x / 0.8, -0.7), 0.8).xz, 0.0, 0.0)", points, &error);
  ASSERT_TRUE(twist) << error;
  for (size_t i = 0; i < points.size(); ++i) {
    const double a = points[i].x;
    const double held = std::clamp(a, -M_PI / 2.0, M_PI / 2.0);
    const glm::vec4 r = (*got)[i];
    EXPECT_NEAR(r.x, std::sin(held), 4e-6) << "sin at " << a;
    EXPECT_NEAR(r.y, std::cos(held), 4e-6) << "cos at " << a;
    // The xz plane turned by `held`, as rmRotation2 turns it.
    EXPECT_NEAR(r.z, std::cos(held) * 1.5 - std::sin(held) * -0.7, 1e-5) << "twisted x at " << a;
    EXPECT_NEAR(r.w, std::sin(held) * 1.5 + std::cos(held) * -0.7, 1e-5) << "twisted z at " << a;
    if (std::abs(a) <= M_PI / 2.0) {
      EXPECT_NEAR(r.z, (*twist)[i].x, 1e-5) << "opTwist's x at " << a;
      EXPECT_NEAR(r.w, (*twist)[i].y, 1e-5) << "opTwist's z at " << a;
    }
  }
}

class Repetition : public EglTest {};

// Far from the origin the local coordinate is as exact as the input allows
// (one float step of |x|) and the cell id is right, unlike mod(). GLSL lets
// p / period be off by 2.5 ulps and leaves round()'s ties open, so near a cell
// border either neighbour is a right cell; whichever is chosen, the local
// coordinate must be exact for it.
TEST_F(Repetition, StaysExactFarFromTheOrigin) {
  const float period = 0.37f;
  for (double magnitude : {1e4, 1e5}) {
    std::vector<glm::vec4> xs;
    for (int i = 0; i < 4096; ++i) {
      const float x = static_cast<float>((i % 2 ? -1 : 1) * (magnitude + i * 0.0123));
      xs.emplace_back(x, 0.0f, 0.0f, 0.0f);
    }
    const auto got = [&] {
      std::string error;
      auto r = probe("#include <rm/transforms.glsl>\nvec3 cell;",
                     "vec4(opRepeat(P.xyz, vec3(0.37), cell).x, cell.x, 0.0, 0.0)", xs, &error);
      EXPECT_TRUE(r) << error;
      return r.value_or(std::vector<glm::vec4>(xs.size(), glm::vec4(NAN)));
    }();
    auto float_step = [](double v) {
      const float f = static_cast<float>(std::abs(v));
      return static_cast<double>(std::nextafter(f, INFINITY) - f);
    };
    const double ulp = float_step(magnitude);
    const double tie_zone = 3.0 * float_step(magnitude / period) * period + ulp;  // 2.5 ulps of the quotient, rounded up
    double worst = 0;
    int wrong_cells = 0, ties = 0;
    for (size_t i = 0; i < xs.size(); ++i) {
      const double x = xs[i].x;
      const double cell = std::round(x / static_cast<double>(period));
      const double offset = x - period * cell;  // from the cell's centre
      const bool near_tie = std::abs(std::abs(offset) - period / 2.0) < tie_zone;
      const double neighbour = cell + (offset > 0 ? 1.0 : -1.0);
      ties += near_tie;
      const bool right_cell = got[i].y == cell || (near_tie && got[i].y == neighbour);
      if (!right_cell) {
        if (++wrong_cells <= 3) ADD_FAILURE() << "x = " << x << ": cell " << got[i].y << ", want " << cell;
        continue;
      }
      const double local = x - static_cast<double>(period) * got[i].y;
      if (!(std::abs(got[i].x - local) <= worst)) worst = std::abs(got[i].x - local);  // NaN makes worst NaN
    }
    std::printf("[repetition] |x| = %g: local error %.3g float steps, %d wrong cells, %d near a tie\n", magnitude,
                worst / ulp, wrong_cells, ties);
    EXPECT_EQ(wrong_cells, 0) << "at |x| = " << magnitude;
    EXPECT_LE(worst, ulp) << "at |x| = " << magnitude;
  }
}

// Instances turned by their cell's hash are not symmetric in their cells: a
// neighbour's corner can be nearer than the own instance, so the repeated
// field overestimates. opRepeatBorder plus the gap every instance leaves (half
// the period minus the half-diagonal) restores the bound.
TEST_F(Repetition, BorderTermKeepsTurnedInstancesABound) {
  const std::string prelude = R"(#include <rm/sdf.glsl>
#include <rm/transforms.glsl>
float turned(vec3 p, bool border) {
  vec3 cell;
  vec3 q = opRepeat(p, vec3(1.0), cell);
  float d = sdBox(opRotate(q, rmRotationAxis(cell + vec3(0.3, 0.7, 0.1), 0.8 + cell.x)), vec3(0.28, 0.12, 0.12));
  return border ? min(d, opRepeatBorder(q, vec3(1.0)) + 0.5 - 0.329) : d;  // half-diagonal 0.329
}
)";
  Field without{"Turned", "turned(p, false)", DistanceClass::Bound, nullptr, 1.0, false};
  Field with_border{"TurnedWithBorder", "turned(p, true)", DistanceClass::Bound, nullptr, 1.0, false};
  without.prelude = with_border.prelude = prelude;
  std::string error;
  const ContractReport bare = measure_contract(without, &error);
  ASSERT_TRUE(error.empty()) << error;
  const ContractReport bounded = measure_contract(with_border, &error);
  ASSERT_TRUE(error.empty()) << error;
  EXPECT_GT(bare.worst_excess, 0.01) << "the scene should show the problem";
  EXPECT_LT(bounded.worst_excess, 2e-5);
}

// Exactly on a cell boundary the point is half a period from either centre.
TEST_F(Repetition, IsExactAtCellBoundaries) {
  std::vector<glm::vec4> xs;
  for (int k = -2000; k < 2000; ++k) xs.emplace_back(0.25f + 0.5f * k, 0.0f, 0.0f, 0.0f);
  for (float x : {10000.25f, -10000.25f, 99999.75f}) xs.emplace_back(x, 0.0f, 0.0f, 0.0f);
  std::string error;
  auto got = probe("#include <rm/transforms.glsl>\nvec3 cell;",
                   "vec4(opRepeat(P.xyz, vec3(0.5), cell).x, cell.x, 0.0, 0.0)", xs, &error);
  ASSERT_TRUE(got) << error;
  for (size_t i = 0; i < xs.size(); ++i) {
    ASSERT_EQ(std::abs((*got)[i].x), 0.25f) << "x = " << xs[i].x;
    ASSERT_EQ((*got)[i].y * 0.5f + (*got)[i].x, xs[i].x) << "x = " << xs[i].x;
  }
}

}  // namespace
}  // namespace rm::test
