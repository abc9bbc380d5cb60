// rm/sdf.glsl: signed distance functions of 3D primitives, in iq's sd* names.
// Provides: sdSphere, sdBox, sdRoundBox, sdBoxFrame, sdPlane, sdTorus,
//   sdCappedTorus, sdLink, sdCapsule, sdVerticalCapsule, sdInfiniteCylinder,
//   sdCappedCylinder, sdRoundedCylinder, sdCappedCone, sdRoundCone,
//   sdSolidAngle, sdCutSphere, sdCutHollowSphere, sdEllipsoid, sdOctahedron,
//   sdPyramid, sdHexPrism, sdTriPrism, sdRhombus.
// Needs: rm/common.glsl and rm/sdf2d.glsl (included).
// Shapes sit at the origin; move, turn and scale them with rm/transforms.glsl.
// Values are negative inside. Each function names its distance class:
//   exact: the Euclidean distance to the surface;
//   bound: never more than the true distance (Lipschitz <= 1);
//   "exact outside" shapes are exact for d > 0 and a bound inside.
// Degenerate parameters (zero sizes, a == b) give finite values, never NaN.
#ifndef RM_SDF_GLSL
#define RM_SDF_GLSL

#include <rm/common.glsl>
#include <rm/sdf2d.glsl>

// Sphere of radius r. exact
float sdSphere(vec3 p, float r) { return length(p) - r; }

// Box with half-extents b. exact
float sdBox(vec3 p, vec3 b) {
  vec3 q = abs(p) - b;
  return length(max(q, 0.0)) + min(rmMaxComponent(q), 0.0);
}

// Box with half-extents b whose edges are rounded by r (b includes r). exact
float sdRoundBox(vec3 p, vec3 b, float r) { return sdBox(p, b - r) - r; }

// The edges of a box with half-extents b, as bars of half-thickness e. exact outside
float sdBoxFrame(vec3 p, vec3 b, float e) {
  p = abs(p) - b;
  vec3 q = abs(p + e) - e;
  // Each bar is a box in the frame's corner coordinates; the frame is their union.
  float x = length(max(vec3(p.x, q.y, q.z), 0.0)) + min(max(p.x, max(q.y, q.z)), 0.0);
  float y = length(max(vec3(q.x, p.y, q.z), 0.0)) + min(max(q.x, max(p.y, q.z)), 0.0);
  float z = length(max(vec3(q.x, q.y, p.z), 0.0)) + min(max(q.x, max(q.y, p.z)), 0.0);
  return min(x, min(y, z));
}

// Plane with unit normal n, moved by h along n (p.y + h for n = +y). exact for unit n
float sdPlane(vec3 p, vec3 n, float h) { return dot(p, n) + h; }

// Torus in the xz plane: t.x ring radius, t.y tube radius. exact
float sdTorus(vec3 p, vec2 t) { return length(vec2(length(p.xz) - t.x, p.y)) - t.y; }

// Part of a torus in the xy plane, symmetric about +y: sc = (sin, cos) of the half
// opening angle, ra ring radius, rb tube radius. exact
float sdCappedTorus(vec3 p, vec2 sc, float ra, float rb) {
  p.x = abs(p.x);
  float k = (sc.y * p.x > sc.x * p.y) ? dot(p.xy, sc) : length(p.xy);
  // |p - ra * ringPoint|^2, clamped because rounding can push it just below zero.
  return sqrt(max(dot(p, p) + ra * ra - 2.0 * ra * k, 0.0)) - rb;
}

// Chain link along y: straight half-length le, ring radius r1, tube radius r2. exact
float sdLink(vec3 p, float le, float r1, float r2) {
  vec3 q = vec3(p.x, max(abs(p.y) - le, 0.0), p.z);
  return length(vec2(length(q.xy) - r1, q.z)) - r2;
}

