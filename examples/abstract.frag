// abstract.frag: one sculpture from smooth booleans, twist and bend. A twisted
// column melts into a bent ring, three orbiting blobs merge with both, and a
// sphere is carved out of the middle. Colours blend across the smooth seams
// through RmHit. Drag with the left mouse button to move the sun.
#define RM_SHADOWS 2
#define RM_AO
#define RM_GROUND -1.2
#define RM_BOUNDING_SPHERE vec4(0.0, 0.1, 0.0, 1.9)  // the whole sculpture
// Fewer AO taps and shadow steps than shaderlib's defaults (5 and 64), picked
// from docs/accuracy.md: they hold the picture's PSNR against the reference
// and cost 13% less. --quality and -D choose their own.
#if !defined(RM_QUALITY) && !defined(RM_AO_SAMPLES)
#define RM_AO_SAMPLES 3
#endif
#if !defined(RM_QUALITY) && !defined(RM_SHADOW_STEPS)
#define RM_SHADOW_STEPS 16
#endif
#include <rm/sdf.glsl>
#include <rm/ops.glsl>
#include <rm/transforms.glsl>
#include <rm/camera.glsl>
#include <rm/render.glsl>

// Twist and bend stretch space, so their distances are divided by their
// Lipschitz constant for the region where they are evaluated exactly: within
// kFar of a tight bounding cylinder. Farther out the distance to that
// cylinder is used, which is a bound and cheap. kFar exceeds the smooth blend
// widths below, so every blend sees true shapes, never the bounding cylinder.
const float kFar = 0.4;

// What depends on the time only, worked out once a pixel instead of at every
// map() call: llvmpipe evaluates map() dozens of times a pixel.
float twist;                 // the column's twist rate
float twistLipschitz;
mat3 ringTurn;               // the ring's rocking
vec3 blobs[3];               // the orbiting blobs' centres

void animate() {
  twist = 1.2 * sin(0.5 * iTime);
  twistLipschitz = opTwistLipschitz(twist, 0.45 + kFar);
  ringTurn = rmRotationZ(0.3 * sin(0.7 * iTime));
  for (int i = 0; i < 3; ++i) {
    float a = iTime * 0.6 + RM_TAU * float(i) / 3.0;
    blobs[i] = vec3(1.1 * cos(a), 0.6 * sin(1.3 * a), 1.1 * sin(a));
  }
}

// A column twisted about y (the cylinder's radius 0.45 holds the column).
float column(vec3 p) {
  float bound = sdCappedCylinder(p, 0.45, 1.25);
  if (bound > kFar) return bound;
  return sdRoundBox(opTwist(p, twist), vec3(0.3, 1.1, 0.3), 0.08) / twistLipschitz;
}

// A torus bent in its own plane, lying across the column.
float ring(vec3 p) {
  vec3 q = opRotate(p - vec3(0.0, 0.2, 0.0), ringTurn);
  float bound = sdCappedCylinder(q.xzy, 1.15, 0.2);  // around the ring, axis along z
  if (bound > kFar) return bound;
  return sdTorus(opBend(q, 0.25).xzy, vec2(0.95, 0.16)) / opBendLipschitz(0.25, 1.15 + kFar);
}

RmHit sculpture(vec3 p) {
  RmHit h = opSmoothUnion(rmHit(column(p), 0.0), rmHit(ring(p), 1.0), 0.3);
  for (int i = 0; i < 3; ++i) h = opSmoothUnion(h, rmHit(sdSphere(p - blobs[i], 0.28), 2.0 + float(i)), 0.35);
  // Carve a hollow through the middle; its wall takes the carving's colour.
  return opSmoothSubtraction(h, rmHit(sdSphere(p - vec3(0.0, 0.2, 0.0), 0.42), 5.0), 0.1);
}

float map(vec3 p) { return sculpture(p).d; }

vec3 palette(float id) { return 0.55 + 0.4 * cos(vec3(0.0, 2.0, 4.0) + 1.4 * id); }

RmMaterial material(vec3 p, vec3 n) {
  RmHit h = sculpture(p);
  RmMaterial m = rmMaterial(rmHitBlend(h, palette(h.id), palette(h.id2)));
  m.specular = 0.6;
  m.shininess = 40.0;
  return m;
}

RmMaterial groundMaterial(vec3 p) { return rmMaterial(vec3(0.45)); }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  animate();
  RmCamera cam = rmLookAt(rmOrbit(vec3(0.0), 5.0, 0.15 * iTime, 0.3), vec3(0.0, -0.1, 0.0), 0.85);
  vec3 color = rmRenderPixel(cam, fragCoord, iResolution);
  fragColor = vec4(rmLinearToSrgb(rmToneMapACES(color)), 1.0);
}
