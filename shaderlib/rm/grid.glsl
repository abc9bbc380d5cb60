// rm/grid.glsl: an endless grid of instances, one per cell, marched cell by
// cell. A ray that misses a cell's bounding sphere crosses the cell in one
// step, and inside the sphere it sphere traces that cell's instance alone, with
// no border term to shorten its steps. examples/cubes.frag took 61 ms a frame
// before and 40 ms after, at 640x360 on llvmpipe (docs/examples.md).
// Provides: map() (from mapCell), rmCellRadius, RmGridRay, rmGridRay, rmCellExit, rmMarchGrid,
//   rmHardShadowCells.
// Needs: the scene's `float mapCell(vec3 q, vec3 cell)`: the instance of the
//   cell with integer id `cell` (as opRepeat numbers them), at q relative to
//   the cell's centre; it must lie within RM_GRID_RADIUS of the centre.
//   rm/common.glsl, rm/map.glsl and rm/march.glsl (included). rm/render.glsl
//   includes this module when RM_GRID_PERIOD is defined, and then marches
//   primary rays and hard shadows with it.
// Knobs (required): RM_GRID_PERIOD vec3, the cell size; RM_GRID_RADIUS, the
//   bounding sphere of every instance, less than half the smallest period.
//   RM_GRID_CELL_RADIUS says the scene also gives `float cellRadius(vec3 cell)`,
//   the bounding sphere of that cell's instance (at most RM_GRID_RADIUS): rays
//   cross the cells of small instances in one step more often.
//   RM_GRID_CONVEX says every instance is convex, so a shadow ray that leaves
//   one starts in the next cell. RM_GRID_MARCH 0 has rm/render.glsl march the
//   grid's map() the plain way instead, to compare.
#ifndef RM_GRID_GLSL
#define RM_GRID_GLSL

#if !defined(RM_GRID_PERIOD) || !defined(RM_GRID_RADIUS)
#error rm/grid.glsl needs RM_GRID_PERIOD (the cell size, a vec3) and RM_GRID_RADIUS (each instance's bounding sphere)
#endif

#include <rm/common.glsl>
#include <rm/map.glsl>
#include <rm/march.glsl>

// 1: rm/render.glsl marches cell by cell; 0: rmMarch and rmHardShadow on map().
#ifndef RM_GRID_MARCH
#define RM_GRID_MARCH 1
#endif

float mapCell(vec3 q, vec3 cell);

#ifdef RM_GRID_CELL_RADIUS
float cellRadius(vec3 cell);
#endif

// The bounding sphere of cell's instance: its own, or the one all share.
float rmCellRadius(vec3 cell) {
#ifdef RM_GRID_CELL_RADIUS
  return cellRadius(cell);
#else
  return RM_GRID_RADIUS;
#endif
}

// The whole grid's distance: the instance of p's cell, or less. A neighbour's
// instance lies beyond the nearest cell border by at least the gap between
// the bounding sphere and the border.
float map(vec3 p) {
  vec3 cell = round(p / RM_GRID_PERIOD);
  vec3 q = p - RM_GRID_PERIOD * cell;
  float border = rmMinComponent(0.5 * RM_GRID_PERIOD - abs(q));
  return min(mapCell(q, cell), border + 0.5 * rmMinComponent(RM_GRID_PERIOD) - RM_GRID_RADIUS);
}

// A ray's direction as the cells see it: the faces it leaves each cell by.
struct RmGridRay {
  vec3 parallel;  // 1 where a direction component is zero: that slab is never left
  vec3 inverse;   // 1 / rd, finite
  vec3 ahead;     // the faces ahead, relative to a cell's centre
};

// rd's RmGridRay.
RmGridRay rmGridRay(vec3 rd) {
  vec3 parallel = step(abs(rd), vec3(1e-30));
  return RmGridRay(parallel, 1.0 / (rd + parallel), 0.5 * RM_GRID_PERIOD * sign(rd + parallel));
}

