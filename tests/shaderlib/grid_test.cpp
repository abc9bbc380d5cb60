// rm/grid.glsl: an endless grid of spheres of different sizes and offsets,
// marched cell by cell, gives the analytic first hits (worked out here in
// double over every cell the ray passes), with fewer steps than the plain
// march of the same grid; hard shadows through it agree with the analytic
// ones, also when RM_GRID_CONVEX starts them in the next cell.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "gpu/egl_fixture.h"
#include "gpu/probe.h"
#include "march_probe.h"

namespace rm::test {
namespace {

using glm::dvec3;

const dvec3 kPeriod(2.0, 1.5, 2.5);
constexpr double kRadius = 0.6;  // below half the smallest period, 0.75

// Each cell's sphere: its size and its offset from the centre come from the
// cell id; the offset plus the largest radius stays within kRadius.
const char* kInstance = R"(
float instance(vec3 q, vec3 cell) {
  float k = mod(cell.x + 2.0 * cell.y + 3.0 * cell.z, 3.0);
  vec3 offset = 0.1 * vec3(k - 1.0, mod(cell.x, 2.0) - 0.5, 0.0);
  return length(q - offset) - (0.25 + 0.1 * k);
}
)";

// Each cell's own bounding sphere, for RM_GRID_CELL_RADIUS: the offset plus
// the radius, from 0.3 to 0.51 where all share kRadius.
const char* kCellRadius = R"(
float cellRadius(vec3 cell) {
  float k = mod(cell.x + 2.0 * cell.y + 3.0 * cell.z, 3.0);
  return length(0.1 * vec2(k - 1.0, mod(cell.x, 2.0) - 0.5)) + 0.25 + 0.1 * k + 1e-4;
}
)";

double gl_mod(double x, double y) { return x - y * std::floor(x / y); }

struct Sphere {
  dvec3 centre;
  double radius;
};

Sphere sphere_of(dvec3 cell) {
  const double k = gl_mod(cell.x + 2 * cell.y + 3 * cell.z, 3);
  return {cell * kPeriod + 0.1 * dvec3(k - 1, gl_mod(cell.x, 2) - 0.5, 0), 0.25 + 0.1 * k};
}

struct Ray {
  dvec3 ro, rd;
  double length;
};

// The first hit along the ray within its length (or -1) and the cosine there;
// `clear` says the ray passes no sphere before it (or before its end) within
// twice the march's threshold: sphere tracing may stop at such a near miss.
struct Analytic {
  double t = -1, cos = 0;
  bool clear = true;
};

Analytic analytic(const Ray& r, dvec3 skip_cell = dvec3(1e9)) {
  Analytic a;
  std::vector<std::pair<double, double>> near_misses;  // (where along the ray, how near)
  const dvec3 end = r.ro + r.length * r.rd;
  const dvec3 lo = glm::floor(glm::min(r.ro, end) / kPeriod) - 1.0, hi = glm::ceil(glm::max(r.ro, end) / kPeriod) + 1.0;
  for (double x = lo.x; x <= hi.x; ++x)
    for (double y = lo.y; y <= hi.y; ++y)
      for (double z = lo.z; z <= hi.z; ++z) {
        if (dvec3(x, y, z) == skip_cell) continue;
        const Sphere s = sphere_of({x, y, z});
        const dvec3 oc = r.ro - s.centre;
        const double b = glm::dot(oc, r.rd), h = b * b - (glm::dot(oc, oc) - s.radius * s.radius);
        const double t = h < 0 ? -1 : -b - std::sqrt(h);
        if (t >= 0 && t <= r.length) {
          if (a.t < 0 || t < a.t) {
            a.t = t;
            a.cos = std::abs(glm::dot(r.rd, glm::normalize(r.ro + t * r.rd - s.centre)));
          }
        } else {
          const double along = std::clamp(-b, 0.0, r.length);
          near_misses.emplace_back(along, glm::length(oc + along * r.rd) - s.radius);
        }
      }
  const double until = a.t >= 0 ? a.t : r.length;
  for (const auto& [along, how_near] : near_misses)
    if (along <= until && how_near < 2.0 * (1.1e-3 * along + 1e-3)) a.clear = false;
  return a;
}

