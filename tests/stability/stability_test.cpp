// Hard cases stay numerically stable (docs/stability.md). Each test renders a
// probe on llvmpipe, reads the GLSL results back as floats and asserts no
// NaN/Inf, an error bound against an analytic or double-precision answer, and
// no ray out of steps where the geometry says it should not be. Each prints
// its measured worst error as "[stability] CASE: worst W (bound B)".
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "core/data_paths.h"
#include "gpu/egl_fixture.h"
#include "gpu/probe.h"
#include "shaderlib/field_contract.h"
#include "shaderlib/march_probe.h"

namespace rm::test {
namespace {

using glm::dvec3;
using glm::vec4;

void report(const char* name, double worst, double bound) {
  std::printf("[stability] %s: worst %.3g (bound %.3g)\n", name, worst, bound);
  EXPECT_LE(worst, bound) << name;
}

bool finite(const vec4& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w); }

std::vector<vec4> run(const std::string& prelude, const std::string& expression, const std::vector<vec4>& p,
                      const std::vector<vec4>& q = {}) {
  std::string error;
  auto got = probe(prelude, expression, p, &error, q);
  EXPECT_TRUE(got) << error;
  auto out = got.value_or(std::vector<vec4>(p.size(), vec4(NAN)));
  for (size_t i = 0; i < out.size(); ++i) EXPECT_TRUE(finite(out[i])) << expression << " at sample " << i;
  return out;
}

class Stability : public EglTest {};

// 1. Grazing rays against the analytic ground: exact t down to 1e-4 rad, and
// rd.y == 0 is a clean miss with and without ro.y == 0.
TEST_F(Stability, GrazingRaysOnTheAnalyticGround) {
  std::vector<vec4> ro, rd;
  std::vector<double> want;
  for (double height : {0.0, 1e-3, 0.5}) {
    for (double angle : {0.0, 1e-4, 1e-3, 1e-2, 0.1, 0.5}) {
      ro.emplace_back(0.0f, static_cast<float>(height), 0.0f, 0.0f);
      const glm::vec3 d = glm::normalize(glm::vec3(std::cos(angle), -std::sin(angle), 0.0));
      rd.emplace_back(d, 0.0f);
      want.push_back(angle > 0 && d.y < 0 ? height / -static_cast<double>(d.y) : -1.0);
    }
  }
  const auto got = run(march_prelude("sdSphere(p - vec3(0.0, 50.0, 0.0), 1.0)",
                               "s.ground = true; s.groundHeight = 0.0; s.tMax = 1e6;"),
                       "trace(P.xyz, Q.xyz)", ro, rd);
  double worst = 0;
  for (size_t i = 0; i < got.size(); ++i) {
    const int outcome = decode_trace(got[i]).outcome;
    if (want[i] < 0 || want[i] > 1e6) {
      EXPECT_NE(outcome, kHit) << "ray " << i << " parallel to the ground hit it";
      continue;
    }
    ASSERT_EQ(outcome, kHit) << "ray " << i;
    worst = std::max(worst, std::abs(got[i].x - want[i]) / std::max(1.0, want[i]));
  }
  report("grazing rays, analytic ground (relative t error)", worst, 1e-5);
}

// 1. Grazing rays against a plane inside map() and rays along a sphere's
// silhouette, with the default budget (160 steps) and a pixel cone of 1e-3:
// down to 0.03 rad the pixel cone ends the march in budget at the right t
// (below that, use the analytic ground above); rays that pass a silhouette
// farther than twice the hit tolerance get the right hit or miss.
TEST_F(Stability, GrazingRaysAndSilhouettesEndInBudget) {
  std::vector<vec4> ro, rd;
  std::vector<double> want;
  for (double angle : {0.03, 0.05, 0.1, 0.3, 0.5}) {
    ro.emplace_back(0.0f, 0.5f, 0.0f, 0.0f);
    const glm::vec3 d = glm::normalize(glm::vec3(std::cos(angle), -std::sin(angle), 0.0));
    rd.emplace_back(d, 0.0f);
    want.push_back(0.5 / -static_cast<double>(d.y));
  }
  const auto plane = run(march_prelude("p.y", ""), "trace(P.xyz, Q.xyz)", ro, rd);
  double worst = 0;
  for (size_t i = 0; i < plane.size(); ++i) {
    ASSERT_EQ(decode_trace(plane[i]).outcome, kHit) << "grazing ray " << i << " did not end in budget";
    const double sin_angle = -static_cast<double>(rd[i].y);
    worst = std::max(worst, std::abs(plane[i].x - want[i]) * sin_angle / plane[i].w);
  }
  report("grazing rays on a plane in map(): t error / (tolerance / sin angle)", worst, 1.0);

  // Past a unit sphere 5 away, at distances from its centre of 1 +- delta.
  std::vector<vec4> sro, srd;
  std::vector<bool> hits;
  for (double delta : {-0.1, -0.03, -0.015, 0.015, 0.03, 0.1}) {
    for (int k = 0; k < 16; ++k) {
      const double a = 2.0 * M_PI * k / 16.0;
      const double r = 1.0 + delta;
      sro.emplace_back(static_cast<float>(r * std::cos(a)), static_cast<float>(r * std::sin(a)), 5.0f, 0.0f);
      srd.emplace_back(0.0f, 0.0f, -1.0f, 0.0f);
      hits.push_back(delta < 0);
    }
  }
  const auto sphere = run(march_prelude("sdSphere(p, 1.0)", ""), "trace(P.xyz, Q.xyz)", sro, srd);
  size_t wrong = 0;
  for (size_t i = 0; i < sphere.size(); ++i) {
    const int outcome = decode_trace(sphere[i]).outcome;
    if (outcome == kOutOfSteps || (outcome == kHit) != hits[i]) ++wrong;
  }
  report("rays past a silhouette (more than twice the tolerance): wrong or out of steps", double(wrong), 0);
}

// 2. Box and slab entry with a zero direction component, origin on the slab.
TEST_F(Stability, SlabEntryWithAZeroComponent) {
  std::vector<vec4> ro = {{1, 0, 3, 0}, {-1, 0.5, 3, 0}, {1, 1, 3, 0}, {0.5, 0.5, 3, 0}, {2, 0, 3, 0}};
  std::vector<vec4> rd(ro.size(), vec4(0, 0, -1, 0));
  const auto got = run("#include <rm/march.glsl>\nfloat map(vec3 p) { return length(p) - 0.5; }\n",
                       "vec4(rmRayBox(P.xyz, Q.xyz, vec3(-1.0), vec3(1.0)), 0.0, 0.0)", ro, rd);
  // On either face plane (closed slabs): entered, with the exact slab distances.
  double worst = 0;
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_LE(got[i].x, got[i].y) << "ray " << i << " should enter the box";
    worst = std::max({worst, std::abs(got[i].x - 2.0), std::abs(got[i].y - 4.0)});
  }
  EXPECT_GT(got[4].x, got[4].y) << "outside the slab and parallel: a miss";
  report("slab entry with the origin on a face: entry/exit distance error", worst, 1e-6);
}

