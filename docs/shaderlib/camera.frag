// rm/camera.glsl: the same orbit position with a 30 degree (left) and a 90
// degree (right) vertical field of view; each half keeps square pixels.
#define RM_SHADOWS 3
#define RM_GROUND -0.5
#include "scene.glsl"
#include <rm/camera.glsl>
#include <rm/render.glsl>

float map(vec3 p) { return objects(p).d; }
RmMaterial material(vec3 p, vec3 n) { return rmMaterial(0.55 + 0.4 * cos(vec3(0.0, 2.0, 4.0) + objects(p).id)); }
RmMaterial groundMaterial(vec3 p) { return rmMaterial(vec3(0.5)); }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  bool left = fragCoord.x < 0.5 * iResolution.x;
  vec3 half_ = vec3(0.5 * iResolution.x, iResolution.yz);
  vec2 local = vec2(left ? fragCoord.x : fragCoord.x - half_.x, fragCoord.y);
  vec3 eye = rmOrbit(vec3(0.0, -0.2, 0.0), left ? 9.0 : 2.6, 0.35, 0.3);
  RmCamera cam = rmLookAt(eye, vec3(0.0, -0.2, 0.0), radians(left ? 30.0 : 90.0));
  vec3 color = rmRender(cam.position, rmCameraRay(cam, local, half_), rmPixelCone(cam, half_));
  if (abs(fragCoord.x - half_.x) < 1.0) color = vec3(1.0);
  fragColor = vec4(rmLinearToSrgb(rmToneMapACES(color)), 1.0);
}
