// The distance contract of a shaderlib field (a primitive, an op or a
// transform applied to primitives), checked on the GPU through the probe:
//  - every value is finite;
//  - exact fields agree with a double-precision geometric reference (1e-5);
//  - no field exceeds the true distance times its Lipschitz constant L, where
//    the true distance is measured by brute force against its zero set, found
//    on a dense grid; exact fields also come within one grid step of it;
//  - |f(a) - f(b)| <= L |a - b| on random point pairs.
#pragma once
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "gpu/probe.h"

namespace rm::test {

enum class DistanceClass {
  Exact,         // |f| is the distance to the surface
  ExactOutside,  // exact where f > 0, a bound inside
  Bound,         // never more than the distance, Lipschitz <= 1
  Approximate,   // Lipschitz <= `lipschitz`; f / L is a bound
};

struct Field {
  std::string name;
  std::string glsl;  // an expression of `p` (vec3, or vec2 when dims == 2)
  DistanceClass kind = DistanceClass::Exact;
  std::function<double(glm::dvec3)> reference = nullptr;  // exact classes
  double lipschitz = 1.0;
  bool bounded = true;     // the whole zero set lies inside the sampled box
  int dims = 3;
  double extent = 1.6;     // samples lie in [-extent, extent]^dims
  std::string prelude = "#include <rm/sdf.glsl>";
};

inline std::ostream& operator<<(std::ostream& out, const Field& f) { return out << f.name; }

struct ContractReport {
  double worst_reference_error = 0.0;  // relative to max(1, |reference|)
  double worst_excess = 0.0;           // max of |f| / L - bruteForce, over queries
  double worst_shortfall = 0.0;        // max of bruteForce - |f|, exact fields
  double max_lipschitz = 0.0;          // largest |f(a) - f(b)| / |a - b| seen
  size_t surface_samples = 0;
  size_t non_finite = 0;
};

inline ContractReport measure_contract(const Field& f, std::string* error) {
  const int grid = f.dims == 3 ? 48 : 256;
  const double spacing = 2.0 * f.extent / (grid - 1);
  std::mt19937 rng(20261121);
  std::uniform_real_distribution<double> u(-f.extent, f.extent);
  std::normal_distribution<double> normal;
  auto random_point = [&] { return glm::dvec3(u(rng), u(rng), f.dims == 3 ? u(rng) : 0.0); };
  // Sample positions as the GPU sees them (float), so references use the same inputs.
  auto as_float = [](glm::dvec3 p) { return glm::dvec3(glm::vec3(p)); };

  constexpr int kQueries = 2048, kPairs = 2048;
  std::vector<glm::dvec3> points;
  for (int i = 0; i < kQueries; ++i) points.push_back(as_float(random_point()));
  for (int i = 0; i < kPairs; ++i) {
    const glm::dvec3 a = random_point();
    glm::dvec3 dir(normal(rng), normal(rng), f.dims == 3 ? normal(rng) : 0.0);
    const double length = std::exp(std::uniform_real_distribution<double>(std::log(1e-2), 0.0)(rng));
    points.push_back(as_float(a));
    points.push_back(as_float(a + glm::normalize(dir) * length));
  }
  const size_t grid_start = points.size();
  const int nz = f.dims == 3 ? grid : 1;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < grid; ++j)
      for (int i = 0; i < grid; ++i)
        points.push_back(as_float(glm::dvec3(-f.extent + i * spacing, -f.extent + j * spacing,
                                             f.dims == 3 ? -f.extent + k * spacing : 0.0)));

  std::vector<glm::vec4> texels;
  for (const auto& p : points) texels.emplace_back(glm::vec3(p), 0.0f);
  const std::string type = f.dims == 3 ? "vec3" : "vec2";
  const std::string swizzle = f.dims == 3 ? "P.xyz" : "P.xy";
  auto field = Probe::build(f.prelude + "\nfloat field(" + type + " p) { return " + f.glsl + "; }\n",
                            "vec4(field(" + swizzle + "), 0.0, 0.0, 0.0)", error);
  ContractReport report;
  if (!field) return report;
  const std::vector<glm::vec4> values = field->run(texels);
  auto value = [&](size_t i) { return static_cast<double>(values[i].x); };
  for (size_t i = 0; i < points.size(); ++i)
    if (!std::isfinite(value(i))) ++report.non_finite;