// 3. Secondary rays do not hit their own surface. A unit sphere rests on the
// plane y = 0 under a light from (0.5, 1, 0.3); camera rays from near (5) and
// far (50) hit the sphere's lit side and the floor. From each marched hit
// point (up to the hit tolerance off the surface) the shadow ray, AO and a
// reflection start at rmSurfaceOffset: lit points see the light (no acne),
// the open floor is unoccluded, reflections leave the surface, and the
// shadow's edge on the floor agrees with the analytic one except within a
// pixel's footprint of it.
TEST_F(Stability, SecondaryRaysDoNotHitTheirOwnSurface) {
  const std::string prelude = R"(#include <rm/march.glsl>
#include <rm/normals.glsl>
#include <rm/lighting.glsl>
float map(vec3 p) { return min(length(p - vec3(0.0, 1.0, 0.0)) - 1.0, p.y); }
const vec3 kLight = normalize(vec3(0.5, 1.0, 0.3));
int surfaceAt(vec3 q) { return abs(length(q - vec3(0.0, 1.0, 0.0)) - 1.0) < abs(q.y) ? 1 : 2; }
// (hard shadow, soft shadow, AO, reflection leaves: 1) at the hit of a camera ray
vec4 secondary(vec3 ro, vec3 rd, float cone) {
  RmMarchSettings s = rmMarchSettings();
  s.cone = cone;
  s.maxSteps = 400;
  RmMarch m = rmMarch(ro, rd, s);
  if (m.outcome != RM_HIT) return vec4(-1.0);
  vec3 p = ro + rd * m.t;
  vec3 n = rmNormal(p, m.tolerance);
  float offset = rmSurfaceOffset(p, m.tolerance);
  vec3 from = p + n * offset;
  float hard = rmHardShadow(from, kLight, offset, 50.0);
  float soft = rmSoftShadowImproved(from, kLight, offset, 50.0, 16.0);
  float ao = rmAmbientOcclusion(p, n);
  RmMarchSettings r = s;
  r.tMin = offset;
  vec3 bounceDir = reflect(rd, n);
  RmMarch bounce = rmMarch(from, bounceDir, r);
  // The sphere and the floor are convex and flat: a reflection can never meet
  // the surface it left again. 0 marks one that did.
  bool same = bounce.outcome == RM_HIT && surfaceAt(from + bounceDir * bounce.t) == surfaceAt(p);
  return vec4(hard, soft, ao, same ? 0.0 : 1.0);
}
)";
  const dvec3 light = glm::normalize(dvec3(0.5, 1.0, 0.3));
  auto analytic_shadow = [&](dvec3 x) {  // the ray x + s light meets the sphere
    const dvec3 oc = x - dvec3(0, 1, 0);
    const double b = glm::dot(oc, light), h = b * b - (glm::dot(oc, oc) - 1.0);
    return h > 0 && -b + std::sqrt(h) > 0;
  };
  for (double distance : {5.0, 50.0}) {
    const double cone = 1.0 / 360.0;  // half a pixel of a 720-pixel-high view with a 90 degree field
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<vec4> ro, rd;
    std::vector<dvec3> aims;
    const dvec3 eye = dvec3(0.3, 0.6, 1.0) * distance / glm::length(dvec3(0.3, 0.6, 1.0)) + dvec3(0, 1, 0);
    for (int i = 0; i < 4096; ++i) {
      const dvec3 aim = i % 2 ? dvec3(0, 1, 0) + 1.2 * dvec3(u(rng), u(rng), u(rng))   // the sphere
                              : dvec3(3.0 * u(rng), 0.0, 3.0 * u(rng));               // the floor and the shadow
      ro.emplace_back(glm::vec3(eye), static_cast<float>(cone));
      rd.emplace_back(glm::normalize(glm::vec3(aim - eye)), 0.0f);
      aims.push_back(aim);
    }
    const auto got = run(prelude, "secondary(P.xyz, Q.xyz, P.w)", ro, rd);
    size_t acne = 0, occluded_floor = 0, stuck = 0, edge_wrong = 0;
    for (size_t i = 0; i < ro.size(); ++i) {
      if (got[i].x < 0) continue;  // the ray missed
      const dvec3 o(glm::vec3(ro[i])), d(glm::vec3(rd[i]));
      // The hit point, analytically: the sphere or the floor, whichever is first.
      const dvec3 oc = o - dvec3(0, 1, 0);
      const double b = glm::dot(oc, d), h = b * b - (glm::dot(oc, oc) - 1.0);
      const double t_sphere = h > 0 ? -b - std::sqrt(h) : 1e30, t_floor = d.y < 0 ? -o.y / d.y : 1e30;
      const bool on_sphere = t_sphere < t_floor;
      const double t = std::min(t_sphere, t_floor);
      const dvec3 x = o + t * d;
      const dvec3 n = on_sphere ? glm::normalize(x - dvec3(0, 1, 0)) : dvec3(0, 1, 0);
      const double footprint = 2.0 * cone * t;
      // Rays that pass within a footprint of the sphere's silhouette hit it by
      // design (the pixel cone): those pixels are the silhouette, not the floor.
      const double closest = glm::length(glm::cross(d, dvec3(0, 1, 0) - o));
      if (!on_sphere && closest < 1.0 + 2.0 * footprint) continue;
      if (got[i].w < 1.0f) ++stuck;
      if (on_sphere && glm::dot(n, light) > 0.2 && got[i].x < 1.0f) ++acne;
      if (!on_sphere) {
        const double to_sphere = std::abs(glm::length(x - dvec3(0, 1, 0)) - 1.0);
        if (to_sphere > 1.5 && got[i].z < 0.999f) ++occluded_floor;
        // The shadow's edge: compare with the analytic shadow a footprint away on either side.
        const bool a = analytic_shadow(x), near_edge = analytic_shadow(x + dvec3(footprint, 0, 0)) != a ||
                                                       analytic_shadow(x - dvec3(footprint, 0, 0)) != a ||
                                                       analytic_shadow(x + dvec3(0, 0, footprint)) != a ||
                                                       analytic_shadow(x - dvec3(0, 0, footprint)) != a;
        if (!near_edge && (got[i].x < 0.5f) != a) ++edge_wrong;
      }
    }
    const std::string at = distance == 5.0 ? "near (5)" : "far (50)";
    report(("self-intersection " + at + ": lit sphere points in their own shadow").c_str(), double(acne), 0);
    report(("self-intersection " + at + ": open floor points occluded by AO").c_str(), double(occluded_floor), 0);
    report(("self-intersection " + at + ": reflections that hit their own surface").c_str(), double(stuck), 0);
    report(("self-intersection " + at + ": floor points shadowed wrongly beyond a pixel of the edge").c_str(),
           double(edge_wrong), 0);
  }
}

