// rm/lighting.glsl: materials, lights and Blinn-Phong shading; hard and soft
// shadows, ambient occlusion, fog, tone mapping and gamma; a mouse-driven light.
// Provides: RmMaterial, rmMaterial, RmLight, RM_POINT_LIGHT,
//   RM_DIRECTIONAL_LIGHT, RM_SPOT_LIGHT, rmPointLight, rmDirectionalLight,
//   rmSpotLight, rmLightDirection, rmLightDistance, rmLightRadiance,
//   rmBlinnPhong, rmShade, rmHardShadow, rmSoftShadow, rmSoftShadowImproved,
//   rmAoTapDistance, rmAoTapBlocked, rmAmbientOcclusion, rmFog,
//   rmToneMapReinhard, rmToneMapACES, rmGamma, rmLinearToSrgb,
//   rmMouseLightDirection.
// Needs: the scene's `float map(vec3 p)`; rm/common.glsl and rm/map.glsl
//   (included; map() calls go through rmMap, which RM_COUNT counts).
// Knobs: RM_SHADOW_STEPS (shadow ray steps), RM_AO_SAMPLES (AO taps).
// Every function returns finite values for any input, including t = 0, h = 0
// and distances that grow faster than the previous step allowed.
#ifndef RM_LIGHTING_GLSL
#define RM_LIGHTING_GLSL

#include <rm/common.glsl>
#include <rm/map.glsl>
#include <rm/quality.glsl>

// Most map() evaluations per shadow ray.
#ifndef RM_SHADOW_STEPS
#define RM_SHADOW_STEPS 64
#endif
// map() evaluations per ambient occlusion estimate (plus one); 0 takes
// none and leaves every point open.
#ifndef RM_AO_SAMPLES
#define RM_AO_SAMPLES 5
#endif
#if RM_AO_SAMPLES < 0 || RM_AO_SAMPLES > 32
#error RM_AO_SAMPLES must be 0 to 32 (its taps are the bits of an int)
#endif


// How a surface looks. Colours are linear RGB.
struct RmMaterial {
  vec3 albedo;        // diffuse colour
  float specular;     // Blinn-Phong specular strength
  float shininess;    // Blinn-Phong exponent
  vec3 emission;      // light the surface gives off
  float reflectivity; // share of mirror reflection, 0..1
  float transparency; // share of refraction, 0..1 (Fresnel splits it further)
  float ior;          // index of refraction inside, relative to outside
  vec3 absorption;    // Beer absorption per unit length inside
};

// A plain diffuse material with a little specular.
RmMaterial rmMaterial(vec3 albedo) {
  return RmMaterial(albedo, 0.3, 32.0, vec3(0.0), 0.0, 0.0, 1.5, vec3(0.0));
}

const int RM_POINT_LIGHT = 0;
const int RM_DIRECTIONAL_LIGHT = 1;
const int RM_SPOT_LIGHT = 2;

// A light; make one with rmPointLight, rmDirectionalLight or rmSpotLight.
struct RmLight {
  int type;         // RM_POINT_LIGHT, RM_DIRECTIONAL_LIGHT or RM_SPOT_LIGHT
  vec3 position;    // point and spot lights
  vec3 direction;   // directional: toward the light; spot: the way it shines
  vec3 color;       // linear RGB; point and spot lights fall off as 1 / distance^2
  float cosInner;   // spot: full light inside this cone (cosine of the half-angle)
  float cosOuter;   // spot: no light outside this cone
};

// A point light at position.
RmLight rmPointLight(vec3 position, vec3 color) {
  return RmLight(RM_POINT_LIGHT, position, vec3(0.0, 1.0, 0.0), color, 1.0, 1.0);
}

// A light at infinity, in the (normalised) direction toward it.
RmLight rmDirectionalLight(vec3 towardLight, vec3 color) {
  return RmLight(RM_DIRECTIONAL_LIGHT, vec3(0.0), rmSafeNormalize(towardLight, vec3(0.0, 1.0, 0.0)), color,
                 1.0, 1.0);
}

