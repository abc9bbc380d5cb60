// rm/views.glsl: the debug views of `raymarching render --view` and the
// window's V key. The host defines RM_VIEW (and RM_COUNT for steps); the
// march and the normals then record the primary hit, and the host's main()
// turns the pixel into the view with rmView.
// Provides: RM_VIEW_STEPS, RM_VIEW_NORMALS, RM_VIEW_DEPTH, RM_VIEW_NAN,
//   RM_VIEW_DATA, and with RM_VIEW: rmRecordHit, rmRecordNormal, rmHeat, rmView.
// Needs: rmEvaluations (and rmBoundEvaluations) from rm/map.glsl (RM_COUNT)
//   for the steps and data views; it is included by rm/map.glsl, after the counters.
// Knobs: RM_VIEW_STEPS_SCALE (map() calls shown as white, default 256),
//   RM_VIEW_DEPTH_SCALE (the distance shown as black, default 100).
#ifndef RM_VIEWS_GLSL
#define RM_VIEWS_GLSL

#define RM_VIEW_STEPS 1    // map() evaluations per pixel as a heatmap, with a legend bar
#define RM_VIEW_NORMALS 2  // the primary hit's normal as colour
#define RM_VIEW_DEPTH 3    // the primary hit's distance, near bright, far dark, misses black
#define RM_VIEW_NAN 4      // the picture in grey, NaN or Inf pixels magenta
#define RM_VIEW_DATA 5     // raw numbers for the accuracy command: (map() calls, t, bad, mapBound() calls)

#ifndef RM_VIEW_STEPS_SCALE
#define RM_VIEW_STEPS_SCALE 256.0
#endif
#ifndef RM_VIEW_DEPTH_SCALE
#define RM_VIEW_DEPTH_SCALE 100.0
#endif

#ifdef RM_VIEW
float rmFirstT = -1.0;        // distance to the primary hit; < 0 while none
vec3 rmFirstNormal = vec3(0.0);
bool rmHasNormal = false;

// Notes the first hit of the pixel (the primary ray's); later ones are secondary.
void rmRecordHit(float t) {
  if (rmFirstT < 0.0) rmFirstT = t;
}

// Notes the first normal computed in the pixel: the primary hit's.
void rmRecordNormal(vec3 n) {
  if (!rmHasNormal) rmFirstNormal = n;
  rmHasNormal = true;
}

// A heat colour for x in [0, 1]: dark blue, cyan, yellow, red, white.
vec3 rmHeat(float x) {
  x = clamp(x, 0.0, 1.0);
  vec3 c = mix(vec3(0.05, 0.05, 0.3), vec3(0.0, 0.7, 0.8), smoothstep(0.0, 0.25, x));
  c = mix(c, vec3(1.0, 0.9, 0.1), smoothstep(0.25, 0.5, x));
  c = mix(c, vec3(0.9, 0.1, 0.05), smoothstep(0.5, 0.75, x));
  return mix(c, vec3(1.0), smoothstep(0.75, 1.0, x));
}

// The pixel as the view RM_VIEW shows it; `bad` says the picture's colour was NaN or Inf.
vec4 rmView(vec4 color, vec2 fragCoord, vec3 resolution, bool bad) {
#if RM_VIEW == RM_VIEW_STEPS
  // The legend: a bar along the bottom left, 0 to RM_VIEW_STEPS_SCALE calls,
  // with a dark tick at every quarter.
  float barWidth = 0.4 * resolution.x, barHeight = max(6.0, 0.04 * resolution.y);
  if (fragCoord.x < barWidth && fragCoord.y < barHeight) {
    float x = fragCoord.x / barWidth;
    float tick = abs(fract(x * 4.0 + 0.5) - 0.5) * barWidth / 4.0;
    return vec4(tick < 0.75 && fragCoord.y < 0.5 * barHeight ? vec3(0.0) : rmHeat(x), 1.0);
  }
  return vec4(rmHeat(float(rmEvaluations) / RM_VIEW_STEPS_SCALE), 1.0);
#elif RM_VIEW == RM_VIEW_NORMALS
  return vec4(rmHasNormal ? 0.5 + 0.5 * rmFirstNormal : vec3(0.1), 1.0);
#elif RM_VIEW == RM_VIEW_DEPTH
  return vec4(vec3(rmFirstT < 0.0 ? 0.0 : 1.0 - log(1.0 + rmFirstT) / log(1.0 + RM_VIEW_DEPTH_SCALE)), 1.0);
#elif RM_VIEW == RM_VIEW_DATA
#ifdef RM_MAP_BOUND
  float boundCalls = float(rmBoundEvaluations);
#else
  float boundCalls = 0.0;
#endif
  return vec4(float(rmEvaluations), rmFirstT, bad ? 1.0 : 0.0, boundCalls);
#else
  return color;
#endif
}
#endif  // RM_VIEW

#endif  // RM_VIEWS_GLSL