// 4. Far from the origin: a unit sphere at distance 1e3 and 1e4 from the
// origin, the camera 5 units from it: hit distance within the tolerance plus a
// few float steps of the magnitude, unit normals within a stated angle.
TEST_F(Stability, FarFromTheOrigin) {
  for (double far : {1e3, 1e4}) {
    const dvec3 centre(far, 0.5 * far, -0.25 * far);
    std::mt19937 rng(4);
    std::normal_distribution<double> normal;
    std::vector<vec4> ro, rd;
    std::vector<dvec3> hits;
    for (int i = 0; i < 512; ++i) {
      const dvec3 eye = centre + dvec3(0, 0, 5);
      const dvec3 aim = centre + 0.7 * dvec3(normal(rng), normal(rng), 0.0) * 0.5;
      const glm::vec3 d = glm::normalize(glm::vec3(aim - eye));
      ro.emplace_back(glm::vec3(eye), 0.0f);
      rd.emplace_back(d, 0.0f);
    }
    char centre_glsl[128];
    std::snprintf(centre_glsl, sizeof centre_glsl, "vec3(%.1f, %.1f, %.1f)", centre.x, centre.y, centre.z);
    const std::string prelude = march_prelude(std::string("sdSphere(p - ") + centre_glsl + ", 1.0)", "") +
                                "vec4 normalAt(vec3 ro, vec3 rd) { vec4 m = trace(ro, rd); "
                                "return vec4(rmNormal(ro + rd * m.x, m.w), m.z); }\n";
    const auto traced = run(prelude, "trace(P.xyz, Q.xyz)", ro, rd);
    const auto normals = run(prelude, "normalAt(P.xyz, Q.xyz)", ro, rd);
    double worst_t = 0, worst_angle = 0, worst_len = 0;
    const double spacing = std::nextafter(static_cast<float>(glm::length(centre)), INFINITY) - static_cast<float>(glm::length(centre));
    for (size_t i = 0; i < ro.size(); ++i) {
      const dvec3 o(glm::vec3(ro[i])), d(glm::vec3(rd[i]));
      const dvec3 oc = o - centre;
      const double b = glm::dot(oc, d), h = b * b - (glm::dot(oc, oc) - 1.0);
      if (h < 0.05) continue;  // a miss or a silhouette
      const double want = -b - std::sqrt(h);
      ASSERT_EQ(decode_trace(traced[i]).outcome, kHit) << "ray " << i << " at " << far;
      const dvec3 n_true = glm::normalize(o + want * d - centre);
      const double cos = std::abs(glm::dot(d, n_true));
      worst_t = std::max(worst_t, std::abs(traced[i].x - want) / (traced[i].w / cos + 4 * spacing));
      const dvec3 n(glm::vec3(normals[i]));
      worst_len = std::max(worst_len, std::abs(glm::length(n) - 1.0));
      worst_angle = std::max(worst_angle, std::acos(std::clamp(glm::dot(glm::normalize(n), n_true), -1.0, 1.0)) * 180 / M_PI);
    }
    const std::string at = far == 1e3 ? "1e3" : "1e4";
    report(("far from the origin at " + at + ": t error / (tolerance/cos + 4 float steps)").c_str(), worst_t, 1.0);
    report(("far from the origin at " + at + ": normal length error").c_str(), worst_len, 1e-3);
    report(("far from the origin at " + at + ": normal angle (degrees)").c_str(), worst_angle, far == 1e3 ? 1.0 : 5.0);
  }
}

