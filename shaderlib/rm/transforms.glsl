// rm/transforms.glsl: domain operations. They map the query point p (op*
// returning a point) or a distance (op* returning a float) so that a primitive
// can be moved, turned, scaled, mirrored, repeated and deformed.
// Provides: opTranslate, rmRotation2SinCos, rmRotation2, rmRotationX, rmRotationY,
//   rmRotationZ, rmRotationAxis, opRotate, opRotateAxis, opScale, opScaleDistance, opMirror, opSymmetryX,
//   opSymmetryXZ, opRepeat, opRepeatBorder, opRepeatLimited, opRepeatPolar, opRepeatPolarMirror,
//   opTwist, opTwistQuarter, opTwistLipschitz, opBend, opBendLipschitz, opElongate, opRound, opOnion,
//   opExtrude, opRevolve.
// Needs: rm/common.glsl (included).
// Classes: each op states what it does to its input's class. Rigid motions
// keep it. Twist and bend stretch space: their field has Lipschitz constant L
// (opTwistLipschitz, opBendLipschitz), so divide the distance by L to get a bound.
#ifndef RM_TRANSFORMS_GLSL
#define RM_TRANSFORMS_GLSL

#include <rm/common.glsl>

// Point for a shape moved by offset: sd(opTranslate(p, offset)). keeps the class
vec3 opTranslate(vec3 p, vec3 offset) { return p - offset; }

// 2D rotation by the angle whose sine and cosine are sinCos.x and sinCos.y
// (counter-clockwise), for callers that have them without sin() and cos().
mat2 rmRotation2SinCos(vec2 sinCos) { return mat2(sinCos.y, sinCos.x, -sinCos.x, sinCos.y); }

// 2D rotation by angle a (radians, counter-clockwise): p.xz = rmRotation2(a) * p.xz.
mat2 rmRotation2(float a) { return rmRotation2SinCos(vec2(sin(a), cos(a))); }

// Rotation by a radians about +x (right-handed: y turns toward z).
mat3 rmRotationX(float a) {
  float c = cos(a), s = sin(a);
  return mat3(1.0, 0.0, 0.0, 0.0, c, s, 0.0, -s, c);
}

// Rotation by a radians about +y (right-handed: z turns toward x).
mat3 rmRotationY(float a) {
  float c = cos(a), s = sin(a);
  return mat3(c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c);
}

// Rotation by a radians about +z (right-handed: x turns toward y).
mat3 rmRotationZ(float a) {
  float c = cos(a), s = sin(a);
  return mat3(c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0);
}

// Rotation by a radians about any axis (normalised here; a zero axis gives identity).
mat3 rmRotationAxis(vec3 axis, float a) {
  if (dot(axis, axis) < 1e-30) return mat3(1.0);
  vec3 u = normalize(axis);
  float c = cos(a), s = sin(a);
  // Rodrigues: c I + s [u]x + (1 - c) u u^T, column by column.
  return mat3(c + u.x * u.x * (1.0 - c), u.y * u.x * (1.0 - c) + u.z * s, u.z * u.x * (1.0 - c) - u.y * s,
              u.x * u.y * (1.0 - c) - u.z * s, c + u.y * u.y * (1.0 - c), u.z * u.y * (1.0 - c) + u.x * s,
              u.x * u.z * (1.0 - c) + u.y * s, u.y * u.z * (1.0 - c) - u.x * s, c + u.z * u.z * (1.0 - c));
}

// Point for a shape turned by the rotation matrix r: sd(opRotate(p, r)). keeps the class
vec3 opRotate(vec3 p, mat3 r) { return p * r; }  // p * r == transpose(r) * p == inverse(r) * p

// opRotate(p, rmRotationAxis(axis, a)) without the matrix: Rodrigues on the
// point. Where the rotation changes from call to call (a turn per instance
// of a grid, say), this is the cheaper: cubes.frag took 40.0 ms a frame at
// 640x360 with the matrix built in every map() call, 38.5 with this. keeps the class
vec3 opRotateAxis(vec3 p, vec3 axis, float a) {
  if (dot(axis, axis) < 1e-30) return p;
  vec3 u = normalize(axis);
  float c = cos(a), s = sin(a);
  return p * c - cross(u, p) * s + u * (dot(u, p) * (1.0 - c));  // turned by -a: the shape by +a
}

// Point for a shape scaled by s > 0; multiply its distance by s with opScaleDistance.
vec3 opScale(vec3 p, float s) { return p / s; }

// Distance correction of opScale: opScaleDistance(sd(opScale(p, s)), s). keeps the class
float opScaleDistance(float d, float s) { return d * s; }

// Folds the space behind the plane through the origin with unit normal n onto
// its front: the shape's front half and its mirror image. exact for shapes in front, else bound
vec3 opMirror(vec3 p, vec3 n) { return p - 2.0 * min(dot(p, n), 0.0) * n; }

// Mirror symmetry across x = 0 (the shape's x >= 0 half, doubled). as opMirror
vec3 opSymmetryX(vec3 p) { return vec3(abs(p.x), p.yz); }

// Mirror symmetry across x = 0 and z = 0 (four copies). as opMirror
vec3 opSymmetryXZ(vec3 p) { return vec3(abs(p.x), p.y, abs(p.z)); }

