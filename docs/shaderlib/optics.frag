// rm/optics.glsl through rm/render.glsl: a glass sphere (Snell refraction,
// Schlick Fresnel, Beer absorption, total internal reflection), a mirror torus
// and a checkered ground, with up to 2 reflections and 5 refraction segments.
#define RM_SHADOWS 3
#define RM_AO
#define RM_REFLECTIONS 2
#define RM_REFRACTION 5
#define RM_GROUND -0.5
#include "scene.glsl"
#include <rm/camera.glsl>
#include <rm/texture.glsl>
#include <rm/render.glsl>

float map(vec3 p) { return objects(p).d; }

RmMaterial material(vec3 p, vec3 n) {
  float id = objects(p).id;
  RmMaterial m = rmMaterial(vec3(0.9, 0.5, 0.2));
  if (id == 1.0) {
    m.transparency = 1.0;
    m.ior = 1.5;
    m.absorption = vec3(0.6, 0.15, 0.05);
    m.specular = 1.0;
    m.shininess = 200.0;
  } else if (id == 2.0) {
    m.albedo = vec3(0.9);
    m.reflectivity = 0.85;
  }
  return m;
}

RmMaterial groundMaterial(vec3 p) { return rmMaterial(mix(vec3(0.15), vec3(0.85), rmChecker(p.xz * 2.0))); }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  RmCamera cam = rmLookAt(vec3(0.0, 1.0, 4.5), vec3(0.0, -0.2, 0.0), 0.9);
  vec3 color = rmRenderPixel(cam, fragCoord, iResolution);
  fragColor = vec4(rmLinearToSrgb(rmToneMapACES(color)), 1.0);
}