// 5. Repetition far from the origin: a grid of spheres of radius 0.49 in
// cells of 1 (nearly filling them) around x = 1e4 and 1e5. Every camera ray
// that analytically hits a sphere (with a margin) stops within the hit
// tolerance of its surface, and none passes through a sphere (no holes).
TEST_F(Stability, RepetitionFarAwayHasNoHoles) {
  for (double far : {1e4, 1e5}) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<vec4> ro, rd;
    const dvec3 eye(far + 0.3, 0.2, 6.5);  // above one layer of spheres in the plane z = 0
    for (int i = 0; i < 2048; ++i) {
      ro.emplace_back(glm::vec3(eye), 0.0f);
      rd.emplace_back(glm::normalize(glm::vec3(dvec3(u(rng) * 0.4, u(rng) * 0.4, -1.0))), 0.0f);
    }
    const auto got = run(march_prelude("sdSphere(opRepeat(p, vec3(1.0, 1.0, 1e9), cell), 0.49)", "s.maxSteps = 400;"),
                         "trace(P.xyz, Q.xyz)", ro, rd);
    size_t holes = 0;
    double worst = 0;
    const float spacing = std::nextafter(static_cast<float>(far), INFINITY) - static_cast<float>(far);
    for (size_t i = 0; i < ro.size(); ++i) {
      const dvec3 o(glm::vec3(ro[i])), d(glm::vec3(rd[i]));
      // The first sphere along the ray: the cells around where it crosses z = 0.
      const dvec3 cross = o + (-o.z / d.z) * d;
      double want = 1e30, margin = 0;
      for (int dx = -2; dx <= 2; ++dx)
        for (int dy = -2; dy <= 2; ++dy) {
          const dvec3 c(std::round(cross.x) + dx, std::round(cross.y) + dy, 0.0);
          const dvec3 oc = o - c;
          const double b = glm::dot(oc, d), h = b * b - (glm::dot(oc, oc) - 0.49 * 0.49);
          if (h > 0 && -b - std::sqrt(h) < want) want = -b - std::sqrt(h), margin = h;
        }
      if (want > 1e29 || margin < 0.01) continue;  // a miss or a silhouette
      if (decode_trace(got[i]).outcome != kHit || got[i].x > want + 0.01) {
        ++holes;
        continue;
      }
      // What sphere tracing promises: the hit point lies within the tolerance
      // (and the float spacing of its coordinates) of the true surface.
      // (A ray that passes within the tolerance of an earlier sphere's
      // silhouette stops there, by design: measure to the nearest sphere.)
      const dvec3 x = o + static_cast<double>(got[i].x) * d;
      double off = 1e30;
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          off = std::min(off, std::abs(glm::length(x - dvec3(std::round(x.x) + dx, std::round(x.y) + dy, 0.0)) - 0.49));
      worst = std::max(worst, off / (got[i].w + 8 * spacing));
    }
    const std::string at = far == 1e4 ? "1e4" : "1e5";
    report(("repetition at " + at + ": rays through a sphere (holes)").c_str(), double(holes), 0);
    report(("repetition at " + at + ": hit point off the surface / (tolerance + 8 float steps)").c_str(), worst, 1.0);
  }
}

