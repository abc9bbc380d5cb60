// rm/map.glsl: the scene's map() as the library calls it, so that a build can
// count every evaluation (primary rays, normals, shadows, AO, secondary rays).
// Provides: rmMap, rmEvaluations when RM_COUNT is defined, and rmMapBound,
//   rmSkipOpenSpace (and rmBoundEvaluations with RM_COUNT) when RM_MAP_BOUND is.
// Needs: the scene's `float map(vec3 p)` (declared here); rm/views.glsl
//   (included, for the debug views); with RM_MAP_BOUND the scene's
//   `vec2 mapBound(vec3 p)`.
// Knobs: RM_COUNT (define it to count; the count is per pixel, in
//   rmEvaluations). Without it rmMap is map itself: counting costs nothing.
//   RM_MAP_BOUND: the scene also gives vec2 mapBound(p): x the distance to its
//   cheap parts, as map() gives it, and y a distance that never exceeds the
//   one to the rest (bounding volumes of its costly parts). The march, the
//   shadow rays and AO cross open space and pass the cheap parts with it, and
//   call map() only where y says a costly part is near (examples/gallery.frag).
//   A CPU renderer such as llvmpipe runs every branch of map() for every
//   pixel, so an `if` around a costly part saves nothing there; a shorter
//   loop does.
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

#ifdef RM_MAP_BOUND
vec2 mapBound(vec3 p);  // the scene defines it: RM_MAP_BOUND says it does

#ifdef RM_COUNT
// mapBound() evaluations so far in this pixel: the work a bounded scene does
// besides its map() calls (the accuracy command reports both).
int rmBoundEvaluations = 0;

// The scene's mapBound at p, counted.
vec2 rmMapBound(vec3 p) {
  ++rmBoundEvaluations;
  return mapBound(p);
}
#else
#define rmMapBound mapBound
#endif

// Marches ro + t rd from t toward tEnd on mapBound() alone while map() is not
// needed: while the costly parts stay farther than near = max(nearMin,
// nearPerT * t), and the cheap parts farther than cheapStop * near. Steps are
// at most maxStep, at most maxSteps of them. Returns where it stopped and the
// least (cheap distance / near) on the way: with cheapStop < 1 the caller
// walks past the cheap parts and learns how close it came (a penumbra).
// `steps` gets the steps taken, which the caller's own limit includes: a ray
// that creeps along a cheap part must not then get a fresh limit of map()
// calls. Bound steps are not map() calls: RM_COUNT counts them apart, in
// rmBoundEvaluations.
vec2 rmSkipOpenSpace(vec3 ro, vec3 rd, float t, float tEnd, float nearMin, float nearPerT, float cheapStop,
                     float maxStep, int maxSteps, out int steps) {
  float closest = 1e30;
  steps = 0;
  if (steps < maxSteps && t < tEnd) {
    do {  // tested at the bottom (rm/common.glsl)
      vec2 h = rmMapBound(ro + rd * t);
      float near = max(nearMin, nearPerT * t);
      closest = min(closest, h.x / near);
      if (h.y < near || h.x < cheapStop * near) break;
      t += min(min(h.x, h.y), maxStep);
    } while (++steps < maxSteps && t < tEnd);
  }
  return vec2(t, closest);
}
#endif

#include <rm/views.glsl>

#endif  // RM_MAP_GLSL
