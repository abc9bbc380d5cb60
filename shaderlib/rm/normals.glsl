// rm/normals.glsl: surface normals of the scene's map() from its gradient.
// Provides: rmNormalEpsilon, rmNormalTetrahedron, rmNormalCentral, rmNormal.
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


// Finite-difference step at p for a hit found within `tolerance`: it grows with
// the pixel footprint and stays far above float spacing at |p| (64 ulps).
float rmNormalEpsilon(vec3 p, float tolerance) {
  return max(max(RM_NORMAL_EPSILON, tolerance), 7.6e-6 * rmMaxComponent(abs(p)));
}

// Normal from 4 taps on a tetrahedron of half-size eps (iq's method). The taps
// are a loop, so the program holds one copy of map(), not four: llvmpipe runs
// every copy whatever the branches, and gallery's frame took 5 ms less.
vec3 rmNormalTetrahedron(vec3 p, float eps) {
  vec3 g = vec3(0.0);
  for (int i = 0; i < 4; ++i) {
    // The corners (1,-1,-1), (-1,-1,1), (-1,1,-1), (1,1,1) from the bits of i.
    vec3 corner = 2.0 * vec3(((i + 3) >> 1) & 1, (i >> 1) & 1, i & 1) - 1.0;
    g += corner * rmMap(p + corner * eps);
  }
  return rmSafeNormalize(g, vec3(0.0, 1.0, 0.0));
}

// Normal from 6 taps of central differences with step eps.
vec3 rmNormalCentral(vec3 p, float eps) {
  const vec2 h = vec2(1.0, 0.0);
  vec3 g = vec3(rmMap(p + h.xyy * eps) - rmMap(p - h.xyy * eps), rmMap(p + h.yxy * eps) - rmMap(p - h.yxy * eps),
                rmMap(p + h.yyx * eps) - rmMap(p - h.yyx * eps));
  return rmSafeNormalize(g, vec3(0.0, 1.0, 0.0));
}

// Normal at a hit point p found within `tolerance` (RmMarch.tolerance), by
// the method RM_NORMAL_TAPS selects.
vec3 rmNormal(vec3 p, float tolerance) {
  float eps = rmNormalEpsilon(p, tolerance);
#if RM_NORMAL_TAPS == 6
  vec3 n = rmNormalCentral(p, eps);
#else
  vec3 n = rmNormalTetrahedron(p, eps);
#endif
#ifdef RM_VIEW
  rmRecordNormal(n);
#endif
  return n;
}

#endif  // RM_NORMALS_GLSL