// A spot light at position shining along direction; full inside innerAngle,
// fading to nothing at outerAngle (half-angles, radians).
RmLight rmSpotLight(vec3 position, vec3 direction, vec3 color, float innerAngle, float outerAngle) {
  return RmLight(RM_SPOT_LIGHT, position, rmSafeNormalize(direction, vec3(0.0, -1.0, 0.0)), color,
                 cos(innerAngle), cos(max(outerAngle, innerAngle)));
}

// Unit vector from p toward the light.
vec3 rmLightDirection(RmLight light, vec3 p) {
  if (light.type == RM_DIRECTIONAL_LIGHT) return light.direction;
  return rmSafeNormalize(light.position - p, vec3(0.0, 1.0, 0.0));
}

// How far a shadow ray from p toward the light needs to go (1e30: infinity).
float rmLightDistance(RmLight light, vec3 p) {
  return light.type == RM_DIRECTIONAL_LIGHT ? 1e30 : length(light.position - p);
}

// Light arriving at p: colour, inverse-square falloff and the spot cone.
vec3 rmLightRadiance(RmLight light, vec3 p) {
  if (light.type == RM_DIRECTIONAL_LIGHT) return light.color;
  vec3 toLight = light.position - p;
  vec3 radiance = light.color / max(dot(toLight, toLight), 1e-4);
  if (light.type == RM_SPOT_LIGHT) {
    float c = dot(-rmSafeNormalize(toLight, -light.direction), light.direction);
    radiance *= smoothstep(light.cosOuter, max(light.cosInner, light.cosOuter + 1e-4), c);
  }
  return radiance;
}

// Diffuse plus specular Blinn-Phong for unit normal n, unit v toward the eye
// and unit l toward a light whose arriving light is `radiance`.
vec3 rmBlinnPhong(vec3 n, vec3 v, vec3 l, vec3 radiance, RmMaterial m) {
  float nl = max(dot(n, l), 0.0);
  vec3 h = rmSafeNormalize(l + v, n);
  float specular = nl > 0.0 ? m.specular * pow(max(dot(n, h), 0.0), m.shininess) : 0.0;
  return radiance * (m.albedo * nl + specular);
}

// One light's Blinn-Phong contribution at p, times the visibility `shadow` (0..1).
vec3 rmShade(vec3 p, vec3 n, vec3 v, RmMaterial m, RmLight light, float shadow) {
  return shadow * rmBlinnPhong(n, v, rmLightDirection(light, p), rmLightRadiance(light, p), m);
}

// 0 if something lies on the ray ro + t rd for t in [tMin, tMax], else 1.
float rmHardShadow(vec3 ro, vec3 rd, float tMin, float tMax) {
  float t = max(tMin, 1e-6);
  int i = 0;  // steps so far, on mapBound or map()
#ifdef RM_MAP_BOUND
  t = rmSkipOpenSpace(ro, rd, t, tMax, 0.0, 1e-4, 1.0, 1e30, RM_SHADOW_STEPS, i).x;
#endif
  if (i < RM_SHADOW_STEPS && t < tMax) {
    do {  // tested at the bottom (rm/common.glsl)
      float h = rmMap(ro + rd * t);
      if (h < 1e-4 * t) return 0.0;
      t += h;
    } while (++i < RM_SHADOW_STEPS && t < tMax);
  }
  return 1.0;
}

