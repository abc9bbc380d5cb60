// cubes.frag: an endless grid of cubes from one cube, by domain repetition.
// rm/grid.glsl hands mapCell each cell's id; the colour, the size and the
// spin of every cube come from a hash of it. Drag with the left mouse button to move
// the sun.
#define RM_SHADOWS 1  // a soft shadow reads the cell-border term in map() as a near miss
// In an endless grid nearly every sun ray meets a cube far away: only the
// cubes of the next two cells cast shadows.
#define RM_SHADOW_REACH 4.0
#define RM_FOG 0.07
#define RM_MAX_STEPS 200
#define RM_SCENE_BACKGROUND
// The grid: rays cross the cells whose cube they miss in one step each. A
// cube of half-size 0.4 turns within 0.4 sqrt(3) = 0.69 of its cell's centre.
#define RM_GRID_PERIOD vec3(1.8)
#define RM_GRID_RADIUS 0.7
#define RM_GRID_CONVEX  // a shadow ray leaving a cube never meets it again
// Each cube's own bounding sphere (cellRadius): rays pass the small ones'
// cells in one step.
#define RM_GRID_CELL_RADIUS
#include <rm/sdf.glsl>
#include <rm/transforms.glsl>
#include <rm/texture.glsl>
#include <rm/camera.glsl>
#include <rm/render.glsl>

vec3 background(vec3 rd) { return vec3(0.05, 0.07, 0.12); }

// Half the side of the cube whose cell hashes to h.
float cubeSize(vec3 h) { return 0.3 + 0.1 * h.y; }

// The cube of one cell; rm/grid.glsl makes map() from it. Each cube turns
// about its own axis, so a neighbour's corner can come nearer than this cell's
// cube: map() never steps past the border by more than the gap every cube
// leaves (half-period 0.9 minus the radius 0.7).
float mapCell(vec3 q, vec3 cell) {
  vec3 h = rmHash3(ivec3(cell));
  return sdRoundBox(opRotateAxis(q, h - 0.5, iTime * (0.3 + h.x)), vec3(cubeSize(h)), 0.05);
}

// The rounded cube's corners, however it turns: the box within it reaches
// sqrt(3) times its half-size less the rounding, and the rounding adds to it.
float cellRadius(vec3 cell) {
  return sqrt(3.0) * (cubeSize(rmHash3(ivec3(cell))) - 0.05) + 0.05 + 1e-3;
}

RmMaterial material(vec3 p, vec3 n) {
  vec3 cell = round(p / RM_GRID_PERIOD);
  RmMaterial m = rmMaterial(0.5 + 0.45 * cos(RM_TAU * (rmHash(cell) + vec3(0.0, 0.33, 0.67))));
  m.specular = 0.5;
  return m;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  // The camera drifts through the grid, off the planes between the cells
  // (rays along those planes would graze cube after cube).
  vec3 eye = vec3(0.31, 0.92, 0.2) + iTime * vec3(0.3, 0.1, -0.6);
  RmCamera cam = rmLookAt(eye, eye + vec3(0.4, -0.15, -1.0), 1.0);
  vec3 color = rmRenderPixel(cam, fragCoord, iResolution);
  fragColor = vec4(rmLinearToSrgb(rmToneMapACES(color)), 1.0);
}
