// rm/common.glsl: constants and small helpers the other modules share.
// Provides: RM_PI, RM_TAU, rmMaxComponent, rmMinComponent, rmDot2, rmNdot,
//   rmOrthogonalIntersection, rmSafeNormalize.
// Needs: nothing.
// Naming: sd* are signed distances, op* operators on distances or on points,
// rm* everything else; Rm* are types and RM_* macros.
#ifndef RM_COMMON_GLSL
#define RM_COMMON_GLSL

#define RM_PI 3.14159265358979
#define RM_TAU 6.28318530717959

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

#endif  // RM_COMMON_GLSL
