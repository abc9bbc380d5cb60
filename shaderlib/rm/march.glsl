// rm/march.glsl: sphere tracing of the scene's map(), with a hit threshold that
// follows the pixel cone, safe over-relaxation, an optional analytic ground
// plane and optional bounding volumes; also marches inside objects.
// Provides: RM_HIT, RM_MISS, RM_OUT_OF_STEPS, RmMarchSettings, RmMarch,
//   rmMarchSettings, rmHitThresholdTerms, rmHitThreshold, rmRaySphere, rmRayBox, rmRayGround,
//   rmEndOnGround, rmMarchSpan, rmMarch, rmSurfaceOffset.
// Needs: the scene's `float map(vec3 p)` (defined by the scene; map() calls go
//   through rmMap, which RM_COUNT counts); rm/common.glsl and rm/map.glsl (included);
//   map must be a bound (Lipschitz <= 1) for the march to be safe.
// Knobs (set with #define before the include, or -D on the command line):
//   RM_MAX_STEPS, RM_MAX_DISTANCE, RM_HIT_CONE, RM_HIT_PIXELS, RM_HIT_EPSILON, RM_OMEGA.
#ifndef RM_MARCH_GLSL
#define RM_MARCH_GLSL

#include <rm/common.glsl>
#include <rm/map.glsl>
#include <rm/quality.glsl>

// Most map() evaluations per ray.
#ifndef RM_MAX_STEPS
#define RM_MAX_STEPS 160
#endif
// Farthest distance along a ray.
#ifndef RM_MAX_DISTANCE
#define RM_MAX_DISTANCE 100.0
#endif
// Hit threshold per unit of t: half a pixel's footprint (see rmPixelCone).
#ifndef RM_HIT_CONE
#define RM_HIT_CONE 1e-3
#endif
// Hit threshold in half-pixel footprints: every march scales its cone by this;
// 0 leaves only RM_HIT_EPSILON, a fixed absolute threshold.
#ifndef RM_HIT_PIXELS
#define RM_HIT_PIXELS 1.0
#endif
// Smallest hit threshold, near the camera.
#ifndef RM_HIT_EPSILON
#define RM_HIT_EPSILON 1e-4
#endif
// Over-relaxation factor: 1 is plain sphere tracing. 1.2 saved 16% of the map()
// calls in a view with a floor, but with a cheap map() the extra work per step
// cost more time than it saved (docs/shaderlib.md), so it is opt-in.
#ifndef RM_OMEGA
#define RM_OMEGA 1.0
#endif


// Outcomes of a march.
const int RM_HIT = 0;           // map() fell below the threshold
const int RM_MISS = 1;          // the ray left [tMin, tMax] or the bounds
const int RM_OUT_OF_STEPS = 2;  // maxSteps ran out first

// How rmMarch marches; rmMarchSettings() gives the defaults from the knobs.
struct RmMarchSettings {
  float tMin;          // where the ray starts
  float tMax;          // where it gives up
  int maxSteps;        // most map() evaluations
  float cone;          // hit threshold per unit t (pixel cone)
  float epsilon;       // smallest hit threshold
  float omega;         // over-relaxation, >= 1
  float side;          // +1 marches outside objects, -1 inside (refraction)
  bool ground;         // also intersect the plane y = groundHeight analytically
  float groundHeight;  // (the ground must then not be part of map())
  vec4 boundSphere;    // xyz centre, w radius; all of map()'s surface lies inside; w <= 0: none
  bool boundBox;       // all of map()'s surface lies in [boundMin, boundMax]
  vec3 boundMin;
  vec3 boundMax;
};

// What rmMarch found.
struct RmMarch {
  float t;          // distance along the ray (of the hit, or where the march stopped)
  int steps;        // map() evaluations spent
  int outcome;      // RM_HIT, RM_MISS or RM_OUT_OF_STEPS
  bool ground;      // the hit is on the analytic ground plane
  float tolerance;  // how far off the surface the hit point may be
};

