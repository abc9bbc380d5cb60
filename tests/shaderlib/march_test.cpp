// rm/march.glsl finds the analytic hit distances of a sphere, a plane and a
// box from many angles within its threshold, with and without over-relaxation
// and bounds, and marches inside objects; rm/normals.glsl gives unit normals
// within 1 degree of the analytic ones.
#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "geometry.h"
#include "gpu/egl_fixture.h"
#include "gpu/probe.h"
#include "march_probe.h"

namespace rm::test {
namespace {

using glm::dvec3;

struct Shape {
  std::string glsl;                                   // map()'s body
  std::function<double(dvec3)> sdf;                   // exact distance, double
  std::function<double(dvec3, dvec3)> intersect;      // first t > 0 of the ray, or -1
  std::function<dvec3(dvec3)> normal;
};

double ray_sphere(dvec3 ro, dvec3 rd, double r, bool inside = false) {
  const double b = glm::dot(ro, rd), h = b * b - (glm::dot(ro, ro) - r * r);
  if (h < 0) return -1;
  const double t = inside ? -b + std::sqrt(h) : -b - std::sqrt(h);
  return t >= 0 ? t : -1;
}

double ray_box(dvec3 ro, dvec3 rd, dvec3 b) {
  double near = -1e30, far = 1e30;
  for (int i = 0; i < 3; ++i) {
    if (rd[i] == 0) {
      if (std::abs(ro[i]) > b[i]) return -1;
      continue;
    }
    const double t0 = (-b[i] - ro[i]) / rd[i], t1 = (b[i] - ro[i]) / rd[i];
    near = std::max(near, std::min(t0, t1));
    far = std::min(far, std::max(t0, t1));
  }
  return near <= far && near >= 0 ? near : -1;
}

const dvec3 kBox(0.8, 0.5, 0.6);

Shape sphere() {
  return {"sdSphere(p, 1.0)", [](dvec3 p) { return glm::length(p) - 1.0; },
          [](dvec3 ro, dvec3 rd) { return ray_sphere(ro, rd, 1.0); }, [](dvec3 p) { return glm::normalize(p); }};
}
Shape plane() {
  return {"p.y + 0.5", [](dvec3 p) { return p.y + 0.5; },
          [](dvec3 ro, dvec3 rd) { return rd.y < 0 ? (ro.y + 0.5) / -rd.y : -1.0; },
          [](dvec3) { return dvec3(0, 1, 0); }};
}
Shape box() {
  return {"sdBox(p, vec3(0.8, 0.5, 0.6))", [](dvec3 p) { return geometry::box(p, kBox); },
          [](dvec3 ro, dvec3 rd) { return ray_box(ro, rd, kBox); },
          [](dvec3 p) {
            const dvec3 q = glm::abs(p) / kBox;  // the face whose slab the point is deepest in
            const int axis = q.x > q.y && q.x > q.z ? 0 : q.y > q.z ? 1 : 2;
            dvec3 n(0);
            n[axis] = p[axis] > 0 ? 1 : -1;
            return n;
          }};
}

struct Ray {
  dvec3 ro, rd;
};

// Rays from a shell of radius 4 toward points near the origin: hits, misses and silhouettes.
std::vector<Ray> rays(int n, bool from_above = false) {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> u(-1.3, 1.3);
  std::vector<Ray> out;
  while (static_cast<int>(out.size()) < n) {
    dvec3 ro = 4.0 * glm::normalize(dvec3(normal(rng), normal(rng), normal(rng)));
    if (from_above) ro.y = std::abs(ro.y);
    const dvec3 rd = glm::normalize(dvec3(u(rng), u(rng), u(rng)) - ro);
    out.push_back({dvec3(glm::vec3(ro)), dvec3(glm::normalize(glm::vec3(rd)))});
  }
  return out;
}

// Marches every ray through `map_body` with settings changed by `settings` (GLSL statements on `s`).
std::vector<Traced> march(const std::string& map_body, const std::string& settings, const std::vector<Ray>& rs) {
  const std::string prelude = march_prelude(map_body, "s.maxSteps = 400;\n  s.tMax = 20.0;\n" + settings);
  std::vector<glm::vec4> ps, qs;
  for (const Ray& r : rs) ps.emplace_back(glm::vec3(r.ro), 0), qs.emplace_back(glm::vec3(r.rd), 0);
  std::string error;
  auto got = probe(prelude, "trace(P.xyz, Q.xyz)", ps, &error, qs);
  EXPECT_TRUE(got) << error;
  std::vector<Traced> out;
  if (!got) return out;
  for (const glm::vec4& v : *got) out.push_back(decode_trace(v));
  return out;
}

// Closest approach of a ray to a shape, by dense sampling.
double closest_approach(const Shape& shape, const Ray& r) {
  double best = 1e30;
  for (double t = 0; t < 10; t += 0.002) best = std::min(best, shape.sdf(r.ro + t * r.rd));
  return best;
}

void expect_finds_analytic_hits(const Shape& shape, const std::string& settings, bool from_above = false) {
  const std::vector<Ray> rs = rays(2048, from_above);
  const std::vector<Traced> got = march(shape.glsl, settings, rs);
  ASSERT_EQ(got.size(), rs.size());
  int hits = 0, misses = 0, grazing = 0;
  for (size_t i = 0; i < rs.size(); ++i) {
    const Ray& r = rs[i];
    const double want = shape.intersect(r.ro, r.rd);
    SCOPED_TRACE("ray " + std::to_string(i) + " settings: " + settings);
    if (want >= 0) {
      const double cos = std::abs(glm::dot(r.rd, shape.normal(r.ro + want * r.rd)));
      if (cos < 0.1) {
        ++grazing;
        continue;
      }
      ++hits;
      ASSERT_EQ(got[i].outcome, kHit);
      // Sphere tracing stops within the threshold of the surface: along the ray
      // that is up to threshold / cos before it, and never through it.
      EXPECT_NEAR(got[i].t, want, got[i].tolerance / cos + 1e-5);
    } else if (closest_approach(shape, r) > 0.02) {
      ++misses;
      ASSERT_EQ(got[i].outcome, kMiss);
    }
  }
  EXPECT_GT(hits, 300);
  EXPECT_GT(misses, 100);
}

class March : public EglTest {};

TEST_F(March, FindsASphere) { expect_finds_analytic_hits(sphere(), "s.omega = 1.0;"); }
TEST_F(March, FindsABox) { expect_finds_analytic_hits(box(), "s.omega = 1.0;"); }
TEST_F(March, FindsAPlane) { expect_finds_analytic_hits(plane(), "s.omega = 1.0;", true); }
TEST_F(March, OverRelaxedFindsASphere) { expect_finds_analytic_hits(sphere(), "s.omega = 1.6;"); }
TEST_F(March, OverRelaxedFindsABox) { expect_finds_analytic_hits(box(), "s.omega = 1.6;"); }
TEST_F(March, OverRelaxedFindsAPlane) { expect_finds_analytic_hits(plane(), "s.omega = 1.6;", true); }
TEST_F(March, BoundingSphereKeepsTheHits) {
  expect_finds_analytic_hits(box(), "s.boundSphere = vec4(0.0, 0.0, 0.0, 1.2);");
}
TEST_F(March, BoundingBoxKeepsTheHits) {
  expect_finds_analytic_hits(sphere(), "s.boundBox = true; s.boundMin = vec3(-1.01); s.boundMax = vec3(1.01);");
}

// Over-relaxation with its fallback never changes what is hit, whatever omega.
// (Whether it saves steps depends on the view: these rays aim at the shapes
// head-on, where it cannot; docs/shaderlib.md measures a view with a floor.)
TEST_F(March, OverRelaxationNeverChangesWhatIsHit) {
  const std::vector<Ray> rs = rays(2048);
  for (const Shape& shape : {sphere(), box()}) {
    const auto plain = march(shape.glsl, "s.omega = 1.0;", rs);
    for (const char* omega : {"1.2", "1.5", "1.9"}) {
      const auto relaxed = march(shape.glsl, std::string("s.omega = ") + omega + ";", rs);
      ASSERT_EQ(plain.size(), relaxed.size());
      for (size_t i = 0; i < rs.size(); ++i) {
        if (plain[i].outcome != kOutOfSteps && relaxed[i].outcome != kOutOfSteps) {
          EXPECT_EQ(plain[i].outcome, relaxed[i].outcome) << shape.glsl << " omega " << omega << " ray " << i;
        }
      }
    }
  }
}

// The analytic ground plane: rays that miss the sphere end on y = -1 at the exact t.
TEST_F(March, AnalyticGroundPlaneIsExact) {
  const std::vector<Ray> rs = rays(2048, true);
  const auto got = march("sdSphere(p, 1.0)", "s.ground = true; s.groundHeight = -1.0;", rs);
  int ground_hits = 0;
  for (size_t i = 0; i < rs.size(); ++i) {
    const Ray& r = rs[i];
    const double sphere_t = ray_sphere(r.ro, r.rd, 1.0);
    const double ground_t = r.rd.y < 0 ? (r.ro.y + 1.0) / -r.rd.y : -1.0;
    if (ground_t < 0 || ground_t > 20.0 || (sphere_t >= 0 && sphere_t < ground_t) || closest_approach(sphere(), r) < 0.02) continue;
    ++ground_hits;
    ASSERT_EQ(got[i].outcome, kHit) << "ray " << i;
    EXPECT_TRUE(got[i].ground) << "ray " << i;
    EXPECT_NEAR(got[i].t, ground_t, 1e-5 * ground_t) << "ray " << i;
  }
  EXPECT_GT(ground_hits, 200);
}

// Marching inside (side = -1) finds where a ray from inside a sphere leaves it.
TEST_F(March, MarchesInsideToTheExit) {
  std::mt19937 rng(3);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> radius(0.0, 0.9);
  std::vector<Ray> rs;
  for (int i = 0; i < 2048; ++i) {
    const dvec3 ro = radius(rng) * glm::normalize(dvec3(normal(rng), normal(rng), normal(rng)));
    const dvec3 rd = glm::normalize(dvec3(normal(rng), normal(rng), normal(rng)));
    rs.push_back({dvec3(glm::vec3(ro)), dvec3(glm::normalize(glm::vec3(rd)))});
  }
  const auto got = march("sdSphere(p, 1.0)", "s.side = -1.0;", rs);
  for (size_t i = 0; i < rs.size(); ++i) {
    const double want = ray_sphere(rs[i].ro, rs[i].rd, 1.0, true);
    const double cos = std::abs(glm::dot(rs[i].rd, glm::normalize(rs[i].ro + want * rs[i].rd)));
    ASSERT_EQ(got[i].outcome, kHit) << "ray " << i;
    EXPECT_NEAR(got[i].t, want, got[i].tolerance / cos + 1e-5) << "ray " << i;
  }
}

TEST_F(March, ReportsRunningOutOfSteps) {
  // Near the sphere's rim: plain sphere tracing needs more than two steps here.
  const auto got = march("sdSphere(p, 1.0)", "s.maxSteps = 2;", {{dvec3(0, 0.9, 10), dvec3(0, 0, -1)}});
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].outcome, kOutOfSteps);
  EXPECT_EQ(got[0].steps, 2);
}

