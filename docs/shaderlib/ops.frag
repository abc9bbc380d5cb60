// rm/ops.glsl: a sphere and a box combined six ways, left to right:
// union, intersection, subtraction, smooth union (materials blend across the
// seam through RmHit), chamfered union, rounded subtraction.
#define RM_SHADOWS 3
#define RM_AO
#define RM_GROUND -0.55
#include <rm/sdf.glsl>
#include <rm/ops.glsl>
#include <rm/camera.glsl>
#include <rm/render.glsl>

RmHit pair(int i, vec3 p) {
  RmHit a = rmHit(sdSphere(p - vec3(0.18, 0.12, 0.0), 0.38), 1.0);
  RmHit b = rmHit(sdBox(p + vec3(0.12, 0.12, 0.0), vec3(0.3)), 2.0);
  switch (i) {
    case 0: return opUnion(a, b);
    case 1: return opIntersection(a, b);
    case 2: return opSubtraction(b, a);
    case 3: return opSmoothUnion(a, b, 0.25);
    case 4: return RmHit(opChamferUnion(a.d, b.d, 0.12) * 0.7071, 1.0, 2.0, 0.5);  // sqrt(2): see ops.glsl
    default: return RmHit(opRoundSubtraction(b.d, a.d, 0.1) * 0.7071, 2.0, 2.0, 0.0);
  }
}

RmHit scene(vec3 p) {
  RmHit best = rmHit(1e10, 0.0);
  for (int i = 0; i < 6; ++i) best = opUnion(best, pair(i, p - vec3(1.15 * (float(i) - 2.5), 0.0, 0.0)));
  return best;
}

float map(vec3 p) { return scene(p).d; }

RmMaterial material(vec3 p, vec3 n) {
  RmHit h = scene(p);
  vec3 sphere = vec3(0.9, 0.35, 0.25), box = vec3(0.25, 0.5, 0.9);
  return rmMaterial(rmHitBlend(h, h.id == 1.0 ? sphere : box, h.id2 == 1.0 ? sphere : box));
}

RmMaterial groundMaterial(vec3 p) { return rmMaterial(vec3(0.5)); }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  RmCamera cam = rmLookAt(vec3(0.0, 1.3, 4.6), vec3(0.0, -0.12, 0.0), 0.55);
  vec3 color = rmRenderPixel(cam, fragCoord, iResolution);
  fragColor = vec4(rmLinearToSrgb(rmToneMapACES(color)), 1.0);
}
