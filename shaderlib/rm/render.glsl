// rm/render.glsl: the whole picture for a scene that gives only its geometry
// and its look. It marches the primary ray, shades the hit with every light,
// and follows reflection and refraction rays in a bounded loop.
// Provides: rmBackground, rmDirectLight, rmRender, rmRenderPixel, and light()
//   when the scene defines no lights.
// Needs: the scene contract:
//   float map(vec3 p);                    a bound distance to the scene
//     (with RM_GRID_PERIOD: float mapCell(vec3 q, vec3 cell), rm/grid.glsl)
//   RmMaterial material(vec3 p, vec3 n);  the look at hit point p, normal n
//   with RM_GROUND:  RmMaterial groundMaterial(vec3 p);
//   with RM_LIGHT_COUNT: RmLight light(int i) for i < RM_LIGHT_COUNT (0: ambient light only)
//     (otherwise one white sun that a left-button drag moves, via iMouse);
//   with RM_SCENE_BACKGROUND: vec3 background(vec3 rd).
//   Includes rm/march, rm/normals, rm/lighting, rm/optics and rm/camera.
// Effects are compiled in only when the scene asks (#define before the include
// or -D on the command line); asking for nothing gives direct light only:
//   RM_SHADOWS 1 hard, 2 soft (k h / t), 3 soft (iq's improved form)
//   RM_SHADOW_SHARPNESS k of the soft shadows (default 16)
//   RM_SHADOW_REACH d  how far shadow rays look for occluders (default
//                  RM_MAX_DISTANCE); in an endless scene almost every long
//                  shadow ray meets something: a short reach lets the sun in
//   RM_AO          ambient occlusion
//   RM_REFLECTIONS n  mirror bounces per pixel, for reflectivity > 0
//   RM_REFRACTION n   segments through transparent solids per pixel (entering,
//                  leaving, internal reflections), with Fresnel, total
//                  internal reflection and Beer absorption; transparency > 0
//   RM_FOG d       exponential fog of density d
//   RM_GROUND h    an analytic ground plane y = h, kept out of map() (the march
//                  meets it exactly; it casts no shadow and gives no AO)
//   RM_BOUNDING_SPHERE vec4(centre, radius): all of map()'s surface lies
//                  inside; rays skip straight to it, miss it for free, and
//                  shadow rays stop where they leave it
//   RM_BOUNDING_BOX_MIN / RM_BOUNDING_BOX_MAX vec3 corners: the same with a
//                  box, which fits a flat layout (objects on a floor) tighter;
//                  both may be given, and a ray then keeps to where they overlap
//   RM_MAP_BOUND   the scene also gives vec2 mapBound(p): its cheap parts'
//                  distance and a bound of its costly parts' (rm/map.glsl);
//                  rays call map() only near the costly parts
//   RM_GRID_PERIOD / RM_GRID_RADIUS  an endless grid of instances: the scene
//                  gives mapCell(q, cell) instead of map() (rm/grid.glsl), and
//                  primary rays and hard shadows cross empty cells in one step
// Secondary rays are spent only where the material asks for them: shadow rays
// for lit sides, reflection rays for reflectivity > 0, refraction for
// transparency > 0. Without RM_REFRACTION a transparent material is opaque.
#ifndef RM_RENDER_GLSL
#define RM_RENDER_GLSL

#include <rm/quality.glsl>
#include <rm/camera.glsl>
#include <rm/lighting.glsl>
#include <rm/march.glsl>
#include <rm/normals.glsl>
#include <rm/optics.glsl>
// An endless grid, for a scene that defines RM_GRID_PERIOD.
#ifdef RM_GRID_PERIOD
#include <rm/grid.glsl>
#endif

// Mirror bounces and refraction segments followed per pixel.
#ifndef RM_REFLECTIONS
#define RM_REFLECTIONS 0
#endif
#ifndef RM_REFRACTION
#define RM_REFRACTION 0
#endif
#if RM_REFLECTIONS < 0
#error RM_REFLECTIONS must be 0 or more
#endif
#if RM_REFRACTION < 0
#error RM_REFRACTION must be 0 or more
#endif
// k of the soft shadows: larger is sharper.
#ifndef RM_SHADOW_SHARPNESS
#define RM_SHADOW_SHARPNESS 16.0
#endif
// How far shadow rays look for occluders.
#ifndef RM_SHADOW_REACH
#define RM_SHADOW_REACH RM_MAX_DISTANCE
#endif
// Supersampling: rmRenderPixel traces RM_SAMPLES x RM_SAMPLES rays per pixel.
#ifndef RM_SAMPLES
#define RM_SAMPLES 1
#endif
#if RM_SAMPLES < 1
#error RM_SAMPLES must be 1 or more (RM_SAMPLES x RM_SAMPLES rays a pixel)
#endif
// Sky light reaching every surface, before AO.
#ifndef RM_AMBIENT
#define RM_AMBIENT 0.12
#endif