// Random rays through the grid, and the awkward ones: along each axis, and
// lying in a plane of cell faces.
std::vector<Ray> rays() {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  std::normal_distribution<double> n;
  std::vector<Ray> out;
  for (int i = 0; i < 1500; ++i) {
    dvec3 rd = glm::normalize(dvec3(n(rng), n(rng), n(rng)));
    if (i % 10 == 0) rd = dvec3(0.0);
    if (i % 10 == 0) rd[i / 10 % 3] = i % 20 == 0 ? 1.0 : -1.0;  // along an axis
    dvec3 ro(u(rng), u(rng), u(rng));
    if (i % 10 == 5) ro.x = 0.5 * kPeriod.x, rd = glm::normalize(dvec3(0.0, rd.y, rd.z));  // in a face plane
    out.push_back({dvec3(glm::vec3(ro)), dvec3(glm::normalize(glm::vec3(rd))), 30.0});
  }
  return out;
}

std::string grid_prelude(const std::string& defines) {
  return "#define RM_GRID_PERIOD vec3(2.0, 1.5, 2.5)\n#define RM_GRID_RADIUS 0.6\n" + defines +
         "#include <rm/grid.glsl>\n" + kInstance + "float mapCell(vec3 q, vec3 cell) { return instance(q, cell); }\n" +
         (defines.find("RM_GRID_CELL_RADIUS") != std::string::npos ? kCellRadius : "");
}

// Marches every ray with `march` (rmMarchGrid, or rmMarch: the plain march of
// the grid's map(), the cell's instance or the border plus the gap).
std::vector<Traced> march(const std::string& march, const std::vector<Ray>& rs, const std::string& defines = "") {
  const std::string trace = "vec4 trace(vec3 ro, vec3 rd) {\n  RmMarchSettings s = rmMarchSettings();\n"
                            "  s.maxSteps = 2000;\n  s.tMax = 30.0;\n  RmMarch m = " + march + "(ro, rd, s);\n"
                            "  return vec4(m.t, float(m.steps), float(m.outcome), m.tolerance);\n}\n";
  std::vector<glm::vec4> ps, qs;
  for (const Ray& r : rs) ps.emplace_back(glm::vec3(r.ro), 0), qs.emplace_back(glm::vec3(r.rd), 0);
  std::string error;
  auto got = probe(grid_prelude(defines) + trace, "trace(P.xyz, Q.xyz)", ps, &error, qs);
  EXPECT_TRUE(got) << error;
  std::vector<Traced> out;
  for (const glm::vec4& v : got.value_or(std::vector<glm::vec4>())) out.push_back(decode_trace(v));
  return out;
}

// Checks each ray's march against the analytic answer, where the ray passes
// no near miss: the hit within the march's tolerance (where it meets the
// sphere at a cosine of 0.1 or more), or a miss. Returns the rays checked.
struct Checked {
  int hits = 0, misses = 0;
  std::vector<size_t> rays;
};
Checked expect_analytic(const std::vector<Ray>& rs, const std::vector<Traced>& got) {
  Checked c;
  for (size_t i = 0; i < rs.size(); ++i) {
    SCOPED_TRACE("ray " + std::to_string(i));
    EXPECT_TRUE(std::isfinite(got[i].t));
    const Analytic want = analytic(rs[i]);
    if (!want.clear) continue;
    if (want.t >= 0 && want.cos >= 0.1) {
      ++c.hits;
      EXPECT_EQ(got[i].outcome, kHit);
      if (got[i].outcome == kHit) {
        EXPECT_NEAR(got[i].t, want.t, got[i].tolerance / want.cos + 1e-5);
      }
    } else if (want.t < 0) {
      ++c.misses;
      EXPECT_EQ(got[i].outcome, kMiss);
    } else {
      continue;
    }
    c.rays.push_back(i);
  }
  return c;
}

class Grid : public EglTest {};

