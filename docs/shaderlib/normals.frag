// rm/normals.glsl: normals from 4 taps (left) and 6 taps (right), shown as
// colour (x, y, z mapped to red, green, blue).
#include "scene.glsl"
#include <rm/march.glsl>
#include <rm/normals.glsl>
#include <rm/camera.glsl>

float map(vec3 p) { return min(objects(p).d, p.y + 0.5); }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  RmCamera cam = rmLookAt(vec3(0.0, 1.0, 4.5), vec3(0.0, -0.2, 0.0), 0.9);
  RmMarchSettings s = rmMarchSettings();
  s.cone = rmPixelCone(cam, iResolution);
  vec3 rd = rmCameraRay(cam, fragCoord, iResolution);
  RmMarch m = rmMarch(cam.position, rd, s);
  vec3 color = vec3(0.1);
  if (m.outcome == RM_HIT) {
    vec3 p = cam.position + rd * m.t;
    float eps = rmNormalEpsilon(p, m.tolerance);
    vec3 n = fragCoord.x < 0.5 * iResolution.x ? rmNormalTetrahedron(p, eps) : rmNormalCentral(p, eps);
    color = 0.5 + 0.5 * n;
  }
  fragColor = vec4(color, 1.0);
}
