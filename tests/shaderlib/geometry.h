// Double-precision distances built from geometry (segments, polygons,
// triangles, arcs), independent of the formulas shaderlib uses. They are the
// references the GPU results are held to.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

namespace rm::test::geometry {

using glm::dvec2;
using glm::dvec3;

inline double segment_distance(dvec2 p, dvec2 a, dvec2 b) {
  const dvec2 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double h = len2 > 0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - a - ab * h);
}

inline double segment_distance(dvec3 p, dvec3 a, dvec3 b) {
  const dvec3 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double h = len2 > 0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - a - ab * h);
}

// Signed distance to a simple polygon (negative inside), by edges and crossings.
inline double polygon(dvec2 p, const std::vector<dvec2>& v) {
  double d = std::numeric_limits<double>::max();
  bool inside = false;
  for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    d = std::min(d, segment_distance(p, v[j], v[i]));
    if ((v[i].y > p.y) != (v[j].y > p.y) && p.x < (v[j].x - v[i].x) * (p.y - v[i].y) / (v[j].y - v[i].y) + v[i].x)
      inside = !inside;
  }
  return inside ? -d : d;
}

// Distance from p to the triangle abc.
inline double triangle_distance(dvec3 p, dvec3 a, dvec3 b, dvec3 c) {
  const dvec3 n = glm::cross(b - a, c - a);
  const double n2 = glm::dot(n, n);
  // Inside the prism over the triangle: the distance to its plane.
  const bool over = glm::dot(glm::cross(b - a, p - a), n) >= 0 && glm::dot(glm::cross(c - b, p - b), n) >= 0 &&
                    glm::dot(glm::cross(a - c, p - c), n) >= 0;
  if (over) return std::abs(glm::dot(p - a, n)) / std::sqrt(n2);
  return std::min({segment_distance(p, a, b), segment_distance(p, b, c), segment_distance(p, c, a)});
}

// Distance from q to the arc of the circle of radius r about the origin whose
// points make an angle of at most `half_angle` with the direction `axis`.
inline double arc_distance(dvec2 q, double r, dvec2 axis, double half_angle) {
  const double len = glm::length(q);
  if (len > 0 && std::acos(std::clamp(glm::dot(q / len, axis), -1.0, 1.0)) <= half_angle) return std::abs(len - r);
  const dvec2 side(axis.y, -axis.x);
  const dvec2 end1 = r * (std::cos(half_angle) * axis + std::sin(half_angle) * side);
  const dvec2 end2 = r * (std::cos(half_angle) * axis - std::sin(half_angle) * side);
  return std::min(glm::length(q - end1), glm::length(q - end2));
}

// Distance to the intersection of regions over orthogonal coordinates.
inline double orthogonal_intersection(double a, double b) {
  return std::min(std::max(a, b), 0.0) + glm::length(glm::max(dvec2(a, b), 0.0));
}

inline double box(dvec3 p, dvec3 b) {
  const dvec3 q = glm::abs(p) - b;
  return glm::length(glm::max(q, 0.0)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0);
}

inline double box(dvec3 p, dvec3 lo, dvec3 hi) { return box(p - 0.5 * (lo + hi), 0.5 * (hi - lo)); }

// Regular hexagon with inradius r and flat sides at y = +-r.
inline std::vector<dvec2> hexagon(double r) {
  const double big = r * 2.0 / std::sqrt(3.0);
  return {{big, 0}, {big / 2, r}, {-big / 2, r}, {-big, 0}, {-big / 2, -r}, {big / 2, -r}};
}

}  // namespace rm::test::geometry

namespace rm::test::geometry {

// Signed distance to a convex polyhedron given as faces (each a convex polygon
// of 3+ vertices in order); `interior` is any point inside, to orient them.
inline double convex_polyhedron(dvec3 p, const std::vector<std::vector<dvec3>>& faces, dvec3 interior) {
  double outside = std::numeric_limits<double>::max();
  double deepest = -std::numeric_limits<double>::max();  // largest plane distance: <= 0 inside
  for (const auto& face : faces) {
    dvec3 n = glm::normalize(glm::cross(face[1] - face[0], face[2] - face[0]));
    if (glm::dot(interior - face[0], n) > 0) n = -n;
    deepest = std::max(deepest, glm::dot(p - face[0], n));
    for (size_t i = 1; i + 1 < face.size(); ++i)
      outside = std::min(outside, triangle_distance(p, face[0], face[i], face[i + 1]));
  }
  return deepest <= 0 ? deepest : outside;
}

// The convex hull of circles (centre, radius), as a polygon of many vertices:
// a 2D reference for shapes like iq's round cone.
inline std::vector<dvec2> hull_of_circles(const std::vector<std::pair<dvec2, double>>& circles) {
  std::vector<dvec2> pts;
  constexpr int kSamples = 4096;
  for (const auto& [c, r] : circles)
    for (int i = 0; i < kSamples; ++i) {
      const double a = 2.0 * M_PI * i / kSamples;
      pts.push_back(c + r * dvec2(std::cos(a), std::sin(a)));
    }
  // Andrew's monotone chain.
  std::sort(pts.begin(), pts.end(), [](dvec2 a, dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  auto turn = [](dvec2 o, dvec2 a, dvec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
  std::vector<dvec2> hull(2 * pts.size());
  size_t k = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && turn(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  for (size_t i = pts.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && turn(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k - 1);
  return hull;
}

}  // namespace rm::test::geometry
