// rm/common.glsl: constants and small helpers the other modules share.
// Provides: RM_PI, RM_TAU, RM_ZERO, rmMaxComponent, rmMinComponent, rmDot2, rmNdot,
//   rmOrthogonalIntersection, rmSafeNormalize, rmSinCosQuarter.
// Needs: nothing.
// Naming: sd* are signed distances, op* operators on distances or on points,
// rm* everything else; Rm* are types and RM_* macros.
#ifndef RM_COMMON_GLSL
#define RM_COMMON_GLSL

#define RM_PI 3.14159265358979
#define RM_TAU 6.28318530717959
// 0, but not to the compiler: a loop from RM_ZERO cannot be unrolled, so the
// program holds one copy of its body. Mesa unrolls short constant loops, and
// a copy of map() in each turn costs compile time (iq's ZERO trick). No host
// sets rm_Zero: GL gives every uniform 0 when the program links.
uniform int rm_Zero;
#define RM_ZERO rm_Zero
// The library's loops test at the bottom (do-while), behind an if where they
// may run no turn. A CPU renderer such as llvmpipe runs a loop's body until
// no lane of the group is left, and a lane that leaves by a test at the top
// costs the group one more turn with every lane masked off: one more map()
// call for nothing whenever a ray ends past its far limit or out of steps.

// Largest component of v.
float rmMaxComponent(vec2 v) { return max(v.x, v.y); }
float rmMaxComponent(vec3 v) { return max(v.x, max(v.y, v.z)); }

// Smallest component of v.
float rmMinComponent(vec2 v) { return min(v.x, v.y); }
float rmMinComponent(vec3 v) { return min(v.x, min(v.y, v.z)); }

// dot(v, v): the squared length.
float rmDot2(vec2 v) { return dot(v, v); }
float rmDot2(vec3 v) { return dot(v, v); }

// a.x * b.x - a.y * b.y, the "negative dot" of iq's rhombus.
float rmNdot(vec2 a, vec2 b) { return a.x * b.x - a.y * b.y; }

// Distance to the intersection of two regions that depend on orthogonal
// coordinates (a 2D profile and a slab, say), from their distances a and b.
// exact when a and b are.
float rmOrthogonalIntersection(float a, float b) {
  return min(max(a, b), 0.0) + length(max(vec2(a, b), 0.0));
}

// v / |v|, or `fallback` when v is too short to have a direction (no NaN).
vec3 rmSafeNormalize(vec3 v, vec3 fallback) {
  float len2 = dot(v, v);
  return len2 > 1e-30 ? v * inversesqrt(len2) : fallback;
}

// (sin a, cos a) for abs(a) <= pi/2 from their Taylor polynomials, within 4e-6;
// beyond, a is held at +-pi/2. llvmpipe computes sin() and cos() with their
// full range reduction, several times the cost of these few multiply-adds.
vec2 rmSinCosQuarter(float a) {
  a = clamp(a, -0.5 * RM_PI, 0.5 * RM_PI);
  float a2 = a * a;
  float s = a * (1.0 + a2 * (-1.0 / 6.0 + a2 * (1.0 / 120.0 + a2 * (-1.0 / 5040.0 + a2 * (1.0 / 362880.0)))));
  float c = 1.0 + a2 * (-0.5 + a2 * (1.0 / 24.0 + a2 * (-1.0 / 720.0 + a2 * (1.0 / 40320.0 + a2 * (-1.0 / 3628800.0)))));
  return vec2(s, c);
}

#endif  // RM_COMMON_GLSL
