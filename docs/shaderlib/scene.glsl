// A small shared scene for the docs pictures: a sphere, a torus and a box on
// the ground (y = -0.5), with object ids for materials.
#include <rm/sdf.glsl>
#include <rm/ops.glsl>
#include <rm/transforms.glsl>

RmHit objects(vec3 p) {
  RmHit h = rmHit(sdSphere(p - vec3(-1.1, 0.05, 0.0), 0.55), 1.0);
  h = opUnion(h, rmHit(sdTorus(opRotate(p - vec3(0.1, 0.0, -0.3), rmRotationX(1.2)), vec2(0.45, 0.15)), 2.0));
  h = opUnion(h, rmHit(sdRoundBox(opRotate(p - vec3(1.2, -0.15, 0.2), rmRotationY(0.6)), vec3(0.35), 0.05), 3.0));
  return h;
}