// Capsule: the segment a-b swept by radius r (a == b gives a sphere). exact
float sdCapsule(vec3 p, vec3 a, vec3 b, float r) {
  vec3 pa = p - a, ba = b - a;
  float h = clamp(dot(pa, ba) / max(dot(ba, ba), 1e-30), 0.0, 1.0);
  return length(pa - ba * h) - r;
}

// Capsule along y from y = 0 to y = h with radius r. exact
float sdVerticalCapsule(vec3 p, float h, float r) {
  p.y -= clamp(p.y, 0.0, h);
  return length(p) - r;
}

// Infinite cylinder along y through (c.x, *, c.y) with radius c.z. exact
float sdInfiniteCylinder(vec3 p, vec3 c) { return length(p.xz - c.xy) - c.z; }

// Cylinder along y: radius r, half-height h. exact
float sdCappedCylinder(vec3 p, float r, float h) {
  return sdBox(vec2(length(p.xz), p.y), vec2(r, h));
}

// Cylinder along y with rounded rims: radius r, half-height h, rim radius rr. exact
float sdRoundedCylinder(vec3 p, float r, float h, float rr) {
  return sdBox(vec2(length(p.xz), p.y), vec2(r, h) - rr) - rr;
}

// Cone frustum along y from y = -h (radius r1) to y = +h (radius r2). exact
float sdCappedCone(vec3 p, float h, float r1, float r2) {
  return sdTrapezoid(vec2(length(p.xz), p.y), r1, r2, h);
}

// Two spheres joined by their tangent cone: radius r1 at y = 0, r2 at y = h
// (when |r1 - r2| >= h the larger sphere swallows the smaller). exact
float sdRoundCone(vec3 p, float r1, float r2, float h) {
  h = max(h, 1e-30);
  float b = (r1 - r2) / h;
  if (abs(b) >= 1.0) return min(length(p) - r1, length(p - vec3(0.0, h, 0.0)) - r2);
  float a = sqrt(1.0 - b * b);
  vec2 q = vec2(length(p.xz), p.y);
  float k = dot(q, vec2(-b, a));
  // The bottom sphere, the top one or the cone between them, by where q
  // projects: selects, as CPU renderers run every branch anyway.
  return k < 0.0 ? length(q) - r1 : k > a * h ? length(q - vec2(0.0, h)) - r2 : dot(q, vec2(a, b)) - r1;
}

// Ball of radius ra cut to the cone of half-angle with sc = (sin, cos) around +y. exact
float sdSolidAngle(vec3 p, vec2 sc, float ra) {
  vec2 q = vec2(length(p.xz), p.y);
  float l = length(q) - ra;
  float m = length(q - sc * clamp(dot(q, sc), 0.0, ra));
  return max(l, m * sign(sc.y * q.x - sc.x * q.y));
}

// Sphere of radius r with everything below y = h cut away (-r < h < r). exact
float sdCutSphere(vec3 p, float r, float h) {
  float w = sqrt(max(r * r - h * h, 0.0));  // radius of the cut disc
  vec2 q = vec2(length(p.xz), p.y);
  float s = max((h - r) * q.x * q.x + w * w * (h + r - 2.0 * q.y), h * q.x - w * q.y);
  return (s < 0.0) ? length(q) - r : (q.x < w) ? h - q.y : length(q - vec2(w, h));
}

// Spherical shell of radius r and half-thickness t, cut at y = h (kept below). exact
float sdCutHollowSphere(vec3 p, float r, float h, float t) {
  float w = sqrt(max(r * r - h * h, 0.0));
  vec2 q = vec2(length(p.xz), p.y);
  return ((h * q.x < w * q.y) ? length(q - vec2(w, h)) : abs(length(q) - r)) - t;
}