// How far along the ray a point at q (from its cell's centre) leaves the cell.
float rmCellExit(RmGridRay ray, vec3 q) {
  return rmMinComponent(mix((ray.ahead - q) * ray.inverse, vec3(1e30), ray.parallel));
}

// rmMarch through the grid, outside objects (s.side > 0; inside, it is
// rmMarch). Every step handles one cell: past it when the ray misses its
// sphere, else one sphere-tracing step of its instance, never beyond the sphere
// or the cell. Over-relaxation (s.omega) does not apply.
RmMarch rmMarchGrid(vec3 ro, vec3 rd, RmMarchSettings s) {
  if (s.side < 0.0) return rmMarch(ro, rd, s);
  float t, tEnd;
  RmMarch miss;
  if (!rmMarchSpan(ro, rd, s, t, tEnd, miss)) return rmEndOnGround(miss);
  RmGridRay ray = rmGridRay(rd);
  float originScale = length(ro);
  int i = 0;
  if (i < s.maxSteps && !(t > tEnd)) {
    do {  // tested at the bottom (rm/common.glsl)
      vec3 p = ro + rd * t;
      vec3 cell = round(p / RM_GRID_PERIOD);
      vec3 q = p - RM_GRID_PERIOD * cell;
      float exit = rmCellExit(ray, q);
      // The ray's span through the cell's bounding sphere, from p.
      float b = dot(q, rd);
      float radius = rmCellRadius(cell);
      float h = b * b - dot(q, q) + radius * radius;
      float root = sqrt(max(h, 0.0));
      float enter = max(-b - root, 0.0), leave = -b + root;
      // Past the face by a little more than float spacing at the point, so that
      // round() puts the next point in the next cell.
      float advance = exit + 1e-4 + 1e-6 * (originScale + t);
      if (h > 0.0 && leave > 0.0 && enter < exit) {
        float d = mapCell(q + rd * enter, cell);
#ifdef RM_COUNT
        ++rmEvaluations;
#endif
        float threshold = rmHitThreshold(s, t + enter, originScale);
        if (d < threshold) {
#ifdef RM_VIEW
          rmRecordHit(t + enter);
#endif
          return RmMarch(t + enter, i + 1, RM_HIT, false, threshold);
        }
        if (enter + d < min(leave, exit)) advance = enter + d;
      }
      t += advance;
    } while (++i < s.maxSteps && !(t > tEnd));
  }
  if (t > tEnd) {
    miss.steps = i;
    return rmEndOnGround(miss);
  }
  return RmMarch(t, i, RM_OUT_OF_STEPS, false, rmHitThreshold(s, t, originScale));
}

// rmHardShadow through the grid: 0 if an instance lies on the ray ro + t rd
// for t in [tMin, tMax] (hit within 1e-4 t), else 1; at most maxSteps steps.
float rmHardShadowCells(vec3 ro, vec3 rd, float tMin, float tMax, int maxSteps) {
  RmMarchSettings s = rmMarchSettings();
  s.cone = RM_HIT_PIXELS > 0.0 ? 1e-4 / RM_HIT_PIXELS : 0.0;  // rmHitThreshold scales it back
  s.epsilon = 0.0;
  s.maxSteps = maxSteps;
  s.tMin = max(tMin, 1e-6);
  s.tMax = tMax;
#ifdef RM_GRID_CONVEX
  // A ray that leaves a convex instance never meets it again: start in the next cell.
  vec3 q = ro - RM_GRID_PERIOD * round(ro / RM_GRID_PERIOD);
  s.tMin = max(s.tMin, rmCellExit(rmGridRay(rd), q) + 1e-4 + 1e-6 * length(ro));
#endif
  return rmMarchGrid(ro, rd, s).outcome == RM_HIT ? 0.0 : 1.0;
}

#endif  // RM_GRID_GLSL
