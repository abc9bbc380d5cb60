// rm/transforms.glsl, left to right: twist, bend, polar repetition, limited
// repetition coloured by cell id, elongation, onion (cut open) and mirror.
// Classic soft shadows: the improved form reads the jump at the bounding
// volumes of twist and bend below as a near miss and speckles.
#define RM_SHADOWS 2
#define RM_AO
#define RM_GROUND -0.6
#include <rm/sdf.glsl>
#include <rm/ops.glsl>
#include <rm/transforms.glsl>
#include <rm/camera.glsl>
#include <rm/render.glsl>

RmHit item(int i, vec3 p) {
  vec3 cell = vec3(0.0);
  float d;
  switch (i) {
    case 0: {
      // Twist stretches space more the farther from the axis. Inside a tight
      // bounding volume (within radius 0.4) divide by the constant for that
      // radius; outside, the distance to the volume is a bound and costs nothing.
      float bound = sdCappedCylinder(p, 0.33, 0.55);
      d = bound > 0.05 ? bound : sdBox(opTwist(p, 2.5), vec3(0.2, 0.5, 0.2)) / opTwistLipschitz(2.5, 0.4);
      break;
    }
    case 1: {
      float bound = opExtrude(p, sdCircle(p.xy, 0.5), 0.2);
      d = bound > 0.05 ? bound : sdBox(opBend(p, 1.2), vec3(0.45, 0.08, 0.15)) / opBendLipschitz(1.2, 0.55);
      break;
    }
    case 2: {
      float k;
      vec2 q = opRepeatPolar(p.xz, 7.0, k);
      d = sdCappedCylinder(vec3(q.x - 0.3, p.y, q.y), 0.07, 0.45);
      cell.x = k;
      break;
    }
    case 3:
      d = sdBox(opRepeatLimited(p, vec3(0.3), vec3(-1.0), vec3(1.0), cell), vec3(0.1));
      break;
    case 4:
      d = sdSphere(opElongate(p, vec3(0.0, 0.3, 0.1)), 0.18);
      break;
    case 5:
      d = opSubtraction(opOnion(sdSphere(p, 0.4), 0.04), -p.z);  // front half removed
      break;
    default:
      d = sdTorus((opMirror(p, vec3(0.7071, 0.0, 0.7071)) - vec3(0.15, 0.0, 0.15)).xzy, vec2(0.17, 0.06));
  }
  return rmHit(d, dot(cell, vec3(1.0, 3.0, 9.0)) + 13.0 * float(i));
}

RmHit scene(vec3 p) {
  RmHit best = rmHit(1e10, 0.0);
  for (int i = 0; i < 7; ++i) best = opUnion(best, item(i, p - vec3(1.1 * (float(i) - 3.0), 0.0, 0.0)));
  return best;
}

float map(vec3 p) { return scene(p).d; }

RmMaterial material(vec3 p, vec3 n) {
  return rmMaterial(0.55 + 0.4 * cos(vec3(0.0, 2.0, 4.0) + 0.7 * scene(p).id));
}

RmMaterial groundMaterial(vec3 p) { return rmMaterial(vec3(0.5)); }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  RmCamera cam = rmLookAt(vec3(0.0, 1.3, 4.8), vec3(0.0, -0.1, 0.0), 0.55);
  vec3 color = rmRenderPixel(cam, fragCoord, iResolution);
  fragColor = vec4(rmLinearToSrgb(rmToneMapACES(color)), 1.0);
}