  // The zero set: sign changes along grid edges, each narrowed by a few rounds
  // of regula falsi on the GPU (a straight interpolation would sit on the chord).
  struct Bracket {
    glm::dvec3 a, b;
    double fa, fb;
  };
  std::vector<Bracket> brackets;
  auto at = [&](int i, int j, int k) { return grid_start + (static_cast<size_t>(k) * grid + j) * grid + i; };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < grid; ++j)
      for (int i = 0; i < grid; ++i) {
        const size_t here = at(i, j, k);
        const int step[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        for (const auto& s : step) {
          if (i + s[0] >= grid || j + s[1] >= grid || k + s[2] >= nz) continue;
          const size_t there = at(i + s[0], j + s[1], k + s[2]);
          if ((value(here) < 0) != (value(there) < 0))
            brackets.push_back({points[here], points[there], value(here), value(there)});
        }
      }
  auto crossing = [](const Bracket& b) { return glm::mix(b.a, b.b, b.fa / (b.fa - b.fb)); };
  for (int round = 0; round < 4 && !brackets.empty(); ++round) {
    std::vector<glm::vec4> guesses;
    for (const Bracket& b : brackets) guesses.emplace_back(glm::vec3(crossing(b)), 0.0f);
    const std::vector<glm::vec4> at_guess = field->run(guesses);
    for (size_t i = 0; i < brackets.size(); ++i) {
      Bracket& b = brackets[i];
      const glm::dvec3 x(glm::vec3(guesses[i]));
      const double fx = at_guess[i].x;
      if ((fx < 0) == (b.fa < 0)) b.a = x, b.fa = fx;
      else b.b = x, b.fb = fx;
    }
  }
  std::vector<glm::dvec3> surface;
  for (const Bracket& b : brackets) surface.push_back(crossing(b));
  report.surface_samples = surface.size();

  for (int q = 0; q < kQueries; ++q) {
    const double got = value(static_cast<size_t>(q));
    if (f.reference) {
      const double want = f.reference(points[static_cast<size_t>(q)]);
      if (f.kind != DistanceClass::ExactOutside || want > 0)
        report.worst_reference_error =
            std::max(report.worst_reference_error, std::abs(got - want) / std::max(1.0, std::abs(want)));
    }
    if (surface.empty()) continue;
    double nearest = std::numeric_limits<double>::max();
    for (const auto& s : surface) nearest = std::min(nearest, glm::length(points[static_cast<size_t>(q)] - s));
    report.worst_excess = std::max(report.worst_excess, std::abs(got) / f.lipschitz - nearest);
    const bool exact_here = f.kind == DistanceClass::Exact || (f.kind == DistanceClass::ExactOutside && got > 0);
    if (exact_here && f.bounded) report.worst_shortfall = std::max(report.worst_shortfall, nearest - std::abs(got));
  }
  for (int i = 0; i < kPairs; ++i) {
    const size_t a = kQueries + 2 * static_cast<size_t>(i), b = a + 1;
    report.max_lipschitz =
        std::max(report.max_lipschitz, std::abs(value(a) - value(b)) / glm::length(points[a] - points[b]));
  }
  return report;
}

// Measures `f` and asserts its contract; returns the report for further checks.
inline ContractReport check_contract(const Field& f) {
  std::string error;
  const ContractReport r = measure_contract(f, &error);
  EXPECT_TRUE(error.empty()) << error;
  if (!error.empty()) return r;
  const double grid_step = 2.0 * f.extent / ((f.dims == 3 ? 48 : 256) - 1);
  EXPECT_EQ(r.non_finite, 0u) << f.glsl;
  if (f.reference) {
    EXPECT_LT(r.worst_reference_error, 1e-5) << f.glsl;
  }
  if (f.bounded) {
    EXPECT_GT(r.surface_samples, 100u) << f.glsl << ": its surface is not in the sampled box";
  }
  // The brute-force distance overestimates by up to a grid cell's diagonal
  // (at corners and tips, where samples are sparse), so a bound may exceed it
  // only by float noise, and an exact field undershoot it by at most a diagonal.
  EXPECT_LT(r.worst_excess, 2e-5) << f.glsl << " exceeds the true distance";
  EXPECT_LT(r.worst_shortfall, grid_step * std::sqrt(f.dims)) << f.glsl << " is well below the true distance";
  EXPECT_LE(r.max_lipschitz, f.lipschitz * (1.0 + 1e-3)) << f.glsl;
  return r;
}

}  // namespace rm::test
