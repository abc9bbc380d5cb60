// menger.frag: the Menger sponge, repeated without end: each cell of an
// infinite grid holds a sponge of four levels, and neighbours touch, so the
// holes line up into corridors the camera flies down. The light is a lantern
// carried ahead of the camera: drag with the left mouse button to swing it.
#define RM_SHADOWS 2
#define RM_AO
#define RM_FOG 0.08
#define RM_MAX_STEPS 200
#define RM_SCENE_BACKGROUND
#define RM_LIGHT_COUNT 1
#include <rm/fractals.glsl>
#include <rm/transforms.glsl>
#include <rm/camera.glsl>
#include <rm/render.glsl>

vec3 background(vec3 rd) { return vec3(0.12, 0.1, 0.09); }

// Period 2 fits the sponge's cube [-1, 1]^3 exactly. The sponge is symmetric
// in its cell, so the repeated field is still a bound.
float map(vec3 p) {
  vec3 cell;
  return sdMenger(opRepeat(p, vec3(2.0), cell), 4);
}

// Down a corridor that the largest holes make (along the x = y = 0 line).
vec3 eye() { return vec3(0.05, 0.08, 2.0 - 0.5 * iTime); }

RmLight light(int i) {
  vec3 swing = rmMouseLightDirection(iMouse, iResolution.xy, vec3(0.3, 0.5, 0.6));
  return rmPointLight(eye() + vec3(0.0, 0.0, -0.6) + 0.5 * swing, vec3(1.6, 1.3, 0.9));
}

RmMaterial material(vec3 p, vec3 n) {
  // Deeper inside the holes is darker and warmer.
  float depth = clamp(0.5 - map(p + n * 0.1) * 2.0, 0.0, 1.0);
  return rmMaterial(mix(vec3(0.85, 0.8, 0.7), vec3(0.6, 0.35, 0.2), depth));
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec3 ahead = eye() + vec3(0.3 * sin(0.3 * iTime), 0.2 * cos(0.25 * iTime), -1.0);
  RmCamera cam = rmLookAt(eye(), ahead, 1.1);
  vec3 color = rmRenderPixel(cam, fragCoord, iResolution);
  fragColor = vec4(rmLinearToSrgb(rmToneMapACES(color)), 1.0);
}