// Settings from the RM_* knobs: outside, no ground plane, no bounds.
RmMarchSettings rmMarchSettings() {
  return RmMarchSettings(0.0, RM_MAX_DISTANCE, RM_MAX_STEPS, RM_HIT_CONE, RM_HIT_EPSILON, RM_OMEGA, 1.0,
                         false, 0.0, vec4(0.0), false, vec3(0.0), vec3(0.0));
}

// rmHitThreshold at t is max(x, y t) of these: its floor and its growth per unit of t.
vec2 rmHitThresholdTerms(RmMarchSettings s, float originScale) {
  return vec2(max(s.epsilon, 4.8e-7 * originScale), s.cone * RM_HIT_PIXELS + 4.8e-7);
}

// Hit threshold at distance t along a ray from ro: the pixel cone, but never
// below epsilon nor below a few float steps at the point's magnitude
// (|ro| + t bounds it). Written so the part that depends on t is one multiply.
float rmHitThreshold(RmMarchSettings s, float t, float originScale) {
  vec2 terms = rmHitThresholdTerms(s, originScale);
  return max(terms.x, terms.y * t);
}

// Entry and exit distances of a ray (unit rd) through a sphere; x > y if it misses.
vec2 rmRaySphere(vec3 ro, vec3 rd, vec3 centre, float radius) {
  vec3 oc = ro - centre;
  float b = dot(oc, rd);
  float h = b * b - (dot(oc, oc) - radius * radius);
  if (h < 0.0) return vec2(1.0, -1.0);
  h = sqrt(h);
  return vec2(-b - h, -b + h);
}

// Entry and exit distances of a ray through the box [lo, hi]; x > y if it
// misses. A zero direction component with the origin on a face gives no NaN.
vec2 rmRayBox(vec3 ro, vec3 rd, vec3 lo, vec3 hi) {
  // A ray parallel to a slab (a zero component) never crosses it: it lies in
  // the closed slab for every t, or for none. Dividing by zero instead gives
  // inf, and inf * 0 (origin on the face) NaN.
  vec3 parallel = step(abs(rd), vec3(1e-30));
  vec3 inv = 1.0 / (rd + parallel);
  vec3 t0 = (lo - ro) * inv, t1 = (hi - ro) * inv;
  vec3 inside = step(lo, ro) * step(ro, hi);
  vec3 near = mix(min(t0, t1), mix(vec3(1e30), vec3(-1e30), inside), parallel);
  vec3 far = mix(max(t0, t1), mix(vec3(-1e30), vec3(1e30), inside), parallel);
  return vec2(rmMaxComponent(near), rmMinComponent(far));
}

// Distance to the plane y = height along the ray, or -1 if the ray never gets
// there from above (parallel rays, rd.y == 0, included).
float rmRayGround(vec3 ro, vec3 rd, float height) {
  float above = ro.y - height;
  if (above < 0.0 || rd.y >= 0.0) return -1.0;
  return above / -rd.y;
}

// The march's result when the ray leaves map()'s range: a hit on the ground
// (recorded for the debug views) or a miss.
RmMarch rmEndOnGround(RmMarch m) {
#ifdef RM_VIEW
  if (m.ground) rmRecordHit(m.t);
#endif
  return m;
}