// 6. Over-relaxation up to 1.9 never tunnels: thin shells (thickness 2e-3),
// a twisted box and a smooth union give the same hit mask as plain sphere tracing.
TEST_F(Stability, OverRelaxationNeverTunnels) {
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  std::vector<vec4> ro, rd;
  for (int i = 0; i < 4096; ++i) {
    const dvec3 o = 4.0 * glm::normalize(dvec3(u(rng), u(rng), u(rng)) + dvec3(0, 0, 2));
    ro.emplace_back(glm::vec3(o), 0.0f);
    rd.emplace_back(glm::normalize(glm::vec3(dvec3(u(rng), u(rng), u(rng)) * 0.6 - o)), 0.0f);
  }
  const std::vector<std::pair<std::string, std::string>> fields = {
      {"thin shell", "opOnion(sdSphere(p, 1.0), 1e-3)"},
      {"twisted box", "sdBox(opTwist(p, 1.5), vec3(0.4, 0.9, 0.3)) / opTwistLipschitz(1.5, 2.3)"},
      {"smooth union", "opSmoothUnion(sdSphere(p - vec3(0.5, 0.0, 0.0), 0.6), sdBox(p + vec3(0.4, 0.0, 0.0), vec3(0.4)), 0.4)"},
  };
  for (const auto& [name, field] : fields) {
    const auto plain = run(march_prelude(field, "s.omega = 1.0; s.maxSteps = 600;"), "trace(P.xyz, Q.xyz)", ro, rd);
    size_t differing = 0;
    for (const char* omega : {"1.3", "1.6", "1.9"}) {
      const auto relaxed = run(march_prelude(field, std::string("s.omega = ") + omega + "; s.maxSteps = 600;"),
                               "trace(P.xyz, Q.xyz)", ro, rd);
      for (size_t i = 0; i < ro.size(); ++i) {
        const int a = decode_trace(plain[i]).outcome, b = decode_trace(relaxed[i]).outcome;
        EXPECT_NE(a, kOutOfSteps) << name << " ray " << i;
        if ((a == kHit) != (b == kHit)) ++differing;
      }
    }
    report(("over-relaxation up to 1.9, " + name + ": rays whose hit differs").c_str(), static_cast<double>(differing), 0);
  }
}

