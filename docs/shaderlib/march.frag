// rm/march.glsl: map() evaluations per pixel, plain sphere tracing (left)
// against over-relaxation with omega = 1.2 (right), blue = few, yellow = many,
// magenta = out of steps. Grazing rays along the floor cost the most; that is
// where over-relaxation saves steps.
#include "scene.glsl"
#include <rm/march.glsl>
#include <rm/camera.glsl>

float map(vec3 p) { return min(objects(p).d, p.y + 0.5); }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  RmCamera cam = rmLookAt(vec3(0.0, 1.0, 4.5), vec3(0.0, -0.2, 0.0), 0.9);
  RmMarchSettings s = rmMarchSettings();
  s.cone = rmPixelCone(cam, iResolution);
  s.maxSteps = 120;
  s.omega = fragCoord.x < 0.5 * iResolution.x ? 1.0 : 1.2;
#ifdef OMEGA  // scripts/shaderlib-docs --measure: the raw count over the whole frame
  s.omega = OMEGA;
  s.maxSteps = 400;
#endif
  RmMarch m = rmMarch(cam.position, rmCameraRay(cam, fragCoord, iResolution), s);
#ifdef OMEGA
  fragColor = vec4(float(m.steps) / 1000.0, 0.0, 0.0, 1.0);
  return;
#endif
  float heat = clamp(float(m.steps) / 80.0, 0.0, 1.0);
  vec3 color = mix(mix(vec3(0.1, 0.15, 0.5), vec3(0.1, 0.7, 0.6), smoothstep(0.0, 0.4, heat)),
                   vec3(1.0, 0.9, 0.2), smoothstep(0.4, 1.0, heat));
  if (m.outcome == RM_OUT_OF_STEPS) color = vec3(1.0, 0.0, 1.0);
  if (abs(fragCoord.x - 0.5 * iResolution.x) < 1.0) color = vec3(1.0);
  fragColor = vec4(color, 1.0);
}