// Where a march of ro + t rd through map() starts (t) and gives up (tEnd),
// after the analytic ground and the bounds, and what it returns when map() has
// nothing in between (`miss`: a hit on the ground, or a miss). False when the
// ray misses the bounds: `miss` is then the answer at once.
bool rmMarchSpan(vec3 ro, vec3 rd, RmMarchSettings s, out float t, out float tEnd, out RmMarch miss) {
  tEnd = s.tMax;
  float tGround = s.ground ? rmRayGround(ro, rd, s.groundHeight) : -1.0;
  bool groundAhead = tGround >= s.tMin && tGround <= s.tMax;
  if (groundAhead) tEnd = tGround;
  // A miss of everything in map() is a hit on the ground, if there is one.
  miss = RmMarch(tEnd, 0, groundAhead ? RM_HIT : RM_MISS, groundAhead, rmHitThreshold(s, tEnd, length(ro)));
  t = s.tMin;
  if (s.boundSphere.w > 0.0) {
    vec2 span = rmRaySphere(ro, rd, s.boundSphere.xyz, s.boundSphere.w);
    if (span.x > span.y || span.y < t) return false;
    t = max(t, span.x);
    tEnd = min(tEnd, span.y);
  }
  if (s.boundBox) {
    vec2 span = rmRayBox(ro, rd, s.boundMin, s.boundMax);
    if (span.x > span.y || span.y < t) return false;
    t = max(t, span.x);
    tEnd = min(tEnd, span.y);
  }
  return true;
}

// Sphere traces the ray ro + t rd (rd unit) through map(). With omega > 1 each
// step is stretched by omega; when the stretched step overshoots (the unbounding
// spheres of two steps stop overlapping), it goes back to the plain step and
// continues with omega = 1, so it never tunnels through a surface.
RmMarch rmMarch(vec3 ro, vec3 rd, RmMarchSettings s) {
  float t, tEnd;
  RmMarch miss;
  if (!rmMarchSpan(ro, rd, s, t, tEnd, miss)) return rmEndOnGround(miss);

  float originScale = length(ro);
  int skipped = 0;  // steps on mapBound, which count toward s.maxSteps but are no map() calls
#ifdef RM_MAP_BOUND
  // Outside objects, cross the open space on the scene's cheap bound.
  if (s.side > 0.0) {
    vec2 threshold = rmHitThresholdTerms(s, originScale);
    vec2 open = rmSkipOpenSpace(ro, rd, t, tEnd, threshold.x, threshold.y, 1.0, 1e30, s.maxSteps, skipped);
    t = open.x;
    if (open.y < 1.0) {  // a cheap part within the threshold: map(), no larger, would only agree
#ifdef RM_VIEW
      rmRecordHit(t);
#endif
      return RmMarch(t, 0, RM_HIT, false, rmHitThreshold(s, t, originScale));
    }
  }
#endif
  float omega = s.omega;
  float previousD = 0.0;  // distance at the last accepted point
  float stepLength = 0.0;
  int i = skipped;
  if (i < s.maxSteps && !(t > tEnd)) {
    do {  // tested at the bottom (rm/common.glsl)
      float d = s.side * rmMap(ro + rd * t);
      if (omega > 1.0 && stepLength > 0.0 && d + previousD < stepLength) {
        // Overshot: the plain step (previousD) was safe, the stretched one may not be.
        t -= stepLength - previousD;
        omega = 1.0;
        stepLength = 0.0;
        continue;
      }
      float threshold = rmHitThreshold(s, t, originScale);
      if (d < threshold) {
#ifdef RM_VIEW
        rmRecordHit(t);
#endif
        return RmMarch(t, i + 1 - skipped, RM_HIT, false, threshold);
      }
      previousD = d;
      stepLength = omega * d;
      t += stepLength;
    } while (++i < s.maxSteps && !(t > tEnd));
  }
  if (t > tEnd) {
    miss.steps = i - skipped;
    return rmEndOnGround(miss);
  }
  return RmMarch(t, i - skipped, RM_OUT_OF_STEPS, false, rmHitThreshold(s, t, originScale));
}

// rmMarch with the default settings.
RmMarch rmMarch(vec3 ro, vec3 rd) { return rmMarch(ro, rd, rmMarchSettings()); }

// How far a secondary ray must start from a hit point p, which may lie up to
// `tolerance` off the surface, so that it does not hit its own surface.
float rmSurfaceOffset(vec3 p, float tolerance) {
  return 2.0 * tolerance + 1e-6 * rmMaxComponent(abs(p));
}

#endif  // RM_MARCH_GLSL