// 7. Soft shadows: finite at t = 0 and h = 0 and when h > 2 h_prev, and the
// penumbra is monotone along a line across it (no banding).
TEST_F(Stability, SoftShadowsAreFiniteAndMonotone) {
  const std::string prelude = "#include <rm/lighting.glsl>\n#include <rm/sdf.glsl>\n"
                              "float map(vec3 p) { return min(sdBox(p - vec3(0.0, 1.0, 0.0), vec3(0.5)), p.y); }\n";
  std::vector<vec4> points;
  for (int i = 0; i < 400; ++i) points.emplace_back(-0.2f + 1.4f * i / 399.0f, 0.01f, 0.0f, 0.0f);  // across the edge x = 0.5
  const std::string light = "normalize(vec3(0.4, 1.0, 0.0))";
  const auto classic = run(prelude, "vec4(rmSoftShadow(P.xyz, " + light + ", 0.0, 20.0, 8.0))", points);
  const auto improved = run(prelude, "vec4(rmSoftShadowImproved(P.xyz, " + light + ", 0.0, 20.0, 8.0))", points);
  for (const auto* series : {&classic, &improved}) {
    double worst_drop = 0;
    for (size_t i = 1; i < series->size(); ++i) worst_drop = std::max(worst_drop, double((*series)[i - 1].x - (*series)[i].x));
    report(series == &classic ? "classic soft shadow: largest decrease across the penumbra"
                              : "improved soft shadow: largest decrease across the penumbra",
           worst_drop, 0.02);
    EXPECT_LT((*series)[0].x, 0.05f) << "deep in the shadow";
    EXPECT_GT(series->back().x, 0.95f) << "in the open";
  }
}

// 8. Smooth minimum: k = 0, +-1e6 and negative distances stay finite and
// continuous (a tiny change of input changes the output by about as much).
TEST_F(Stability, SmoothMinimumStaysFiniteAndContinuous) {
  std::vector<vec4> points;
  for (double a : {-1e6, -1.0, -1e-3, 0.0, 1e-3, 1.0, 1e6})
    for (double b : {-1e6, -0.5, 0.0, 0.5, 1e6})
      for (double k : {0.0, 1e-6, 0.1, 10.0}) points.emplace_back(a, b, k, 0.0);
  const auto got = run("#include <rm/ops.glsl>\n",
                       "vec4(opSmoothUnion(P.x, P.y, P.z), opSmoothUnion(P.x * 1.0001 + 1e-4, P.y, P.z),"
                       " opSmoothIntersection(P.x, P.y, P.z), opSmoothSubtraction(P.x, P.y, P.z))",
                       points);
  double worst = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const double step = std::abs(points[i].x) * 1e-4 + 1e-4;
    worst = std::max(worst, std::abs(got[i].y - got[i].x) / step);
  }
  report("smooth minimum: output change per input change (Lipschitz)", worst, 1.0 + 1e-2);
}

