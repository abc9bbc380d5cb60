// rm/map.glsl: the scene's map() as the library calls it, so that a build can
// count every evaluation (primary rays, normals, shadows, AO, secondary rays).
// Provides: rmMap, and rmEvaluations when RM_COUNT is defined.
// Needs: the scene's `float map(vec3 p)` (declared here); rm/views.glsl
//   (included, for the debug views).
// Knobs: RM_COUNT (define it to count; the count is per pixel, in
//   rmEvaluations). Without it rmMap is map itself: counting costs nothing.
#ifndef RM_MAP_GLSL
#define RM_MAP_GLSL

float map(vec3 p);

#ifdef RM_COUNT
// map() evaluations so far in this pixel: the machine-independent cost.
int rmEvaluations = 0;

// The scene's distance at p, counted.
float rmMap(vec3 p) {
  ++rmEvaluations;
  return map(p);
}
#else
#define rmMap map
#endif

#include <rm/views.glsl>

#endif  // RM_MAP_GLSL