RmMaterial material(vec3 p, vec3 n);
#ifdef RM_GROUND
RmMaterial groundMaterial(vec3 p);
#endif

#ifdef RM_LIGHT_COUNT
#if RM_LIGHT_COUNT < 0
#error RM_LIGHT_COUNT must be 0 (ambient light only) or more
#endif
RmLight light(int i);
#else
#define RM_LIGHT_COUNT 1
// One white sun; a left-button drag moves it.
RmLight light(int i) {
  return rmDirectionalLight(rmMouseLightDirection(iMouse, iResolution.xy, vec3(0.6, 0.7, 0.4)), vec3(1.0));
}
#endif

#ifdef RM_SCENE_BACKGROUND
vec3 background(vec3 rd);
// The scene's background(rd).
vec3 rmBackground(vec3 rd) { return background(rd); }
#else
// A plain sky: pale at the horizon, deeper blue above, darker below.
vec3 rmBackground(vec3 rd) {
  return rd.y >= 0.0 ? mix(vec3(0.62, 0.7, 0.8), vec3(0.25, 0.4, 0.7), rd.y) : vec3(0.3, 0.32, 0.35);
}
#endif

// Ambient plus every light at p (normal n, v toward the viewer) on material m;
// `offset` lifts shadow rays off the surface, and `surface` is map(p), from
// which ambient occlusion measures (rmAmbientOcclusion: 0 on the ground).
vec3 rmDirectLight(vec3 p, vec3 n, vec3 v, RmMaterial m, float offset, float surface) {
  float occlusion = 1.0;
#ifdef RM_AO
  occlusion = rmAmbientOcclusion(p, n, surface);
#endif
  vec3 color = m.albedo * RM_AMBIENT * occlusion * (0.6 + 0.4 * n.y);
#if RM_LIGHT_COUNT > 0
  int i = 0;
  do {  // tested at the bottom (rm/common.glsl)
    RmLight l = light(i);
    float visible = 1.0;
#ifdef RM_SHADOWS
    vec3 toLight = rmLightDirection(l, p);
    if (dot(n, toLight) > 0.0) {  // the dark side needs no shadow ray
      vec3 from = p + n * offset;
      float reach = min(rmLightDistance(l, p), RM_SHADOW_REACH);
      // Nothing outside the bounds can cast a shadow: stop where the ray leaves them.
#ifdef RM_BOUNDING_SPHERE
      vec2 span = rmRaySphere(from, toLight, RM_BOUNDING_SPHERE.xyz, RM_BOUNDING_SPHERE.w);
      reach = span.x > span.y ? 0.0 : min(reach, max(span.y, 0.0));
#endif
#ifdef RM_BOUNDING_BOX_MIN
      vec2 box = rmRayBox(from, toLight, RM_BOUNDING_BOX_MIN, RM_BOUNDING_BOX_MAX);
      reach = box.x > box.y ? 0.0 : min(reach, max(box.y, 0.0));
#endif
#if RM_SHADOWS == 1 && defined(RM_GRID_PERIOD) && RM_GRID_MARCH
      visible = rmHardShadowCells(from, toLight, offset, reach, RM_SHADOW_STEPS);
#elif RM_SHADOWS == 1
      visible = rmHardShadow(from, toLight, offset, reach);
#elif RM_SHADOWS == 2
      visible = rmSoftShadow(from, toLight, offset, reach, RM_SHADOW_SHARPNESS);
#else
      visible = rmSoftShadowImproved(from, toLight, offset, reach, RM_SHADOW_SHARPNESS);
#endif
    }
#endif
    color += rmShade(p, n, v, m, l, visible);
  } while (++i < RM_LIGHT_COUNT);
#endif
  return color;
}

// rmDirectLight at a hit point p of map()'s surface.
vec3 rmDirectLight(vec3 p, vec3 n, vec3 v, RmMaterial m, float offset) {
  return rmDirectLight(p, n, v, m, offset, rmMap(p));
}