// Ellipsoid with semi-axes r. bound (exact on the surface and at the centre)
float sdEllipsoid(vec3 p, vec3 r) {
  float k0 = length(p / r);
  // Inside, the distance scaled by the smallest axis is a safe bound and has no
  // 0/0 at the centre. Outside, iq's k0 (k0 - 1) / k1 is a tighter bound.
  if (k0 < 1.0) return (k0 - 1.0) * rmMinComponent(r);
  float k1 = length(p / (r * r));
  return k0 * (k0 - 1.0) / k1;
}

// Regular octahedron with vertices at distance s on the axes. exact
float sdOctahedron(vec3 p, float s) {
  p = abs(p);
  float m = p.x + p.y + p.z - s;
  // The nearest feature is the face when no coordinate is below m / 3, else the
  // edge or vertex in the first such coordinate's sector. Selects, not
  // branches: a CPU renderer runs every branch anyway.
  vec3 q = 3.0 * p.x < m ? p.xyz : 3.0 * p.y < m ? p.yzx : p.zxy;
  float k = clamp(0.5 * (q.z - q.y + s), 0.0, s);
  float edge = length(vec3(q.x, q.y - s + k, q.z - k));
  return 3.0 * rmMinComponent(p) < m ? edge : m * 0.57735027;
}

// Square pyramid: unit base (half-side 0.5) on y = 0, apex at height h. exact
float sdPyramid(vec3 p, float h) {
  float m2 = h * h + 0.25;
  p.xz = abs(p.xz);  // fold into one quadrant, then onto the face nearer +x
  p.xz = (p.z > p.x) ? p.zx : p.xz;
  p.xz -= 0.5;
  // Below the base the nearest point is on the base square. (iq's published
  // form lacks this and the interior base test below; the contract test caught both.)
  if (p.y < 0.0) return length(vec3(max(p.x, 0.0), p.y, max(p.z, 0.0)));
  vec3 q = vec3(p.z, h * p.y - 0.5 * p.x, h * p.x + 0.5 * p.y);
  float s = max(-q.x, 0.0);
  float t = clamp((q.y - 0.5 * p.z) / (m2 + 0.25), 0.0, 1.0);
  float a = m2 * (q.x + s) * (q.x + s) + q.y * q.y;
  float b = m2 * (q.x + 0.5 * t) * (q.x + 0.5 * t) + (q.y - m2 * t) * (q.y - m2 * t);
  float d2 = min(q.y, -q.x * m2 - q.y * 0.5) > 0.0 ? 0.0 : min(a, b);
  float d = sqrt((d2 + q.z * q.z) / m2) * sign(max(q.z, -p.y));
  // Inside, the base plane may be nearer than any slanted face.
  return d < 0.0 ? max(d, -p.y) : d;
}

// Hexagonal prism along z: h.x inradius of the hexagon, h.y half-length. exact
float sdHexPrism(vec3 p, vec2 h) {
  return rmOrthogonalIntersection(sdHexagon(p.xy, h.x), abs(p.z) - h.y);
}

// Triangular prism along z: h.x inradius-like size of the equilateral triangle
// (iq's convention), h.y half-length. bound
float sdTriPrism(vec3 p, vec2 h) {
  vec3 q = abs(p);
  return max(q.z - h.y, max(q.x * 0.866025 + p.y * 0.5, -p.y) - h.x * 0.5);
}

// Rhombus slab in xz: half-diagonals la (x) and lb (z), half-thickness h,
// corner rounding ra. exact
float sdRhombus(vec3 p, float la, float lb, float h, float ra) {
  p = abs(p);
  vec2 b = vec2(la, lb);
  float f = clamp(rmNdot(b, b - 2.0 * p.xz) / dot(b, b), -1.0, 1.0);
  vec2 q = vec2(length(p.xz - 0.5 * b * vec2(1.0 - f, 1.0 + f)) *
                    sign(p.x * b.y + p.z * b.x - b.x * b.y) - ra,
                p.y - h);
  return rmOrthogonalIntersection(q.x, q.y);
}

#endif  // RM_SDF_GLSL