class Normals : public EglTest {
 protected:
  // Normals at points on `shape`'s surface (given by `points`), by `method`.
  void expect_accurate(const Shape& shape, const std::string& method, const std::vector<dvec3>& points,
                       dvec3 offset = dvec3(0)) {
    std::vector<glm::vec4> ps;
    for (const dvec3& p : points) ps.emplace_back(glm::vec3(p + offset), 0);
    const std::string map = "float map(vec3 p) { p -= vec3(" + std::to_string(offset.x) + ", " +
                            std::to_string(offset.y) + ", " + std::to_string(offset.z) + "); return " + shape.glsl +
                            "; }\n";
    std::string error;
    auto got = probe("#include <rm/sdf.glsl>\n#include <rm/normals.glsl>\n" + map, "vec4(" + method + ", 0.0)", ps,
                     &error);
    ASSERT_TRUE(got) << error;
    double worst_angle = 0, worst_length = 0;
    for (size_t i = 0; i < points.size(); ++i) {
      const dvec3 n((*got)[i]);
      worst_length = std::max(worst_length, std::abs(glm::length(n) - 1.0));
      const double c = glm::dot(glm::normalize(n), shape.normal(points[i]));
      worst_angle = std::max(worst_angle, std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI);
    }
    EXPECT_LT(worst_length, 1e-3) << method;
    EXPECT_LT(worst_angle, 1.0) << method << " (degrees)";
  }
};

