// rm/normals.glsl: surface normals of the scene's map() from its gradient.
// Provides: rmNormalEpsilon, rmGradientTetrahedron, rmGradientCentral,
//   rmNormalTetrahedron, rmNormalCentral, rmNormalAndDistance, rmNormal.
// Needs: the scene's `float map(vec3 p)`; rm/common.glsl and rm/map.glsl
//   (included; map() calls go through rmMap, which RM_COUNT counts).
// Knobs: RM_NORMAL_EPSILON (smallest step), RM_NORMAL_TAPS (4 or 6).
// Normals are unit length; where the gradient vanishes (a sphere's centre, a
// medial point) they fall back to +y instead of NaN.
#ifndef RM_NORMALS_GLSL
#define RM_NORMALS_GLSL

#include <rm/common.glsl>
#include <rm/map.glsl>
#include <rm/quality.glsl>

// Smallest finite-difference step.
#ifndef RM_NORMAL_EPSILON
#define RM_NORMAL_EPSILON 1e-4
#endif
// 4: tetrahedron taps; 6: central differences.
#ifndef RM_NORMAL_TAPS
#define RM_NORMAL_TAPS 4
#endif
#if RM_NORMAL_TAPS != 4 && RM_NORMAL_TAPS != 6
#error RM_NORMAL_TAPS must be 4 (a tetrahedron) or 6 (central differences)
#endif


// Finite-difference step at p for a hit found within `tolerance`: it grows with
// the pixel footprint and stays far above float spacing at |p| (64 ulps).
float rmNormalEpsilon(vec3 p, float tolerance) {
  return max(max(RM_NORMAL_EPSILON, tolerance), 7.6e-6 * rmMaxComponent(abs(p)));
}

// The taps of a normal: the gradient's direction in xyz, and in w their mean,
// which is map(p) to second order in eps (the taps lie symmetrically about
// p), so that ambient occlusion needs no map(p) of its own.
// From 4 taps on a tetrahedron of half-size eps (iq's method). The taps are a
// loop, so the program holds one copy of map(), not four: llvmpipe runs every
// copy whatever the branches, and gallery's frame took 5 ms less. The loop
// starts at RM_ZERO, since Mesa unrolled it where map() is small: the copies
// made code edits of tori, cubes and optics 8 to 19 ms slower to show.
vec4 rmGradientTetrahedron(vec3 p, float eps) {
  vec4 g = vec4(0.0);
  int i = RM_ZERO;
  do {
    // The corners (1,-1,-1), (-1,-1,1), (-1,1,-1), (1,1,1) from the bits of i.
    vec3 corner = 2.0 * vec3(((i + 3) >> 1) & 1, (i >> 1) & 1, i & 1) - 1.0;
    g += vec4(corner, 0.25) * rmMap(p + corner * eps);
  } while (++i < 4);
  return g;
}

// From 6 taps of central differences with step eps.
vec4 rmGradientCentral(vec3 p, float eps) {
  const vec2 h = vec2(1.0, 0.0);
  vec3 plus = vec3(rmMap(p + h.xyy * eps), rmMap(p + h.yxy * eps), rmMap(p + h.yyx * eps));
  vec3 minus = vec3(rmMap(p - h.xyy * eps), rmMap(p - h.yxy * eps), rmMap(p - h.yyx * eps));
  return vec4(plus - minus, dot(plus + minus, vec3(1.0 / 6.0)));
}

// Normal from 4 taps on a tetrahedron of half-size eps.
vec3 rmNormalTetrahedron(vec3 p, float eps) {
  return rmSafeNormalize(rmGradientTetrahedron(p, eps).xyz, vec3(0.0, 1.0, 0.0));
}

// Normal from 6 taps of central differences with step eps.
vec3 rmNormalCentral(vec3 p, float eps) {
  return rmSafeNormalize(rmGradientCentral(p, eps).xyz, vec3(0.0, 1.0, 0.0));
}

// Normal (xyz) at a hit point p found within `tolerance` (RmMarch.tolerance),
// by the method RM_NORMAL_TAPS selects, and map(p) estimated from its taps (w).
vec4 rmNormalAndDistance(vec3 p, float tolerance) {
  float eps = rmNormalEpsilon(p, tolerance);
#if RM_NORMAL_TAPS == 6
  vec4 g = rmGradientCentral(p, eps);
#else
  vec4 g = rmGradientTetrahedron(p, eps);
#endif
  vec3 n = rmSafeNormalize(g.xyz, vec3(0.0, 1.0, 0.0));
#ifdef RM_VIEW
  rmRecordNormal(n);
#endif
  return vec4(n, g.w);
}

// Normal at a hit point p found within `tolerance` (RmMarch.tolerance), by
// the method RM_NORMAL_TAPS selects.
vec3 rmNormal(vec3 p, float tolerance) { return rmNormalAndDistance(p, tolerance).xyz; }

#endif  // RM_NORMALS_GLSL
