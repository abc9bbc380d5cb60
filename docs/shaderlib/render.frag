// rm/render.glsl: the same scene compiled with more effects each time:
// direct light only; + soft shadows (-D RM_SHADOWS=3); + ambient occlusion
// (-D RM_AO); + the mirror (-D RM_REFLECTIONS=2), the glass
// (-D RM_REFRACTION=4) and fog (-D RM_FOG=0.08).
#define RM_GROUND -0.5
#include "scene.glsl"
#include <rm/camera.glsl>
#include <rm/texture.glsl>
#include <rm/render.glsl>

float map(vec3 p) { return objects(p).d; }

RmMaterial material(vec3 p, vec3 n) {
  float id = objects(p).id;
  RmMaterial m = rmMaterial(vec3(0.85, 0.45, 0.25));
  if (id == 1.0) m.reflectivity = 0.8;
  if (id == 3.0) {
    m.transparency = 0.9;
    m.absorption = vec3(0.1, 0.4, 0.6);
  }
  return m;
}

RmMaterial groundMaterial(vec3 p) { return rmMaterial(mix(vec3(0.25), vec3(0.7), rmChecker(p.xz * 2.0))); }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  RmCamera cam = rmLookAt(vec3(0.0, 1.0, 4.5), vec3(0.0, -0.2, 0.0), 0.9);
  vec3 color = rmRenderPixel(cam, fragCoord, iResolution);
  fragColor = vec4(rmLinearToSrgb(rmToneMapACES(color)), 1.0);
}
