// rm/lighting.glsl: three coloured point lights with improved soft shadows and
// ambient occlusion; Blinn-Phong highlights on every object.
#define RM_SHADOWS 3
#define RM_AO
#define RM_LIGHT_COUNT 3
#include "scene.glsl"
#include <rm/camera.glsl>
#include <rm/render.glsl>

float map(vec3 p) { return min(objects(p).d, p.y + 0.5); }

RmLight light(int i) {
  float a = RM_TAU * float(i) / 3.0 + 0.3 * iTime;
  vec3 colors[3] = vec3[](vec3(6.0, 2.0, 1.5), vec3(1.5, 5.0, 2.0), vec3(1.5, 2.5, 7.0));
  return rmPointLight(vec3(2.2 * cos(a), 1.8, 2.2 * sin(a)), colors[i]);
}

RmMaterial material(vec3 p, vec3 n) {
  // Pick by nearest distance, not by height: hit points sit up to the hit
  // tolerance off the surface, and that grows with distance.
  RmMaterial m = rmMaterial(objects(p).d < p.y + 0.5 ? vec3(0.8) : vec3(0.6));
  m.specular = 0.6;
  m.shininess = 48.0;
  return m;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  RmCamera cam = rmLookAt(vec3(0.0, 1.2, 4.5), vec3(0.0, -0.2, 0.0), 0.9);
  vec3 color = rmRenderPixel(cam, fragCoord, iResolution);
  fragColor = vec4(rmLinearToSrgb(rmToneMapACES(color)), 1.0);
}
