// plain_library.frag: three objects on a floor through rm/render.glsl, asking
// for nothing extra: direct light only. tests/bench/scenes/plain_handwritten.frag
// is the same picture from a hand-written marcher; scripts/effects-bench
// compares their frame times (the library's overhead).
#define RM_LIGHT_COUNT 1
#define RM_SCENE_BACKGROUND
#include <rm/sdf.glsl>
#include <rm/camera.glsl>
#include <rm/render.glsl>

float map(vec3 p) {
  float d = min(sdSphere(p - vec3(-1.1, 0.05, 0.0), 0.55), sdTorus(p - vec3(0.1, 0.0, -0.3), vec2(0.45, 0.15)));
  return min(min(d, sdBox(p - vec3(1.2, -0.15, 0.2), vec3(0.35))), p.y + 0.5);
}

RmMaterial material(vec3 p, vec3 n) { return rmMaterial(vec3(0.7, 0.5, 0.3)); }
RmLight light(int i) { return rmDirectionalLight(vec3(0.5, 0.8, 0.3), vec3(1.0)); }
vec3 background(vec3 rd) { return vec3(0.5, 0.6, 0.8); }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  RmCamera cam = rmLookAt(vec3(0.0, 1.0, 4.5), vec3(0.0, -0.2, 0.0), 0.9);
  vec3 color = rmRenderPixel(cam, fragCoord, iResolution);
  fragColor = vec4(rmGamma(rmToneMapACES(color), 2.2), 1.0);
}
