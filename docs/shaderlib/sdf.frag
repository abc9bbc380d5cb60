// rm/sdf.glsl: the 3D primitives, one per cell, lit by rm/render.glsl.
#define RM_SHADOWS 3
#define RM_AO
#define RM_GROUND -0.5
#include <rm/sdf.glsl>
#include <rm/transforms.glsl>
#include <rm/camera.glsl>
#include <rm/render.glsl>

const vec3 kCell = vec3(1.2, 1.0, 1.2);

float primitive(int i, vec3 p) {
  switch (i) {
    case 0: return sdSphere(p, 0.4);
    case 1: return sdBox(p, vec3(0.35));
    case 2: return sdRoundBox(p, vec3(0.35), 0.1);
    case 3: return sdBoxFrame(p, vec3(0.35), 0.04);
    case 4: return sdTorus(p, vec2(0.3, 0.1));
    case 5: return sdCappedTorus(p.xzy, vec2(sin(2.2), cos(2.2)), 0.3, 0.07);
    case 6: return sdLink(p, 0.15, 0.2, 0.07);
    case 7: return sdCapsule(p, vec3(-0.25, -0.3, 0.0), vec3(0.25, 0.3, 0.0), 0.12);
    case 8: return sdCappedCylinder(p, 0.3, 0.35);
    case 9: return sdRoundedCylinder(p, 0.3, 0.35, 0.08);
    case 10: return sdCappedCone(p, 0.35, 0.35, 0.12);
    case 11: return sdRoundCone(p + vec3(0.0, 0.25, 0.0), 0.25, 0.1, 0.5);
    case 12: return sdSolidAngle(p + vec3(0.0, 0.4, 0.0), vec2(sin(0.6), cos(0.6)), 0.75);
    case 13: return sdCutSphere(p, 0.4, 0.1);
    case 14: return sdCutHollowSphere(p, 0.4, 0.15, 0.03);
    case 15: return sdEllipsoid(p, vec3(0.4, 0.25, 0.3));
    case 16: return sdOctahedron(p, 0.45);
    case 17: return opScaleDistance(sdPyramid(opScale(p + vec3(0.0, 0.35, 0.0), 0.7), 1.0), 0.7);
    case 18: return sdHexPrism(p, vec2(0.3, 0.2));
    case 19: return sdTriPrism(p, vec2(0.4, 0.2));
    case 20: return sdRhombus(p, 0.4, 0.25, 0.08, 0.05);
    case 21: return sdVerticalCapsule(p + vec3(0.0, 0.35, 0.0), 0.7, 0.15);
    case 22: return opExtrude(p, sdEquilateralTriangle(p.xy, 0.35), 0.15);
    default: return sdTrapezoid(opRevolve(p, 0.0), 0.35, 0.1, 0.35);
  }
}

// The union of all 24; a primitive is evaluated only when its bounding
// sphere is nearer than what is already found.
float map(vec3 p) {
  float d = 1e10;
  for (int i = 0; i < 24; ++i) {
    vec3 centre = vec3(float(i % 6) - 2.0, 0.0, float(i / 6) - 1.0) * kCell;
    if (length(p - centre) - 0.6 < d) d = min(d, primitive(i, p - centre));
  }
  return d;
}

RmMaterial material(vec3 p, vec3 n) {
  vec3 cell = round(p / kCell);
  return rmMaterial(0.55 + 0.4 * cos(vec3(0.0, 2.0, 4.0) + 0.9 * (cell.x + 3.0 * cell.z)));
}

RmMaterial groundMaterial(vec3 p) { return rmMaterial(vec3(0.45)); }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  RmCamera cam = rmLookAt(vec3(0.6, 5.2, 6.6), vec3(0.6, -0.4, 0.55), 0.75);
  vec3 color = rmRenderPixel(cam, fragCoord, iResolution);
  fragColor = vec4(rmLinearToSrgb(rmToneMapACES(color)), 1.0);
}