std::vector<dvec3> on_sphere(int n) {
  std::mt19937 rng(11);
  std::normal_distribution<double> normal;
  std::vector<dvec3> out;
  for (int i = 0; i < n; ++i) out.push_back(glm::normalize(dvec3(normal(rng), normal(rng), normal(rng))));
  return out;
}

// Points on the box's faces, away from edges by more than the normal's epsilon.
std::vector<dvec3> on_box_faces(int n) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(-0.9, 0.9);
  std::vector<dvec3> out;
  for (int i = 0; i < n; ++i) {
    dvec3 p(u(rng) * kBox.x, u(rng) * kBox.y, u(rng) * kBox.z);
    const int axis = i % 3;
    p[axis] = (i % 2 ? 1 : -1) * kBox[axis];
    out.push_back(p);
  }
  return out;
}

TEST_F(Normals, TetrahedronOnASphere) { expect_accurate(sphere(), "rmNormal(P.xyz, 1e-3)", on_sphere(4096)); }
TEST_F(Normals, CentralDifferencesOnASphere) {
  expect_accurate(sphere(), "rmNormalCentral(P.xyz, 1e-3)", on_sphere(4096));
}
TEST_F(Normals, TetrahedronOnBoxFaces) { expect_accurate(box(), "rmNormal(P.xyz, 1e-3)", on_box_faces(4096)); }
// At |p| = 1000 a fixed 1e-4 step is two float steps; rmNormalEpsilon grows it.
TEST_F(Normals, StayAccurateAThousandUnitsOut) {
  expect_accurate(sphere(), "rmNormal(P.xyz, 1e-3)", on_sphere(4096), dvec3(1000, 0, 0));
}

}  // namespace
}  // namespace rm::test
