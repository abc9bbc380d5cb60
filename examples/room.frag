// room.frag: a ball travels a figure-eight inside a room of planes. Two
// lights show the two kinds of shadow: the lamp (yellow) casts hard shadows,
// the sun (white, dragged with the left mouse button) soft ones.
// This scene uses shaderlib's building blocks directly: march, normals,
// lights and shadows, no rm/render.glsl.
#include <rm/sdf.glsl>
#include <rm/march.glsl>
#include <rm/normals.glsl>
#include <rm/lighting.glsl>
#include <rm/camera.glsl>

// The ball's centre depends on the time only: worked out once a pixel, at the
// start of mainImage, not in each of the dozens of map() calls a pixel makes.
vec3 ballCentre;

vec3 ballCentreAt(float time) {
  float t = 0.7 * time;
  return vec3(1.6 * sin(t), 0.45 + 0.25 * abs(sin(2.0 * t)), -0.8 + 1.1 * sin(2.0 * t));
}

// The room: a floor and three walls, each an exact plane, open to the sky
// and toward the camera. x is the distance, y which surface it is.
vec2 room(vec3 p) {
  vec2 nearest = vec2(p.y, 1.0);                                  // floor
  if (p.z + 3.0 < nearest.x) nearest = vec2(p.z + 3.0, 2.0);      // back wall
  if (3.0 - abs(p.x) < nearest.x) nearest = vec2(3.0 - abs(p.x), 3.0);  // side walls
  return nearest;
}

vec2 scene(vec3 p) {
  vec2 ball = vec2(sdSphere(p - ballCentre, 0.45), 0.0);
  vec2 walls = room(p);
  return ball.x < walls.x ? ball : walls;
}

float map(vec3 p) { return scene(p).x; }

// The material of the nearest surface: choosing by distance, not by testing
// p.y < 0.01, keeps far hits (which lie up to the hit tolerance off the
// surface) on the right material.
vec3 albedo(vec3 p) {
  float id = scene(p).y;
  return id == 0.0 ? vec3(0.85, 0.2, 0.15) : id == 1.0 ? vec3(0.6, 0.55, 0.5)
       : id == 2.0 ? vec3(0.45, 0.55, 0.7) : vec3(0.75);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  ballCentre = ballCentreAt(iTime);
  RmCamera cam = rmLookAt(vec3(0.0, 1.6, 5.5), vec3(0.0, 1.0, -1.0), 0.95);
  vec3 rd = rmCameraRay(cam, fragCoord, iResolution);
  RmMarchSettings s = rmMarchSettings();
  s.cone = rmPixelCone(cam, iResolution);
  RmMarch m = rmMarch(cam.position, rd, s);
  vec3 color = mix(vec3(0.6, 0.7, 0.85), vec3(0.3, 0.45, 0.75), max(rd.y, 0.0));  // sky
  if (m.outcome == RM_HIT) {
    vec3 p = cam.position + rd * m.t;
    vec3 n = rmNormal(p, m.tolerance);
    float offset = rmSurfaceOffset(p, m.tolerance);
    RmMaterial mat = rmMaterial(albedo(p));
    color = vec3(0.0);
    vec3 from = p + n * offset;

    // The lamp above the room: a point light with a hard shadow.
    RmLight lamp = rmPointLight(vec3(-1.2, 3.2, 0.5), vec3(5.0, 4.0, 2.5));
    float hard = rmHardShadow(from, rmLightDirection(lamp, p), offset, rmLightDistance(lamp, p));
    color += rmShade(p, n, -rd, mat, lamp, hard);

    // The sun: far away, moved by the mouse, with a soft shadow.
    vec3 toWindow = rmMouseLightDirection(iMouse, iResolution.xy, vec3(0.3, 0.75, 0.6));
    RmLight window = rmDirectionalLight(toWindow, vec3(0.8));
    float soft = rmSoftShadowImproved(from, toWindow, offset, 12.0, 12.0);
    color += rmShade(p, n, -rd, mat, window, soft);

    color += mat.albedo * 0.08 * rmAmbientOcclusion(p, n);
  }
  fragColor = vec4(rmLinearToSrgb(rmToneMapACES(color)), 1.0);
}