// 9. Refraction through a glass ball (ior 1.5) by the library's path: march
// in, normal, refract, march inside (side = -1), normal, refract out. The exit
// direction matches Snell's law at both surfaces, in double precision. At the
// critical angle and past it, refraction falls back to reflection.
TEST_F(Stability, RefractionThroughABall) {
  std::vector<vec4> ro, rd;
  for (int i = 0; i < 200; ++i) {
    const double b = 0.95 * (i + 0.5) / 200.0;  // impact parameter
    ro.emplace_back(static_cast<float>(b), 0.0f, 5.0f, 0.0f);
    rd.emplace_back(0.0f, 0.0f, -1.0f, 0.0f);
  }
  const std::string prelude = R"(#define RM_NORMAL_TAPS 6
#define RM_NORMAL_EPSILON 1e-3
#include <rm/march.glsl>
#include <rm/normals.glsl>
#include <rm/optics.glsl>
float map(vec3 p) { return length(p) - 1.0; }
vec4 through(vec3 ro, vec3 rd) {
  RmMarchSettings s = rmMarchSettings();
  s.cone = 0.0;
  s.epsilon = 1e-6;
  s.maxSteps = 500;
  RmMarch in_ = rmMarch(ro, rd, s);
  vec3 p = ro + rd * in_.t;
  vec3 n = rmNormal(p, 1e-5);
  bool tir;
  vec3 d = rmRefract(rd, n, 1.5, tir);
  s.side = -1.0;
  vec3 o = p - n * rmSurfaceOffset(p, 1e-5);
  RmMarch out_ = rmMarch(o, d, s);
  vec3 q = o + d * out_.t;
  vec3 exitDir = rmRefract(d, rmNormal(q, 1e-5), 1.5, tir);
  return vec4(exitDir, float(in_.outcome + out_.outcome) + (tir ? 10.0 : 0.0));
}
)";
  const auto got = run(prelude, "through(P.xyz, Q.xyz)", ro, rd);
  auto refract = [](dvec3 d, dvec3 n, double eta) {  // n faces against d
    const double c = -glm::dot(n, d), k = 1.0 - eta * eta * (1.0 - c * c);
    return eta * d + (eta * c - std::sqrt(k)) * n;
  };
  double worst = 0;
  for (size_t i = 0; i < ro.size(); ++i) {
    ASSERT_EQ(got[i].w, 0.0f) << "ray " << i << ": a march missed or total internal reflection";
    const double b = ro[i].x;
    const dvec3 entry(b, 0, std::sqrt(1 - b * b));
    const dvec3 inside = refract(dvec3(0, 0, -1), entry, 1.0 / 1.5);
    const double t = -2.0 * glm::dot(entry, inside);  // the chord to the far side
    const dvec3 exit = entry + t * inside;
    const dvec3 want = refract(inside, -exit, 1.5);
    worst = std::max(worst, std::acos(std::clamp(glm::dot(glm::normalize(dvec3(glm::vec3(got[i]))), want), -1.0, 1.0)));
  }
  report("refraction through a ball: exit direction error (radians)", worst, 1e-3);

  // From inside glass toward a flat surface (normal +y), at and past the critical angle.
  const double critical = std::asin(1.0 / 1.5);
  std::vector<vec4> dirs;
  for (double a : {critical - 1e-3, critical, critical + 1e-6, critical + 0.1, 1.5})
    dirs.emplace_back(std::sin(a), std::cos(a), 0.0, 0.0);
  const auto bent = run("#include <rm/optics.glsl>\nvec4 bend(vec3 d) { bool tir; vec3 r = rmRefract(d, "
                        "vec3(0.0, 1.0, 0.0), 1.5, tir); return vec4(r, tir ? 1.0 : 0.0); }\n",
                        "bend(P.xyz)", dirs);
  EXPECT_EQ(bent[0].w, 0.0f) << "just inside the critical angle: refracted";
  for (size_t i = 2; i < dirs.size(); ++i) {
    EXPECT_EQ(bent[i].w, 1.0f) << "past the critical angle: reflected";
    EXPECT_NEAR(bent[i].y, -dirs[i].y, 1e-6);
  }
  for (const vec4& v : bent) EXPECT_NEAR(glm::length(glm::vec3(v)), 1.0, 1e-5);
}

