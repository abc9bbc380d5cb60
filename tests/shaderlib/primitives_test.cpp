// rm/sdf.glsl, rm/sdf2d.glsl and rm/fractals.glsl: every primitive meets the
// distance class its comment states (see field_contract.h).
#include <gtest/gtest.h>

#include "field_contract.h"
#include "geometry.h"
#include "gpu/egl_fixture.h"

namespace rm::test {
namespace {

using glm::dvec2;
using glm::dvec3;
namespace g = geometry;
using K = DistanceClass;

// (radius from the y axis, height): the profile plane of shapes of revolution.
dvec2 profile(dvec3 p) { return {glm::length(dvec2(p.x, p.z)), p.y}; }

// The square pyramid of sdPyramid(p, h): base half-side 0.5 on y = 0, apex (0, h, 0).
std::vector<std::vector<dvec3>> pyramid_faces(double h) {
  const dvec3 apex(0, h, 0), a(0.5, 0, 0.5), b(-0.5, 0, 0.5), c(-0.5, 0, -0.5), d(0.5, 0, -0.5);
  return {{a, b, c, d}, {a, b, apex}, {b, c, apex}, {c, d, apex}, {d, a, apex}};
}

std::vector<std::vector<dvec3>> octahedron_faces(double s) {
  std::vector<std::vector<dvec3>> faces;
  for (int sx : {-1, 1})
    for (int sy : {-1, 1})
      for (int sz : {-1, 1}) faces.push_back({dvec3(sx * s, 0, 0), dvec3(0, sy * s, 0), dvec3(0, 0, sz * s)});
  return faces;
}

// The 12 bars of sdBoxFrame(p, b, e), as boxes; the frame is their union.
double box_frame(dvec3 p, dvec3 b, double e) {
  double d = std::numeric_limits<double>::max();
  for (int axis = 0; axis < 3; ++axis)
    for (int s1 : {-1, 1})
      for (int s2 : {-1, 1}) {
        dvec3 lo, hi;
        for (int c = 0, n = 0; c < 3; ++c) {
          if (c == axis) {
            lo[c] = -b[c], hi[c] = b[c];
            continue;
          }
          const int s = n++ == 0 ? s1 : s2;
          lo[c] = s > 0 ? b[c] - 2 * e : -b[c];
          hi[c] = s > 0 ? b[c] : -b[c] + 2 * e;
        }
        d = std::min(d, g::box(p, lo, hi));
      }
  return d;
}

std::vector<Field> primitives() {
  const double capped_angle = 1.0, solid_angle = 0.6;
  const auto round_cone = g::hull_of_circles({{dvec2(0, 0), 0.6}, {dvec2(0, 1.0), 0.25}});
  const auto hexagon = g::hexagon(0.8);
  const std::vector<dvec2> rhombus = {{1.0, 0}, {0, 0.6}, {-1.0, 0}, {0, -0.6}};
  return {
      {"Sphere", "sdSphere(p, 1.1)", K::Exact, [](dvec3 p) { return glm::length(p) - 1.1; }},
      {"Box", "sdBox(p, vec3(1.0, 0.5, 0.7))", K::Exact, [](dvec3 p) { return g::box(p, {1.0, 0.5, 0.7}); }},
      {"RoundBox", "sdRoundBox(p, vec3(1.0, 0.5, 0.7), 0.2)", K::Exact,
       [](dvec3 p) { return g::box(p, {0.8, 0.3, 0.5}) - 0.2; }},
      {"BoxFrame", "sdBoxFrame(p, vec3(1.0, 0.8, 0.6), 0.1)", K::ExactOutside,
       [](dvec3 p) { return box_frame(p, {1.0, 0.8, 0.6}, 0.1); }},
      {"Plane", "sdPlane(p, vec3(0.267261, 0.534522, 0.801784), 0.3)", K::Exact,
       [](dvec3 p) { return glm::dot(p, glm::normalize(dvec3(1, 2, 3))) + 0.3; }, 1.0, false},
      {"Torus", "sdTorus(p, vec2(1.0, 0.3))", K::Exact,
       [](dvec3 p) { return glm::length(dvec2(glm::length(dvec2(p.x, p.z)) - 1.0, p.y)) - 0.3; }},
      {"CappedTorus", "sdCappedTorus(p, vec2(sin(1.0), cos(1.0)), 0.9, 0.2)", K::Exact,
       [=](dvec3 p) {
         const double arc = g::arc_distance(dvec2(p.x, p.y), 0.9, {0, 1}, capped_angle);
         return std::sqrt(arc * arc + p.z * p.z) - 0.2;
       }},
      {"Link", "sdLink(p, 0.5, 0.6, 0.15)", K::Exact,
       [](dvec3 p) {
         auto half_circle = [&](double cy, double dir) {
           const double arc = g::arc_distance(dvec2(p.x, p.y - cy), 0.6, {0, dir}, M_PI / 2);
           return std::sqrt(arc * arc + p.z * p.z);
         };
         return std::min({g::segment_distance(p, {0.6, -0.5, 0}, {0.6, 0.5, 0}),
                          g::segment_distance(p, {-0.6, -0.5, 0}, {-0.6, 0.5, 0}), half_circle(0.5, 1),
                          half_circle(-0.5, -1)}) -
                0.15;
       }},
      {"Capsule", "sdCapsule(p, vec3(-0.8, -0.3, 0.2), vec3(0.7, 0.6, -0.4), 0.35)", K::Exact,
       [](dvec3 p) { return g::segment_distance(p, {-0.8, -0.3, 0.2}, {0.7, 0.6, -0.4}) - 0.35; }},
      {"DegenerateCapsule", "sdCapsule(p, vec3(0.2), vec3(0.2), 0.5)", K::Exact,
       [](dvec3 p) { return glm::length(p - dvec3(0.2)) - 0.5; }},
      {"VerticalCapsule", "sdVerticalCapsule(p, 1.0, 0.4)", K::Exact,
       [](dvec3 p) { return g::segment_distance(p, {0, 0, 0}, {0, 1, 0}) - 0.4; }},
      {"InfiniteCylinder", "sdInfiniteCylinder(p, vec3(0.2, -0.1, 0.6))", K::Exact,
       [](dvec3 p) { return glm::length(dvec2(p.x - 0.2, p.z + 0.1)) - 0.6; }, 1.0, false},
      {"CappedCylinder", "sdCappedCylinder(p, 0.7, 1.0)", K::Exact,
       [](dvec3 p) { return g::polygon(profile(p), {{0.7, -1.0}, {0.7, 1.0}, {-0.7, 1.0}, {-0.7, -1.0}}); }},
      {"RoundedCylinder", "sdRoundedCylinder(p, 0.8, 0.9, 0.2)", K::Exact,
       [](dvec3 p) {
         return g::polygon(profile(p), {{0.6, -0.7}, {0.6, 0.7}, {-0.6, 0.7}, {-0.6, -0.7}}) - 0.2;
       }},
      {"CappedCone", "sdCappedCone(p, 0.9, 0.8, 0.3)", K::Exact,
       [](dvec3 p) { return g::polygon(profile(p), {{-0.8, -0.9}, {0.8, -0.9}, {0.3, 0.9}, {-0.3, 0.9}}); }},
      {"RoundCone", "sdRoundCone(p, 0.6, 0.25, 1.0)", K::Exact,
       [=](dvec3 p) { return g::polygon(profile(p), round_cone); }},
      {"SolidAngle", "sdSolidAngle(p, vec2(sin(0.6), cos(0.6)), 1.2)", K::Exact,
       [=](dvec3 p) {
         const dvec2 q = profile(p);
         const dvec2 rim = 1.2 * dvec2(std::sin(solid_angle), std::cos(solid_angle));
         const double d = std::min(g::arc_distance(q, 1.2, {0, 1}, solid_angle), g::segment_distance(q, {0, 0}, rim));
         const bool inside = glm::length(q) < 1.2 && std::atan2(q.x, q.y) < solid_angle;
         return inside ? -d : d;
       }},
      {"CutSphere", "sdCutSphere(p, 1.1, 0.3)", K::Exact,
       [](dvec3 p) {
         const dvec2 q = profile(p);
         const double w = std::sqrt(1.1 * 1.1 - 0.3 * 0.3);
         const double d = std::min(g::arc_distance(q, 1.1, {0, 1}, std::acos(0.3 / 1.1)),
                                   g::segment_distance(q, {-w, 0.3}, {w, 0.3}));
         return glm::length(q) < 1.1 && q.y > 0.3 ? -d : d;
       }},
      {"CutHollowSphere", "sdCutHollowSphere(p, 1.1, 0.5, 0.1)", K::Exact,
       [](dvec3 p) { return g::arc_distance(profile(p), 1.1, {0, -1}, M_PI - std::acos(0.5 / 1.1)) - 0.1; }},
      {"Ellipsoid", "sdEllipsoid(p, vec3(1.2, 0.6, 0.9))", K::Bound},
      {"Octahedron", "sdOctahedron(p, 1.2)", K::Exact,
       [](dvec3 p) { return g::convex_polyhedron(p, octahedron_faces(1.2), dvec3(0)); }},
      {"Pyramid", "sdPyramid(p + vec3(0.0, 0.6, 0.0), 1.3)", K::Exact,
       [](dvec3 p) { return g::convex_polyhedron(p + dvec3(0, 0.6, 0), pyramid_faces(1.3), dvec3(0, 0.3, 0)); }},
      {"HexPrism", "sdHexPrism(p, vec2(0.8, 0.9))", K::Exact,
       [=](dvec3 p) {
         return g::orthogonal_intersection(g::polygon(dvec2(p.x, p.y), hexagon), std::abs(p.z) - 0.9);
       }},
      {"TriPrism", "sdTriPrism(p, vec2(1.0, 0.8))", K::Bound},
      {"Rhombus", "sdRhombus(p, 1.0, 0.6, 0.2, 0.1)", K::Exact,
       [=](dvec3 p) {
         return g::orthogonal_intersection(g::polygon(dvec2(p.x, p.z), rhombus) - 0.1, std::abs(p.y) - 0.2);
       }},
  };
}

std::vector<Field> shapes2d() {
  const double k = std::sqrt(3.0);
  std::vector<Field> fields = {
      {"Circle", "sdCircle(p, 1.1)", K::Exact, [](dvec3 p) { return glm::length(dvec2(p)) - 1.1; }},
      {"Rectangle", "sdBox(p, vec2(1.0, 0.6))", K::Exact,
       [](dvec3 p) { return g::polygon(dvec2(p), {{1, -0.6}, {1, 0.6}, {-1, 0.6}, {-1, -0.6}}); }},
      {"RoundRectangle", "sdRoundBox(p, vec2(1.0, 0.6), 0.25)", K::Exact,
       [](dvec3 p) { return g::polygon(dvec2(p), {{0.75, -0.35}, {0.75, 0.35}, {-0.75, 0.35}, {-0.75, -0.35}}) - 0.25; }},
      {"Segment", "sdSegment(p, vec2(-0.8, -0.2), vec2(0.9, 0.5))", K::Exact,
       [](dvec3 p) { return g::segment_distance(dvec2(p), {-0.8, -0.2}, {0.9, 0.5}); }, 1.0, false},
      {"Hexagon", "sdHexagon(p, 0.9)", K::Exact, [](dvec3 p) { return g::polygon(dvec2(p), g::hexagon(0.9)); }},
      {"EquilateralTriangle", "sdEquilateralTriangle(p, 1.0)", K::Exact,
       [=](dvec3 p) { return g::polygon(dvec2(p), {{-1, -1 / k}, {1, -1 / k}, {0, 2 / k}}); }},
      {"Trapezoid", "sdTrapezoid(p, 1.0, 0.4, 0.7)", K::Exact,
       [](dvec3 p) { return g::polygon(dvec2(p), {{-1, -0.7}, {1, -0.7}, {0.4, 0.7}, {-0.4, 0.7}}); }},
  };
  for (Field& f : fields) {
    f.name = "Shape2d" + f.name;
    f.dims = 2;
  }
  return fields;
}

std::vector<Field> fractals() {
  std::vector<Field> fields = {
      {"Menger4", "sdMenger(p, 4)", K::Bound},
      {"Tetrahedron", "sdTetrahedron(p, 1.0)", K::Bound},
      {"Sierpinski6", "sdSierpinski(p, 6)", K::Bound},
  };
  for (Field& f : fields) f.prelude = "#include <rm/fractals.glsl>";
  return fields;
}

class Primitive : public EglTest, public ::testing::WithParamInterface<Field> {};

TEST_P(Primitive, MeetsItsDistanceContract) { check_contract(GetParam()); }

std::string field_name(const ::testing::TestParamInfo<Field>& info) { return info.param.name; }

INSTANTIATE_TEST_SUITE_P(Sdf, Primitive, ::testing::ValuesIn(primitives()), field_name);
INSTANTIATE_TEST_SUITE_P(Sdf2d, Primitive, ::testing::ValuesIn(shapes2d()), field_name);
INSTANTIATE_TEST_SUITE_P(Fractals, Primitive, ::testing::ValuesIn(fractals()), field_name);

class ProbeHarness : public EglTest {};

TEST_F(ProbeHarness, ReportsABrokenExpression) {
  std::string error;
  EXPECT_FALSE(probe("#include <rm/sdf.glsl>", "vec4(sdNothing(P.xyz))", {glm::vec4(0)}, &error));
  EXPECT_NE(error.find("sdNothing"), std::string::npos);
}

}  // namespace
}  // namespace rm::test
