// rm/fractals.glsl: a Menger sponge (4 levels), a Sierpinski tetrahedron
// (6 folds) and a Mandelbulb (power 8, 8 iterations).
#define RM_SHADOWS 3
#define RM_AO
#define RM_GROUND -0.6
#define RM_MAX_STEPS 256
#include <rm/fractals.glsl>
#include <rm/transforms.glsl>
#include <rm/camera.glsl>
#include <rm/render.glsl>

vec2 fractal(vec3 p) {
  vec2 h = vec2(opScaleDistance(sdMenger(opScale(opRotate(p - vec3(-1.35, 0.0, 0.0), rmRotationY(0.6)), 0.5), 4), 0.5), 1.0);
  float s = opScaleDistance(sdSierpinski(opScale(opRotate(p - vec3(0.0, -0.05, 0.0), rmRotationY(0.5)), 0.32), 6), 0.32);
  if (s < h.x) h = vec2(s, 2.0);
  // The Mandelbulb's estimate is approximate: half steps keep it safe.
  float b = 0.5 * opScaleDistance(sdMandelbulb(opScale(opRotate(p - vec3(1.35, 0.0, 0.0), rmRotationX(-1.3)), 0.5), 8.0, 8), 0.5);
  if (b < h.x) h = vec2(b, 3.0);
  return h;
}

float map(vec3 p) { return fractal(p).x; }
RmMaterial material(vec3 p, vec3 n) {
  return rmMaterial(0.55 + 0.4 * cos(vec3(0.0, 2.0, 4.0) + 1.3 * fractal(p).y));
}
RmMaterial groundMaterial(vec3 p) { return rmMaterial(vec3(0.5)); }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  RmCamera cam = rmLookAt(vec3(0.0, 1.2, 4.0), vec3(0.0, -0.1, 0.0), 0.75);
  vec3 color = rmRenderPixel(cam, fragCoord, iResolution);
  fragColor = vec4(rmLinearToSrgb(rmToneMapACES(color)), 1.0);
}
