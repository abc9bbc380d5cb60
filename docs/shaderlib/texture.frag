// rm/texture.glsl on spheres, left to right: fbm marble, value noise, a 3D
// checker and grid lines; the ground is a 2D checker.
#define RM_SHADOWS 3
#define RM_AO
#define RM_GROUND -0.5
#include <rm/sdf.glsl>
#include <rm/camera.glsl>
#include <rm/texture.glsl>
#include <rm/render.glsl>

float map(vec3 p) {
  p.x = abs(p.x + 0.0);
  return min(sdSphere(p - vec3(0.6, 0.0, 0.0), 0.45), sdSphere(p - vec3(1.75, 0.0, 0.0), 0.45));
}

RmMaterial material(vec3 p, vec3 n) {
  vec3 c;
  if (p.x < -1.1) c = mix(vec3(0.2, 0.25, 0.4), vec3(0.95), smoothstep(0.3, 0.7, rmFbm(p * 3.0, 6)));
  else if (p.x < 0.0) c = vec3(rmValueNoise(p * 8.0));
  else if (p.x < 1.1) c = mix(vec3(0.8, 0.3, 0.2), vec3(0.95), rmChecker(p * 5.0));
  else c = mix(vec3(0.9, 0.85, 0.6), vec3(0.1), rmGrid(p.xy * 6.0, 0.12));
  return rmMaterial(c);
}

RmMaterial groundMaterial(vec3 p) { return rmMaterial(mix(vec3(0.3), vec3(0.6), rmChecker(p.xz * 2.0))); }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  RmCamera cam = rmLookAt(vec3(0.0, 1.2, 4.4), vec3(0.0, -0.1, 0.0), 0.75);
  vec3 color = rmRenderPixel(cam, fragCoord, iResolution);
  fragColor = vec4(rmLinearToSrgb(rmToneMapACES(color)), 1.0);
}