// Infinite repetition with the given period per axis; cell gets the integer
// cell id, and the result is the point in the cell's frame (centred on it).
// The round() form keeps the local point exact far from the origin, unlike mod().
// exact for instances that fit their cell and are mirror-symmetric in it, else check neighbours
vec3 opRepeat(vec3 p, vec3 period, out vec3 cell) {
  cell = round(p / period);
  return p - period * cell;
}

// Distance from a repeated point (opRepeat's result) to its cell's border.
// Instances that are not mirror-symmetric in their cell (turned by their own
// hash, say) keep a bound with min(d, opRepeatBorder(q, period) + gap), where
// gap is the least distance from any cell border to its instance.
float opRepeatBorder(vec3 q, vec3 period) { return rmMinComponent(0.5 * period - abs(q)); }

// Repetition limited to the cells lo..hi (integer ids, per axis). as opRepeat
vec3 opRepeatLimited(vec3 p, vec3 period, vec3 lo, vec3 hi, out vec3 cell) {
  cell = clamp(round(p / period), lo, hi);
  return p - period * cell;
}

// n copies around the origin in 2D (apply to p.xz for copies around y); cell
// gets the copy's index 0..n-1; the copy at angle 0 sits on +x. as opRepeat
vec2 opRepeatPolar(vec2 p, float n, out float cell) {
  cell = 0.0;
  if (dot(p, p) == 0.0) return p;  // atan(0, 0) is undefined in GLSL
  float sector = RM_TAU / n;
  float k = round(atan(p.y, p.x) / sector);
  cell = mod(k, n);
  return rmRotation2(-k * sector) * p;
}

// opRepeatPolar for a shape that is mirror-symmetric about its copy's axis (+x
// for the copy at angle 0), with n a power of two: mirrors fold p into the
// wedge 0 <= angle <= pi / n, without the atan, sin and cos that make most of
// opRepeatPolar's cost on a CPU renderer. Other n fold too few times. as opRepeat
vec2 opRepeatPolarMirror(vec2 p, int n) {
  p.y = abs(p.y);
  int j = 1;
  if (j <= findMSB(n)) {
    do {  // a count, not a doubling: compilers unroll it; tested at the bottom (rm/common.glsl)
      float a = RM_PI / float(1 << j);  // the mirror's angle: a constant when n is
      vec2 mirrorNormal = vec2(-sin(a), cos(a));
      p -= 2.0 * max(dot(p, mirrorNormal), 0.0) * mirrorNormal;
    } while (++j <= findMSB(n));
  }
  return p;
}

// Twist about y: turns the xz plane by k radians per unit of y.
// approximate, Lipschitz opTwistLipschitz(k, r)
vec3 opTwist(vec3 p, float k) { return vec3(rmRotation2(k * p.y) * p.xz, p.y).xzy; }

// opTwist for a shape that turns at most a quarter turn either way
// (abs(k y) <= pi/2 over its height): the same there, within 4e-6, and turned
// by a quarter turn beyond, a field as continuous as opTwist's with at most
// its Lipschitz constant. Its sine and cosine are polynomials
// (rmSinCosQuarter), which llvmpipe evaluates far faster than sin() and cos():
// gallery's twist took 1.1 ms less of a 32.5 ms frame.
// approximate, Lipschitz opTwistLipschitz(k, r)
vec3 opTwistQuarter(vec3 p, float k) {
  return vec3(rmRotation2SinCos(rmSinCosQuarter(k * p.y)) * p.xz, p.y).xzy;
}

// Lipschitz constant of opTwist(p, k) where the field is evaluated within distance
// r of the y axis (the stretch grows with the distance, so take the larger of the
// shape's radius and the query point's). Use it inside a tight bounding volume
// within radius r, and outside step by the distance to that volume.
float opTwistLipschitz(float k, float r) {
  float a = abs(k) * r;  // largest singular value of the twist's Jacobian
  return 0.5 * (a + sqrt(a * a + 4.0));
}

// Bend in the xy plane: turns xy by k radians per unit of x.
// approximate, Lipschitz opBendLipschitz(k, r)
vec3 opBend(vec3 p, float k) { return vec3(rmRotation2(k * p.x) * p.xy, p.z); }

// Lipschitz constant of opBend(p, k) where the field is evaluated within distance r
// of the origin in xy (as for opTwistLipschitz).
float opBendLipschitz(float k, float r) { return 1.0 + abs(k) * r; }

// Point for a shape stretched by h along each axis (its centre becomes a box of
// half-size h). exact outside, bound inside
vec3 opElongate(vec3 p, vec3 h) { return p - clamp(p, -h, h); }

// Rounds a shape by r (it grows by r). exact outside for an exact d
float opRound(float d, float r) { return d - r; }

// Hollows a shape into a shell of half-thickness t. keeps exact
float opOnion(float d, float t) { return abs(d) - t; }

// Extrudes a 2D distance d2 = sd(p.xy) along z to half-length h. keeps exact
float opExtrude(vec3 p, float d2, float h) { return rmOrthogonalIntersection(d2, abs(p.z) - h); }

// Point for revolving a 2D shape around y: sd2(opRevolve(p, offset)), with the
// profile's x measured from a circle of radius offset. keeps exact
vec2 opRevolve(vec3 p, float offset) { return vec2(length(p.xz) - offset, p.y); }

#endif  // RM_TRANSFORMS_GLSL
