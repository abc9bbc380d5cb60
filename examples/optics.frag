// optics.frag: spectacles in front of a phone, beside a mirror. The lenses are
// converging (each is the intersection of two spheres), so through them the
// phone's screen looks magnified. The screen is iChannel0, triplanar-mapped;
// without --channel0 the host loads the texture named below. The mirror shows
// the scene from the side. Drag with the left mouse button to move the sun.
#pragma channel0 "textures/phone_screen.png"
#define RM_SHADOWS 2
#define RM_AO
#define RM_REFLECTIONS 1
#define RM_REFRACTION 5
#define RM_GROUND 0.0
#define RM_BOUNDING_SPHERE vec4(0.7, 1.0, -0.3, 2.6)  // spectacles, phone and mirror
#include <rm/sdf.glsl>
#include <rm/ops.glsl>
#include <rm/transforms.glsl>
#include <rm/camera.glsl>
#include <rm/texture.glsl>
#include <rm/render.glsl>

const float kGlass = 1.0, kFrame = 2.0, kPhone = 3.0, kScreen = 4.0, kMirror = 5.0, kMirrorFrame = 6.0;

// A biconvex lens facing z: two spheres of radius 0.9 whose overlap is 0.14 thick.
float lens(vec3 p) {
  return max(sdSphere(p - vec3(0.0, 0.0, -0.83), 0.9), sdSphere(p + vec3(0.0, 0.0, -0.83), 0.9));
}

// The spectacles, centred at the origin, looking along +z.
RmHit spectacles(vec3 p) {
  vec3 q = opSymmetryX(p) - vec3(0.42, 0.0, 0.0);  // both eyes from one
  RmHit glass = rmHit(lens(q), kGlass);
  float rim = sdTorus(q.xzy, vec2(0.35, 0.025));
  float bridge = sdCapsule(p, vec3(-0.08, 0.06, 0.0), vec3(0.08, 0.06, 0.0), 0.02);
  float temple = sdCapsule(q, vec3(0.35, 0.05, 0.0), vec3(0.38, 0.05, -1.0), 0.02);
  return opUnion(glass, rmHit(min(min(rim, bridge), temple), kFrame));
}

// The phone, leaning back a little; its screen faces +z.
vec3 phoneSpace(vec3 p) { return opRotate(p - vec3(0.0, 0.9, -0.55), rmRotationX(-0.15)); }

RmHit phone(vec3 p) {
  vec3 q = phoneSpace(p);
  float body = sdRoundBox(q, vec3(0.45, 0.9, 0.04), 0.04);
  return rmHit(body, q.z > 0.035 && max(abs(q.x) - 0.4, abs(q.y) - 0.82) < 0.0 ? kScreen : kPhone);
}

// A tall mirror on the right, turned to show the phone and spectacles.
RmHit mirror(vec3 p) {
  vec3 q = opRotate(p - vec3(1.9, 1.2, -0.6), rmRotationY(-0.6));
  float glass = sdBox(q, vec3(0.6, 1.1, 0.02));
  float frame = opSubtraction(sdBox(q, vec3(0.68, 1.18, 0.05)), sdBox(q, vec3(0.6, 1.1, 0.1)));
  return opUnion(rmHit(glass, kMirror), rmHit(frame, kMirrorFrame));
}

// The spectacles' slow turn, worked out once a pixel in mainImage instead of
// at every map() call.
mat3 spectaclesTurn;

RmHit scene(vec3 p) {
  RmHit h = spectacles(opRotate(p - vec3(0.0, 0.85, 0.55), spectaclesTurn));
  return opUnion(opUnion(h, phone(p)), mirror(p));
}

float map(vec3 p) { return scene(p).d; }

RmMaterial material(vec3 p, vec3 n) {
  float id = scene(p).id;
  RmMaterial m = rmMaterial(vec3(0.1));
  if (id == kGlass) {
    m.transparency = 1.0;
    m.ior = 1.5;
    m.absorption = vec3(0.05, 0.03, 0.02);
    m.specular = 1.0;
    m.shininess = 300.0;
  } else if (id == kScreen) {
    // Triplanar mapping of iChannel0 in the phone's own frame, scaled so the
    // screen (0.8 x 1.64) spans the texture once.
    vec3 q = phoneSpace(p);
    vec3 uvw = vec3(q.x / 0.8 + 0.5, q.y / 1.64 + 0.5, q.z);
    m.albedo = 0.2 * rmTriplanar(iChannel0, uvw, opRotate(n, rmRotationX(-0.15)), 1.0, 8.0).rgb;
    m.emission = 4.0 * m.albedo;  // a lit screen
    m.specular = 0.6;
  } else if (id == kMirror) {
    m.albedo = vec3(0.9);
    m.reflectivity = 0.9;
  } else if (id == kMirrorFrame) {
    m.albedo = vec3(0.45, 0.3, 0.15);
  }
  return m;
}

RmMaterial groundMaterial(vec3 p) { return rmMaterial(mix(vec3(0.5, 0.45, 0.4), vec3(0.6, 0.55, 0.5), rmChecker(p.xz * 2.0))); }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  spectaclesTurn = rmRotationY(0.25 * sin(0.5 * iTime));
  RmCamera cam = rmLookAt(vec3(-0.6, 1.2, 3.1), vec3(0.3, 0.85, 0.0), 0.7);
  vec3 color = rmRenderPixel(cam, fragCoord, iResolution);
  fragColor = vec4(rmLinearToSrgb(rmToneMapACES(color)), 1.0);
}
