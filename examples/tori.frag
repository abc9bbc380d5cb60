// tori.frag: a chain of five linked tori, each turning on its own axis, above
// a mirror-polished floor. Drag with the left mouse button to move the sun.
// The window's controls set how fast the tori spin and how polished the floor is.
#define RM_SHADOWS 3
#define RM_AO
#define RM_REFLECTIONS 1
#define RM_GROUND -1.0
#define RM_BOUNDING_SPHERE vec4(0.0, 0.0, 0.0, 3.2)  // the chain fits inside
#include <rm/sdf.glsl>
#include <rm/ops.glsl>
#include <rm/transforms.glsl>
#include <rm/camera.glsl>
#include <rm/render.glsl>

uniform float spin;   // ui: min=0 max=3 default=1
uniform float polish; // ui: min=0 max=1 default=0.35

// Torus i of the chain: alternate ones stand upright, so neighbours link.
// Each torus's centre and turns depend on the time only: worked out once a
// pixel in animate(), not in each of the dozens of map() calls a pixel makes.
vec3 centres[5];
mat3 uprights[5], spins[5];

void animate() {
  for (int i = 0; i < 5; ++i) {
    centres[i] = vec3(1.1 * (float(i) - 2.0), 0.15 * sin(iTime + float(i)), 0.0);
    uprights[i] = rmRotationX(i % 2 == 0 ? 0.0 : 1.5708);  // upright or flat
    spins[i] = rmRotationY(0.4 * spin * iTime * (i % 2 == 0 ? 1.0 : -1.0));
  }
}

RmHit torus(int i, vec3 p) {
  vec3 q = opRotate(opRotate(p - centres[i], uprights[i]), spins[i]);
  return rmHit(sdTorus(q, vec2(0.6, 0.13)), float(i));
}

RmHit chain(vec3 p) {
  RmHit h = torus(0, p);
  for (int i = 1; i < 5; ++i) h = opUnion(h, torus(i, p));
  return h;
}

float map(vec3 p) { return chain(p).d; }

RmMaterial material(vec3 p, vec3 n) {
  RmMaterial m = rmMaterial(0.55 + 0.4 * cos(vec3(0.0, 2.1, 4.2) + 0.9 * chain(p).id));
  m.specular = 0.8;
  m.shininess = 64.0;
  return m;
}

RmMaterial groundMaterial(vec3 p) {
  RmMaterial m = rmMaterial(vec3(0.2, 0.22, 0.25));
  m.reflectivity = polish;
  return m;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  animate();
  RmCamera cam = rmLookAt(rmOrbit(vec3(0.0), 5.2, 0.25 * sin(0.2 * iTime), 0.35), vec3(0.0, -0.2, 0.0), 0.8);
  vec3 color = rmRenderPixel(cam, fragCoord, iResolution);
  fragColor = vec4(rmLinearToSrgb(rmToneMapACES(color)), 1.0);
}