// 10. Singular points: finite distances and unit normals at the ellipsoid's and
// sphere's centres, on box medial axes and at zero-gradient points.
TEST_F(Stability, SingularPointsGiveUnitNormals) {
  const std::vector<std::pair<std::string, vec4>> cases = {
      {"sdSphere(p, 1.0)", {0, 0, 0, 0}},
      {"sdEllipsoid(p, vec3(1.0, 0.5, 2.0))", {0, 0, 0, 0}},
      {"sdBox(p, vec3(1.0))", {0, 0, 0, 0}},
      {"sdBox(p, vec3(1.0))", {0.5, 0.5, 0, 0}},
      {"sdTorus(p, vec2(1.0, 0.3))", {0, 0, 0, 0}},
      {"sdTorus(p, vec2(1.0, 0.3))", {1, 0, 0, 0}},
  };
  double worst = 0;
  for (const auto& [field, at] : cases) {
    const auto got = run("#include <rm/normals.glsl>\n#include <rm/sdf.glsl>\nfloat map(vec3 p) { return " + field + "; }\n",
                         "vec4(rmNormal(P.xyz, 1e-3), map(P.xyz))", {at});
    worst = std::max(worst, std::abs(glm::length(glm::vec3(got[0])) - 1.0));
  }
  report("singular points: normal length error", worst, 1e-3);
}

// 11. Fractals: the Menger sponge at 1 to 14 levels and the Mandelbulb near
// r = 0 and at high iteration counts stay finite; the Menger estimate never
// exceeds the distance to its own surface.
TEST_F(Stability, FractalsStayFiniteAndBounded) {
  std::vector<vec4> points;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.3, 1.3);
  for (int i = 0; i < 1024; ++i) points.emplace_back(u(rng), u(rng), u(rng), 0.0f);
  points.emplace_back(0.0f, 0.0f, 0.0f, 0.0f);
  points.emplace_back(1e-30f, 0.0f, 0.0f, 0.0f);
  for (int levels : {1, 7, 14})
    run("#include <rm/fractals.glsl>\n", "vec4(sdMenger(P.xyz, " + std::to_string(levels) + "))", points);
  for (int iterations : {1, 8, 64, 256})
    run("#include <rm/fractals.glsl>\n", "vec4(sdMandelbulb(P.xyz, 8.0, " + std::to_string(iterations) + "))", points);
  double worst = 0;
  for (int levels : {1, 2, 3}) {
    Field menger{"Menger", "sdMenger(p, " + std::to_string(levels) + ")", DistanceClass::Bound, nullptr};
    menger.prelude = "#include <rm/fractals.glsl>";
    std::string error;
    const ContractReport r = measure_contract(menger, &error);
    ASSERT_TRUE(error.empty()) << error;
    worst = std::max(worst, r.worst_excess);
  }
  report("Menger sponge, 1-3 levels: excess over the brute-force distance", worst, 2e-5);

  // The Mandelbulb's estimate is approximate: as it is, it exceeds the
  // distance to its own surface (found by brute force) by up to about 0.02;
  // halved it never does on these samples. The stated factor is 2.
  Field bulb{"Mandelbulb", "sdMandelbulb(p, 8.0, 8)", DistanceClass::Approximate, nullptr, 2.0, true, 3, 1.4};
  bulb.prelude = "#include <rm/fractals.glsl>";
  std::string error;
  const ContractReport r = measure_contract(bulb, &error);
  ASSERT_TRUE(error.empty()) << error;
  report("Mandelbulb (8 iterations): estimate / 2 over the brute-force distance (excess)", r.worst_excess, 2e-5);
}

// 12. Degenerate inputs from the host: every example at 1x1, at iTime = 1e6,
// and with iMouse at 0 and at the window's far corner gives finite pixels.
TEST(HostInputs, ExamplesStayFinite) {
  size_t bad = 0, renders = 0;
  TempDir dir;
  for (const auto& entry : std::filesystem::directory_iterator(default_scene().parent_path())) {
    if (entry.path().extension() != ".frag") continue;
    for (const std::string args : {"--size 1x1", "--size 16x9 --time 1000000", "--size 16x9 --mouse 0,0,0,0",
                                   "--size 16x9 --mouse 16,9,16,9"}) {
      const auto out = dir / "frame.exr";
      const Outcome r = run_binary("render '" + entry.path().string() + "' -o '" + out.string() + "' " + args);
      ASSERT_EQ(r.status, 0) << entry.path() << " " << args << ": " << r.err;
      for (float v : read_pixels(out)) bad += !std::isfinite(v);
      ++renders;
    }
  }
  std::printf("[stability] host inputs (1x1, iTime 1e6, iMouse at 0 and at the corner), %zu renders: "
              "worst %zu non-finite values (bound 0)\n", renders, bad);
  EXPECT_EQ(bad, 0u);
}

}  // namespace
}  // namespace rm::test
