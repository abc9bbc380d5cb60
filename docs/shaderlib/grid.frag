// rm/grid.glsl: steps per pixel through an endless grid of spheres, cell by
// cell with rmMarchGrid (left) against rmMarch's plain sphere tracing of the
// same grid (right), blue = few, yellow = many, magenta = out of steps. The
// plain march creeps past every sphere it nearly meets and along the planes
// between the cells; cell by cell, a ray crosses a cell whose sphere it misses
// in one step.
#define RM_GRID_PERIOD vec3(1.5)
#define RM_GRID_RADIUS 0.5
#include <rm/grid.glsl>
#include <rm/camera.glsl>
#include <rm/texture.glsl>

// Each cell's sphere, its size from a hash of the cell.
float mapCell(vec3 q, vec3 cell) { return length(q) - (0.2 + 0.3 * rmHash(cell)); }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  RmCamera cam = rmLookAt(vec3(0.7, 0.65, 0.0), vec3(3.0, 1.4, -8.0), 1.0);
  RmMarchSettings s = rmMarchSettings();
  s.cone = rmPixelCone(cam, iResolution);
  s.maxSteps = 200;
  s.tMax = 60.0;
  vec3 rd = rmCameraRay(cam, fragCoord, iResolution);
  bool cells = fragCoord.x < 0.5 * iResolution.x;
  RmMarch m = cells ? rmMarchGrid(cam.position, rd, s) : rmMarch(cam.position, rd, s);
  float heat = clamp(float(m.steps) / 100.0, 0.0, 1.0);
  vec3 color = mix(mix(vec3(0.1, 0.15, 0.5), vec3(0.1, 0.7, 0.6), smoothstep(0.0, 0.4, heat)),
                   vec3(1.0, 0.9, 0.2), smoothstep(0.4, 1.0, heat));
  if (m.outcome == RM_OUT_OF_STEPS) color = vec3(1.0, 0.0, 1.0);
  if (abs(fragCoord.x - 0.5 * iResolution.x) < 1.0) color = vec3(1.0);
  fragColor = vec4(color, 1.0);
}