TEST_F(Grid, MarchesCellByCellToTheAnalyticHitsInFewerSteps) {
  const std::vector<Ray> rs = rays();
  const std::vector<Traced> cells = march("rmMarchGrid", rs), plain = march("rmMarch", rs);
  ASSERT_EQ(cells.size(), rs.size());
  ASSERT_EQ(plain.size(), rs.size());
  const Checked checked = expect_analytic(rs, cells);
  int axis_or_face = 0;
  double cell_steps = 0, plain_steps = 0;
  for (size_t i : checked.rays) {
    axis_or_face += i % 5 == 0;
    cell_steps += cells[i].steps;
    plain_steps += plain[i].steps;
  }
  EXPECT_GT(checked.hits, 600);
  EXPECT_GT(checked.misses, 100);
  EXPECT_GT(axis_or_face, 150) << "rays along an axis or in a face plane are checked too";
  EXPECT_LT(cell_steps, 0.7 * plain_steps) << "cells " << cell_steps << ", plain " << plain_steps;
}

// With each cell's own bounding sphere (RM_GRID_CELL_RADIUS) the grid march
// meets the same hits and misses, and crosses more cells in one step.
TEST_F(Grid, EachCellsOwnRadiusGivesTheSameHitsInFewerSteps) {
  const std::vector<Ray> rs = rays();
  const std::vector<Traced> shared = march("rmMarchGrid", rs),
                            own = march("rmMarchGrid", rs, "#define RM_GRID_CELL_RADIUS\n");
  ASSERT_EQ(shared.size(), rs.size());
  ASSERT_EQ(own.size(), rs.size());
  const Checked checked = expect_analytic(rs, own);
  double shared_steps = 0, own_steps = 0;
  for (size_t i : checked.rays) {
    shared_steps += shared[i].steps;
    own_steps += own[i].steps;
  }
  EXPECT_GT(checked.hits, 600);
  EXPECT_GT(checked.misses, 100);
  EXPECT_LT(own_steps, 0.9 * shared_steps) << "own " << own_steps << ", shared " << shared_steps;
}

// rmHardShadowCells: 0 exactly when a sphere lies within the segment. From a point on a sphere toward the open side, RM_GRID_CONVEX
// starts in the next cell and still finds every other sphere.
TEST_F(Grid, HardShadowsMeetTheSpheresOnTheirSegment) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-5.0, 5.0), length(1.0, 8.0);
  std::normal_distribution<double> n;
  std::vector<Ray> open, leaving;
  std::vector<dvec3> own;
  while (open.size() < 600) {
    const Ray r{dvec3(glm::vec3(u(rng), u(rng), u(rng))), dvec3(glm::normalize(glm::vec3(n(rng), n(rng), n(rng)))),
                length(rng)};
    const dvec3 cell = glm::round(r.ro / kPeriod);
    const Sphere s = sphere_of(cell);
    if (glm::length(r.ro - s.centre) > s.radius + 0.05) open.push_back(r);
    // A point on this cell's sphere, and a direction away from it.
    const dvec3 normal = glm::normalize(dvec3(n(rng), n(rng), n(rng)));
    dvec3 rd = glm::normalize(normal + 0.8 * glm::normalize(dvec3(n(rng), n(rng), n(rng))));
    if (glm::dot(rd, normal) < 0.3) continue;
    leaving.push_back({dvec3(glm::vec3(s.centre + (s.radius + 1e-3) * normal)), dvec3(glm::vec3(rd)), length(rng)});
    own.push_back(cell);
  }
  auto shadows = [](const std::string& defines, const std::vector<Ray>& rs) {
    std::vector<glm::vec4> ps, qs;
    for (const Ray& r : rs) ps.emplace_back(glm::vec3(r.ro), static_cast<float>(r.length)), qs.emplace_back(glm::vec3(r.rd), 0);
    std::string error;
    auto got = probe(grid_prelude(defines), "vec4(rmHardShadowCells(P.xyz, Q.xyz, 0.0, P.w, 64))", ps, &error, qs);
    EXPECT_TRUE(got) << error;
    return got.value_or(std::vector<glm::vec4>(rs.size()));
  };
  auto expect_agree = [](const std::vector<glm::vec4>& got, const std::vector<Ray>& rs, const std::vector<dvec3>& skip) {
    int shaded = 0, lit = 0;
    for (size_t i = 0; i < rs.size(); ++i) {
      const Analytic want = analytic(rs[i], skip.empty() ? dvec3(1e9) : skip[i]);
      if (!want.clear) continue;
      if (want.t >= 0 && want.cos > 0.1) {
        ++shaded;
        EXPECT_EQ(got[i].x, 0.0f) << "ray " << i << " meets a sphere at " << want.t;
      } else if (want.t < 0) {
        ++lit;
        EXPECT_EQ(got[i].x, 1.0f) << "ray " << i;
      }
    }
    EXPECT_GT(shaded, 80);
    EXPECT_GT(lit, 80);
  };
  expect_agree(shadows("", open), open, {});
  expect_agree(shadows("#define RM_GRID_CONVEX\n", leaving), leaving, own);
  expect_agree(shadows("", leaving), leaving, own);
}

