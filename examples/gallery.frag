// gallery.frag: nine objects on plinths, three rows of three: primitives
// (back), transforms (middle) and smooth booleans (front). Three coloured
// lights circle the room and change colour over time; the first one follows
// the mouse (drag with the left button).
// Classic soft shadows: the improved form speckles at the jumps of the
// nearest-cell field between plinths (docs/shaderlib.md).
#define RM_SHADOWS 2
#define RM_AO
#define RM_LIGHT_COUNT 3
#define RM_GROUND 0.0
// All nine plinths and what stands on them: a box fits the flat layout
// tighter than a sphere, so shadow rays from the floor leave it sooner.
#define RM_BOUNDING_BOX_MIN vec3(-2.1, -0.01, -2.1)
#define RM_BOUNDING_BOX_MAX vec3(2.1, 1.5, 2.1)
// Every exhibit lies in a sphere about its slot's centre: rays, shadow rays and
// AO cross the room and the plinths on those spheres (mapBound), and run the
// switch of nine exhibits only near one. A CPU renderer runs every case of the
// switch in every map() call, so fewer calls is what makes it faster.
#define RM_MAP_BOUND
// Its own interactive settings, chosen from its accuracy sweep
// (docs/accuracy.md): finer hits and shorter shadow rays are both nearer the
// reference (31.3 dB, not 28.9) and 11% faster than the library's defaults.
// A --quality preset sets its own instead.
#ifndef RM_QUALITY
#define RM_HIT_PIXELS 0.35
#define RM_SHADOW_STEPS 12
#endif
#include <rm/sdf.glsl>
#include <rm/ops.glsl>
#include <rm/transforms.glsl>
#include <rm/camera.glsl>
#include <rm/render.glsl>

const float kSpacing = 1.6;

// What depends on the time only, worked out once a pixel in animate()
// instead of at every map() call: llvmpipe evaluates map() dozens of times a
// pixel, and every case of the switch below in each of them.
mat3 turn;        // every exhibit turns about y
float swing;      // sin(t): the twist's rate, the onion's cut, the carving's size
float bob;        // the smooth-union sphere's height
float twistLipschitz;
// The lights' colours, and the key light's direction from the mouse: the
// library's light loop calls light(i) once a light and shading, and llvmpipe
// runs both of its branches each time (2 ms a frame when worked out there).
vec3 hues[3];
vec3 keyDirection;

void animate() {
  turn = rmRotationY(0.5 * iTime);
  swing = sin(iTime);
  bob = 0.25 * sin(2.0 * iTime);
  twistLipschitz = opTwistLipschitz(2.0, 0.55);
  for (int i = 0; i < 3; ++i) hues[i] = 0.6 + 0.4 * cos(vec3(0.0, 2.1, 4.2) + 0.7 * iTime + 2.1 * float(i));
  keyDirection = rmMouseLightDirection(iMouse, iResolution.xy, vec3(0.4, 0.8, 0.5));
}

// Radius of the sphere about its slot's centre that holds each exhibit, turned
// and animated (the smooth union's sphere bobs up to 0.25 and bulges k / 4).
const float kExhibitRadius[9] = float[](0.43, 0.39, 0.51, 0.47, 0.5, 0.42, 0.52, 0.41, 0.54);

// The front row: a sphere and a box joined by a smooth union (6), cut to
// their smooth intersection (7), and a rounded box minus a sphere (8). Each
// slot sizes its sphere and box, and the three share one evaluation of them:
// llvmpipe evaluates every case of exhibit()'s switch.
float frontRow(int i, vec3 p) {
  vec3 sphereCentre = i == 6 ? vec3(0.0, bob, 0.0) : vec3(0.0);
  float sphereRadius = i == 6 ? 0.22 : i == 7 ? 0.4 : 0.33 + 0.05 * swing;
  vec3 boxSize = i == 6 ? vec3(0.3, 0.08, 0.3) : vec3(i == 7 ? 0.3 : 0.32);
  float sphere = sdSphere(p - sphereCentre, sphereRadius), box = sdRoundBox(p, boxSize, i == 8 ? 0.04 : 0.0);
  if (i == 6) return opSmoothUnion(sphere, box, 0.15);
  if (i == 7) return opSmoothIntersection(sphere, box, 0.08);
  return opSmoothSubtraction(box, sphere, 0.05);
}

