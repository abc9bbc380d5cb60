// sky_lit: a scene lit by a Cube A pass. cube_a.frag draws a cloudy sky into
// a cube map (256 pixels a face); the sky is the background and what the
// chrome and the glossy floor reflect, and its sun lights and shadows the
// scene. Run it as it is: raymarching examples/sky_lit/image.frag
#pragma channel0 "cube_a.frag" cube size=256
#define RM_SHADOWS 3
#define RM_AO
#define RM_REFLECTIONS 2
#define RM_GROUND 0.0
#define RM_LIGHT_COUNT 1
#define RM_SCENE_BACKGROUND
#define RM_BOUNDING_SPHERE vec4(0.0, 0.9, 0.0, 2.2)
#include <rm/sdf.glsl>
#include <rm/ops.glsl>
#include <rm/transforms.glsl>
#include <rm/camera.glsl>
#include <rm/render.glsl>
#include "sky.glsl"

const float kChrome = 1.0, kClay = 2.0;

RmHit scene(vec3 p) {
  RmHit ball = rmHit(sdSphere(p - vec3(-0.75, 0.7, 0.0), 0.7), kChrome);
  vec3 q = opRotate(p - vec3(0.85, 0.75, 0.2), rmRotationY(0.3 * iTime));
  RmHit knot = rmHit(sdTorus(q.xzy, vec2(0.55, 0.2)), kClay);
  RmHit pill = rmHit(sdCapsule(p, vec3(0.1, 0.25, 1.1), vec3(0.9, 0.25, 1.3), 0.25), kChrome);
  return opUnion(opUnion(ball, knot), pill);
}

float map(vec3 p) { return scene(p).d; }

RmMaterial material(vec3 p, vec3 n) {
  if (scene(p).id == kChrome) {
    RmMaterial m = rmMaterial(vec3(0.05));
    m.reflectivity = 0.9;
    m.specular = 1.0;
    m.shininess = 200.0;
    return m;
  }
  RmMaterial m = rmMaterial(vec3(0.8, 0.35, 0.2));
  m.specular = 0.4;
  m.shininess = 32.0;
  return m;
}

RmMaterial groundMaterial(vec3 p) {
  vec2 tile = floor(p.xz * 1.5);
  RmMaterial m = rmMaterial(mod(tile.x + tile.y, 2.0) == 0.0 ? vec3(0.55) : vec3(0.35));
  m.reflectivity = 0.2;
  return m;
}

RmLight light(int i) { return rmDirectionalLight(sunDirection(), vec3(2.2, 2.0, 1.7)); }

vec3 background(vec3 rd) { return texture(iChannel0, rd).rgb; }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  RmCamera cam = rmLookAt(rmOrbit(vec3(0.0, 0.6, 0.0), 4.6, 0.1 * sin(0.1 * iTime), 0.3), vec3(0.0, 0.6, 0.0), 0.9);
  vec3 color = rmRenderPixel(cam, fragCoord, iResolution);
  fragColor = vec4(rmLinearToSrgb(rmToneMapACES(color)), 1.0);
}