// Soft shadow, the classic form: how close the ray passes to an occluder,
// min(k h / t). Larger k gives sharper penumbrae.
float rmSoftShadow(vec3 ro, vec3 rd, float tMin, float tMax, float k) {
  float shade = 1.0;
  float t = max(tMin, 1e-6);  // t = 0 would make k h / t a 0/0
  int i = 0;  // steps so far, on mapBound or map()
#ifdef RM_MAP_BOUND
  // Past the cheap parts, k h / t is their k x / t; the costly ones leave the
  // light whole while k y / t >= 1. map() decides only where that fails.
  vec2 open = rmSkipOpenSpace(ro, rd, t, tMax, 0.0, 1.0 / k, 1e-3, 0.5, RM_SHADOW_STEPS, i);
  t = open.x;
  shade = min(shade, open.y);
  if (shade < 1e-3) return 0.0;
#endif
  if (i < RM_SHADOW_STEPS && t < tMax) {
    do {  // tested at the bottom (rm/common.glsl)
      float h = rmMap(ro + rd * t);
      shade = min(shade, k * h / t);
      if (shade < 1e-3) break;
      t += clamp(h, 1e-3, 0.5);  // small steps in the penumbra, bounded ones in the open
    } while (++i < RM_SHADOW_STEPS && t < tMax);
  }
  return clamp(shade, 0.0, 1.0);
}

// Soft shadow, iq's improved form: estimates the closest approach between
// two steps, which removes the banding of the classic form. Same k.
float rmSoftShadowImproved(vec3 ro, vec3 rd, float tMin, float tMax, float k) {
  float shade = 1.0;
  float previousH = 0.0;
  float stepLength = 0.0;
  float t = max(tMin, 1e-6);
  int i = 0;  // steps so far, on mapBound or map()
#ifdef RM_MAP_BOUND
  // Light is certain while k h / t >= 1 (h >= mapBound): only where that
  // fails does map() decide the penumbra.
  t = rmSkipOpenSpace(ro, rd, t, tMax, 0.0, 1.0 / k, 1.0, 0.5, RM_SHADOW_STEPS, i).x;
#endif
  if (i < RM_SHADOW_STEPS && t < tMax) {
    do {  // tested at the bottom (rm/common.glsl)
      float h = rmMap(ro + rd * t);
      if (h <= 0.0) return 0.0;
      // The occluder is nearest where the spheres of this and the last step meet:
      // y back along the ray, d off it. iq writes y = h^2 / (2 previousH), which
      // assumes the step equalled previousH; clamped steps break that, and when
      // one sphere holds the other (h >= 2 previousH) there is no chord and
      // sqrt(h^2 - y^2) would be NaN or 0. Then fall back to the classic estimate.
      float y = stepLength > 0.0 ? (h * h - previousH * previousH + stepLength * stepLength) / (2.0 * stepLength) : 0.0;
      float d = h;
      if (y > 0.0 && y < h) d = sqrt(h * h - y * y);
      else y = 0.0;
      shade = min(shade, k * d / max(t - y, 1e-6));
      if (shade < 1e-3) break;
      previousH = h;
      stepLength = clamp(h, 1e-3, 0.5);
      t += stepLength;
    } while (++i < RM_SHADOW_STEPS && t < tMax);
  }
  return clamp(shade, 0.0, 1.0);
}

// How far from the surface AO's tap i of RM_AO_SAMPLES looks.
float rmAoTapDistance(int i) { return 0.02 + 0.2 * float(i + 1) / float(RM_AO_SAMPLES); }

// The share of tap distance h that is blocked, where map() there is d and at the surface base.
float rmAoTapBlocked(float h, float d, float base) { return clamp((h - (d - base)) / h, 0.0, 1.0); }

