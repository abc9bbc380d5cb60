// rm/sdf2d.glsl: signed distance functions of 2D shapes, for extrusion and
// revolution (opExtrude, opRevolve in rm/transforms.glsl) and for flat designs.
// Provides: sdCircle, sdBox, sdRoundBox, sdSegment, sdHexagon,
//   sdEquilateralTriangle, sdTrapezoid (the vec2 overloads of the sd* names).
// Needs: rm/common.glsl (included).
// Shapes sit at the origin; values are negative inside.
#ifndef RM_SDF2D_GLSL
#define RM_SDF2D_GLSL

#include <rm/common.glsl>

// Circle of radius r. exact
float sdCircle(vec2 p, float r) { return length(p) - r; }

// Rectangle with half-extents b. exact
float sdBox(vec2 p, vec2 b) {
  vec2 q = abs(p) - b;
  return rmOrthogonalIntersection(q.x, q.y);
}

// Rectangle with half-extents b and corners rounded by r (b includes r). exact
float sdRoundBox(vec2 p, vec2 b, float r) { return sdBox(p, b - r) - r; }

// Distance to the segment a-b (unsigned: zero on the segment). exact
float sdSegment(vec2 p, vec2 a, vec2 b) {
  vec2 pa = p - a, ba = b - a;
  float h = clamp(dot(pa, ba) / max(dot(ba, ba), 1e-30), 0.0, 1.0);
  return length(pa - ba * h);
}

// Regular hexagon with inradius r, flat sides at y = +-r. exact
float sdHexagon(vec2 p, float r) {
  const vec3 k = vec3(-0.866025404, 0.5, 0.577350269);  // (-cos 30, sin 30, tan 30)
  p = abs(p);
  p -= 2.0 * min(dot(k.xy, p), 0.0) * k.xy;  // fold the slanted side onto the top
  p -= vec2(clamp(p.x, -k.z * r, k.z * r), r);
  return length(p) * sign(p.y);
}

// Equilateral triangle pointing up, side 2r, centred on its centroid. exact
float sdEquilateralTriangle(vec2 p, float r) {
  const float k = 1.732050808;  // sqrt(3)
  p.x = abs(p.x) - r;
  p.y = p.y + r / k;
  if (p.x + k * p.y > 0.0) p = vec2(p.x - k * p.y, -k * p.x - p.y) / 2.0;
  p.x -= clamp(p.x, -2.0 * r, 0.0);
  return -length(p) * sign(p.y);
}

// Isosceles trapezoid: half-width r1 at y = -h, r2 at y = +h. exact
float sdTrapezoid(vec2 p, float r1, float r2, float h) {
  vec2 k1 = vec2(r2, h);
  vec2 k2 = vec2(r2 - r1, 2.0 * h);
  p.x = abs(p.x);
  vec2 ca = vec2(p.x - min(p.x, p.y < 0.0 ? r1 : r2), abs(p.y) - h);
  vec2 cb = p - k1 + k2 * clamp(dot(k1 - p, k2) / max(dot(k2, k2), 1e-30), 0.0, 1.0);
  float s = (cb.x < 0.0 && ca.y < 0.0) ? -1.0 : 1.0;
  return s * sqrt(min(dot(ca, ca), dot(cb, cb)));
}

#endif  // RM_SDF2D_GLSL