// Object i, centred at the origin, resting 0.55 above its plinth's base.
float exhibit(int i, vec3 p) {
  p = opRotate(p, turn);
  switch (i) {
    // primitives
    case 0: return sdOctahedron(p, 0.42);
    case 1: return sdCappedTorus(p.xzy, vec2(sin(2.4), cos(2.4)), 0.3, 0.08);
    case 2: return sdRoundCone(p + vec3(0.0, 0.25, 0.0), 0.25, 0.1, 0.5);
    // transforms: twist (in its bound), polar repetition, onion cut open
    case 3: {  // twist stretches space: its constant holds within 0.55 of the axis,
               // so outside that sphere the distance is its bounding sphere's
      float bound = length(p) - kExhibitRadius[3];
      // In that sphere |y| <= 0.55, so it turns at most 1.1 radians, under a
      // quarter turn: opTwistQuarter's polynomials cost llvmpipe far less than sin and cos
      float twisted = sdBox(opTwistQuarter(p, 2.0 * swing), vec3(0.15, 0.4, 0.15)) / twistLipschitz;
      return bound > 0.55 - kExhibitRadius[3] ? bound : twisted;  // a select: a CPU renderer runs both sides of an if
    }
    case 4: {
      vec2 q = opRepeatPolarMirror(p.xz, 8);  // each capsule is symmetric about its own plane
      return sdCapsule(vec3(q.x, p.y, q.y), vec3(0.15, -0.3, 0.0), vec3(0.32, 0.3, 0.0), 0.05);
    }
    case 5: return opSubtraction(opOnion(sdSphere(p, 0.38), 0.03), p.y - 0.15 * swing);
    // smooth booleans, whose sphere and box the three evaluate once
    default: return frontRow(i, p);
  }
}

// p relative to the centre of its nearest slot, whose index goes to i.
vec3 slotSpace(vec3 p, out int i) {
  vec3 cell;
  vec3 q = opRepeatLimited(p - vec3(0.0, 0.85, 0.0), vec3(kSpacing, 10.0, kSpacing), vec3(-1.0, 0.0, -1.0),
                           vec3(1.0, 0.0, 1.0), cell);
  i = int(cell.x + 1.0) + 3 * int(cell.z + 1.0);
  return q;
}

float plinth(vec3 q) { return sdRoundBox(q + vec3(0.0, 0.6, 0.0), vec3(0.35, 0.25, 0.35), 0.03); }

RmHit scene(vec3 p) {
  // A plinth under every object, then the object nearest to p's slot only:
  // objects are far apart, so the nearest cell's object bounds the rest.
  int i;
  vec3 q = slotSpace(p, i);
  return opUnion(rmHit(plinth(q), -1.0), rmHit(exhibit(i, q), float(i)));
}

float map(vec3 p) { return scene(p).d; }

// The plinths exactly, and a bound of the exhibits: the distance to their spheres.
vec2 mapBound(vec3 p) {
  int i;
  vec3 q = slotSpace(p, i);
  return vec2(plinth(q), length(q) - kExhibitRadius[i]);
}

RmLight light(int i) {
  if (i == 0) return rmDirectionalLight(keyDirection, 0.8 * mix(vec3(1.0), hues[0], 0.25));  // near white
  float a = 0.4 * iTime + RM_TAU * float(i) / 3.0;
  return rmPointLight(vec3(3.0 * cos(a), 2.5, 3.0 * sin(a)), 5.0 * hues[i] * hues[i]);
}

RmMaterial material(vec3 p, vec3 n) {
  // On a plinth or not: the plinth alone tells, without all nine exhibits.
  int i;
  RmMaterial m = rmMaterial(plinth(slotSpace(p, i)) < 0.01 ? vec3(0.75) : vec3(0.85));
  m.specular = 0.5;
  m.shininess = 48.0;
  return m;
}

RmMaterial groundMaterial(vec3 p) { return rmMaterial(vec3(0.35)); }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  animate();
  RmCamera cam = rmLookAt(vec3(0.0, 4.2, 5.2), vec3(0.0, 0.5, 0.2), 0.8);
  vec3 color = rmRenderPixel(cam, fragCoord, iResolution);
  fragColor = vec4(rmLinearToSrgb(rmToneMapACES(color)), 1.0);
}