// Ambient occlusion at p with unit normal n: how much nearby geometry blocks
// the hemisphere, 1 = open. Each tap's distance is measured from `surface`,
// map()'s value at p: a hit point found slightly off the surface does not
// darken. A point exactly on a surface that map() does not hold (the analytic
// ground, RM_GROUND) gives 0: map(p) there is the distance to the objects,
// and subtracting it would close the hemisphere wherever they are far.
float rmAmbientOcclusion(vec3 p, vec3 n, float surface) {
#if RM_AO_SAMPLES == 0
  return 1.0;  // no taps, nothing found in the way (the loops below run once at least)
#else
  float base = surface;
  float blocked = 0.0;  // weighted share of each tap's distance that is blocked
  float total = 0.0;
  float weight = 1.0;
#ifdef RM_MAP_BOUND
  // A tap whose costly parts lie beyond its reach sees map() as the cheap
  // parts, which mapBound gives exactly. map() only for the others, in a loop
  // no longer than they span: a CPU renderer runs an if's body for every pixel.
  int first = RM_AO_SAMPLES, last = -1;
  // One loop, not RM_AO_SAMPLES copies of mapBound (from RM_ZERO), and the
  // costly taps as bits: an array indexed in a loop is slow on llvmpipe.
  int costly = 0;  // bit i: tap i needs map() (RM_AO_SAMPLES < 32)
  int i = RM_ZERO;
  do {  // tested at the bottom (rm/common.glsl)
    float h = rmAoTapDistance(i);
    vec2 bound = rmMapBound(p + n * h);
    bool exact = bound.y - base >= h;
    costly |= exact ? 0 : 1 << i;
    blocked += exact ? weight * rmAoTapBlocked(h, bound.x, base) : 0.0;
    first = exact ? first : min(first, i);
    last = exact ? last : i;
    total += weight;
    weight *= 0.8;
  } while (++i < RM_AO_SAMPLES);
  weight = pow(0.8, float(first));
  if (first <= last) {
    i = first;
    do {
      float h = rmAoTapDistance(i);
      if ((costly & (1 << i)) != 0) blocked += weight * rmAoTapBlocked(h, rmMap(p + n * h), base);
      weight *= 0.8;
    } while (++i <= last);
  }
#else
  // One loop (from RM_ZERO), not RM_AO_SAMPLES copies of map(): it compiles
  // faster, and draws faster too unless map() is tiny.
  int i = RM_ZERO;
  do {  // tested at the bottom (rm/common.glsl)
    float h = rmAoTapDistance(i);
    blocked += weight * rmAoTapBlocked(h, rmMap(p + n * h), base);
    total += weight;
    weight *= 0.8;  // near taps matter most
  } while (++i < RM_AO_SAMPLES);
#endif
  return clamp(1.0 - 1.5 * blocked / total, 0.0, 1.0);
#endif
}

// Ambient occlusion at a hit point p of map()'s surface, with unit normal n.
float rmAmbientOcclusion(vec3 p, vec3 n) { return rmAmbientOcclusion(p, n, rmMap(p)); }

// Exponential fog: color seen through distance t of fog with the given density.
vec3 rmFog(vec3 color, vec3 fogColor, float t, float density) {
  return mix(fogColor, color, exp(-density * max(t, 0.0)));
}

// Reinhard tone mapping: maps [0, inf) into [0, 1).
vec3 rmToneMapReinhard(vec3 c) { return c / (1.0 + max(c, 0.0)); }

// ACES filmic tone mapping (Narkowicz's fit), clamped to [0, 1].
vec3 rmToneMapACES(vec3 c) {
  c = max(c, 0.0);
  return clamp((c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14), 0.0, 1.0);
}

// Gamma encoding, c^(1/gamma) (2.2 is the usual display gamma).
vec3 rmGamma(vec3 c, float gamma) { return pow(max(c, 0.0), vec3(1.0 / gamma)); }

// Exact sRGB encoding of linear RGB.
vec3 rmLinearToSrgb(vec3 c) {
  c = max(c, 0.0);
  return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}

// Unit direction toward a light that a left-button drag moves (pass iMouse and
// iResolution.xy): x turns it around the scene, y raises it from 6 to 83
// degrees. Until the first click it points toward `rest`.
vec3 rmMouseLightDirection(vec4 mouse, vec2 resolution, vec3 rest) {
  if (mouse.x == 0.0 && mouse.y == 0.0 && mouse.z == 0.0) return rmSafeNormalize(rest, vec3(0.0, 1.0, 0.0));
  vec2 m = clamp(mouse.xy / max(resolution, vec2(1.0)), 0.0, 1.0);
  float azimuth = RM_TAU * m.x;
  float elevation = mix(0.1, 1.45, m.y);
  return vec3(cos(azimuth) * cos(elevation), sin(elevation), sin(azimuth) * cos(elevation));
}

#endif  // RM_LIGHTING_GLSL
