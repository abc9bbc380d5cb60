// buffer_a.frag of the progressive project: each frame traces one more
// jittered sample per pixel, through a thin lens (depth of field), and adds
// it to what this buffer held: rgb is the sum, alpha the number of samples.
// A drag with the mouse, or a new size, starts the sum again. A resize keeps
// a buffer's texels where they fit (as Shadertoy does), so texel (0, 0)
// holds the size the sums were traced at instead of a sum.
#pragma channel0 self filter=nearest
#define RM_SHADOWS 3
#define RM_AO
#define RM_REFLECTIONS 1
#define RM_GROUND 0.0
#define RM_BOUNDING_SPHERE vec4(0.0, 0.8, 0.0, 2.6)
#include <rm/sdf.glsl>
#include <rm/ops.glsl>
#include <rm/transforms.glsl>
#include <rm/camera.glsl>
#include <rm/render.glsl>

RmHit scene(vec3 p) {
  RmHit h = rmHit(sdSphere(p - vec3(-1.4, 0.6, -1.2), 0.6), 0.0);
  h = opUnion(h, rmHit(sdRoundBox(opRotate(p - vec3(0.0, 0.55, 0.0), rmRotationY(0.6)), vec3(0.45), 0.1), 1.0));
  h = opUnion(h, rmHit(sdTorus((p - vec3(1.3, 0.3, 1.3)), vec2(0.5, 0.2)), 2.0));
  return h;
}

float map(vec3 p) { return scene(p).d; }

RmMaterial material(vec3 p, vec3 n) {
  RmMaterial m = rmMaterial(0.55 + 0.4 * cos(vec3(0.0, 2.1, 4.2) + 2.0 * scene(p).id));
  m.specular = 0.6;
  m.shininess = 48.0;
  return m;
}

RmMaterial groundMaterial(vec3 p) {
  vec2 tile = floor(p.xz * 2.0);
  RmMaterial m = rmMaterial(mod(tile.x + tile.y, 2.0) == 0.0 ? vec3(0.6) : vec3(0.3));
  m.reflectivity = 0.15;
  return m;
}

// Two numbers in [0, 1) per pixel and frame (a PCG hash).
vec2 random2(uvec3 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.z; v.y += v.z * v.x; v.z += v.x * v.y;
  v ^= v >> 16u;
  v.x += v.y * v.z; v.y += v.z * v.x;
  return vec2(v.xy) / 4294967296.0;
}

void mainImage(out vec4 sum, in vec2 fragCoord) {
  bool resized = texelFetch(iChannel0, ivec2(0), 0).xy != iResolution.xy;
  if (ivec2(fragCoord) == ivec2(0)) {
    sum = vec4(iResolution.xy, 0.0, 0.0);
    return;
  }
  RmCamera cam = rmLookAt(vec3(0.0, 1.6, 5.0), vec3(0.0, 0.5, 0.0), 0.8);
  vec2 u = random2(uvec3(fragCoord, iFrame)), lens = random2(uvec3(fragCoord, iFrame + 7919));
  vec3 rd = rmCameraRay(cam, fragCoord + u - 0.5, iResolution);
  // A thin lens focused on the box: the ray leaves a point of the aperture
  // and passes where the pinhole ray meets the focal plane.
  const float kFocus = 5.0, kAperture = 0.12;
  vec3 focus = cam.position + rd * (kFocus / dot(rd, cam.basis[2]));
  float r = kAperture * sqrt(lens.x), a = 6.2831853 * lens.y;
  vec3 ro = cam.position + cam.basis * vec3(r * cos(a), r * sin(a), 0.0);
  vec3 color = rmRender(ro, normalize(focus - ro), rmPixelCone(cam, iResolution));
  bool restart = iFrame == 0 || iMouse.z > 0.0 || resized;
  sum = (restart ? vec4(0.0) : texelFetch(iChannel0, ivec2(fragCoord), 0)) + vec4(color, 1.0);
}