// rm/render.glsl marches a grid cell by cell, and with RM_GRID_MARCH 0 the
// plain way: the same colours, for fewer map() calls.
TEST_F(Grid, RenderMarchesTheGridCellByCellUnlessToldNotTo) {
  std::vector<glm::vec4> ps, qs;
  for (const Ray& r : rays()) {
    if (!analytic(r).clear) continue;
    ps.emplace_back(glm::vec3(r.ro), 0), qs.emplace_back(glm::vec3(r.rd), 0);
  }
  auto render = [&](const std::string& defines) {
    const std::string prelude = "uniform vec4 iMouse;\nuniform vec3 iResolution;\n#define RM_COUNT\n#define RM_SHADOWS 1\n"
                                "#define RM_MAX_DISTANCE 30.0\n#define RM_MAX_STEPS 2000\n#define RM_SHADOW_STEPS 2000\n" + defines +
                                "#define RM_GRID_PERIOD vec3(2.0, 1.5, 2.5)\n#define RM_GRID_RADIUS 0.6\n"
                                "#include <rm/render.glsl>\n" + kInstance +
                                "float mapCell(vec3 q, vec3 cell) { return instance(q, cell); }\n"
                                "RmMaterial material(vec3 p, vec3 n) { return rmMaterial(0.5 + 0.5 * n); }\n";
    std::string error;
    auto got = probe(prelude, "vec4(rmRender(P.xyz, Q.xyz, 1e-3), float(rmEvaluations))", ps, &error, qs);
    EXPECT_TRUE(got) << error;
    return got.value_or(std::vector<glm::vec4>(ps.size()));
  };
  const auto cells = render(""), plain = render("#define RM_GRID_MARCH 0\n");
  double cell_calls = 0, plain_calls = 0;
  size_t alike = 0;
  for (size_t i = 0; i < ps.size(); ++i) {
    alike += glm::length(glm::vec3(cells[i]) - glm::vec3(plain[i])) < 2e-2f;
    cell_calls += cells[i].w;
    plain_calls += plain[i].w;
  }
  EXPECT_GT(alike, 0.98 * static_cast<double>(ps.size())) << "of " << ps.size() << " rays";
  EXPECT_LT(cell_calls, 0.7 * plain_calls) << "cells " << cell_calls << ", plain " << plain_calls;
}

// Without its knobs the module says what it needs, in its own file.
TEST_F(Grid, WithoutACellSizeSaysWhatItNeeds) {
  std::string error;
  EXPECT_FALSE(Probe::build("#include <rm/grid.glsl>\nfloat mapCell(vec3 q, vec3 cell) { return length(q) - 0.4; }\n",
                            "vec4(0.0)", &error));
  EXPECT_NE(error.find("grid.glsl:"), std::string::npos) << error;
  EXPECT_NE(error.find("needs RM_GRID_PERIOD"), std::string::npos) << error;
}

}  // namespace
}  // namespace rm::test