// Colour (linear) seen along the ray ro + t rd; `cone` is the pixel cone
// (rmPixelCone) that sets the hit threshold. Without RM_REFLECTIONS and
// RM_REFRACTION this is one march and one shading: no loop, no secondary rays.
vec3 rmRender(vec3 ro, vec3 rd, float cone) {
  RmMarchSettings s = rmMarchSettings();
  s.cone = cone;
#ifdef RM_GROUND
  s.ground = true;
  s.groundHeight = RM_GROUND;
#endif
#ifdef RM_BOUNDING_SPHERE
  s.boundSphere = RM_BOUNDING_SPHERE;
#endif
#ifdef RM_BOUNDING_BOX_MIN
  s.boundBox = true;
  s.boundMin = RM_BOUNDING_BOX_MIN;
  s.boundMax = RM_BOUNDING_BOX_MAX;
#endif
  vec3 primary = rd;
  vec3 color = vec3(0.0);
  vec3 throughput = vec3(1.0);  // what is left of the pixel's light after the bounces so far
  float firstT = RM_MAX_DISTANCE;
#if RM_REFRACTION > 0
  bool inside = false;          // travelling through a transparent solid
  RmMaterial medium;            // that solid's material
#endif
  int bounce = 0;
  do {  // tested at the bottom (rm/common.glsl)
#if RM_REFRACTION > 0
    s.side = inside ? -1.0 : 1.0;
#ifdef RM_GROUND
    s.ground = !inside;
#endif
#endif
#if defined(RM_GRID_PERIOD) && RM_GRID_MARCH
    RmMarch m = rmMarchGrid(ro, rd, s);
#else
    RmMarch m = rmMarch(ro, rd, s);
#endif
    if (m.outcome != RM_HIT) {
      color += throughput * rmBackground(rd);
      break;
    }
    vec3 p = ro + rd * m.t;
    // The normal, and map(p) from its taps; the ground is exact: no map(p) to subtract.
    vec4 surface = m.ground ? vec4(0.0, 1.0, 0.0, 0.0) : rmNormalAndDistance(p, m.tolerance);
    vec3 n = surface.xyz;
#ifdef RM_VIEW
    rmRecordNormal(n);  // the ground's, which rmNormal never sees
#endif
    float offset = rmSurfaceOffset(p, m.tolerance);
    if (bounce == 0) firstT = m.t;

#if RM_REFRACTION > 0
    if (inside) {
      // Leaving the solid: absorb along the way, then refract out or reflect back in.
      throughput *= rmBeer(medium.absorption, m.t);
      bool tir;
      rd = rmRefract(rd, n, medium.ior, tir);
      inside = tir;
      ro = p + (tir ? -n : n) * offset;
      continue;
    }
#endif

#ifdef RM_GROUND
    RmMaterial mat = m.ground ? groundMaterial(p) : material(p, n);
#else
    RmMaterial mat = material(p, n);
#endif
    float reflected = 0.0, refracted = 0.0;
#if RM_REFLECTIONS > 0
    reflected = mat.reflectivity;
#endif
#if RM_REFRACTION > 0
    float fresnel = mat.transparency > 0.0 ? rmFresnel(rd, n, mat.ior) : 0.0;
    reflected = clamp(reflected + mat.transparency * fresnel, 0.0, 1.0);
    refracted = mat.transparency * (1.0 - fresnel);
    float diffuse = max(1.0 - mat.reflectivity - mat.transparency, 0.0);
#else
    float diffuse = max(1.0 - mat.reflectivity, 0.0);  // without refraction, glass is opaque
#endif
    color += throughput * mat.emission;
    // Clear glass and perfect mirrors show no light of their own: no shadow rays, no AO.
    if (diffuse > 0.0) color += throughput * diffuse * rmDirectLight(p, n, -rd, mat, offset, surface.w);

#if RM_REFRACTION > 0
    if (refracted > 0.0) {
      // Follow the refracted ray; the reflected share sees the sky.
      color += throughput * reflected * rmBackground(reflect(rd, n));
      throughput *= refracted;
      bool tir;
      rd = rmRefract(rd, n, mat.ior, tir);
      inside = !tir;
      medium = mat;
      ro = p + (inside ? -n : n) * offset;
      continue;
    }
#endif
#if RM_REFLECTIONS > 0
    if (reflected > 0.0) {  // only mirrors spend a reflection ray
      throughput *= reflected;
      rd = reflect(rd, n);
      ro = p + n * offset;
      continue;
    }
#endif
    break;
  } while (++bounce <= RM_REFLECTIONS + RM_REFRACTION);
#ifdef RM_FOG
  color = rmFog(color, rmBackground(primary), firstT, RM_FOG);
#endif
  return color;
}

// Colour (linear) of the pixel at fragCoord seen by camera: the average of
// RM_SAMPLES x RM_SAMPLES rays spread evenly over the pixel.
vec3 rmRenderPixel(RmCamera camera, vec2 fragCoord, vec3 resolution) {
  float cone = rmPixelCone(camera, resolution) / float(RM_SAMPLES);
  vec3 sum = vec3(0.0);
  int i = 0;
  do {  // tested at the bottom (rm/common.glsl)
    vec2 offset = (vec2(i % RM_SAMPLES, i / RM_SAMPLES) + 0.5) / float(RM_SAMPLES) - 0.5;
    sum += rmRender(camera.position, rmCameraRay(camera, fragCoord + offset, resolution), cone);
  } while (++i < RM_SAMPLES * RM_SAMPLES);
  return sum / float(RM_SAMPLES * RM_SAMPLES);
}

#endif  // RM_RENDER_GLSL
