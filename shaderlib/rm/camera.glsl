// rm/camera.glsl: a look-at pinhole camera, primary rays from fragCoord with the
// right aspect ratio and field of view, the pixel cone for the march, and an
// orbit helper.
// Provides: RmCamera, rmLookAt, rmCameraRay, rmPixelCone, rmOrbit.
// Needs: rm/common.glsl (included).
#ifndef RM_CAMERA_GLSL
#define RM_CAMERA_GLSL

#include <rm/common.glsl>

// A pinhole camera; make one with rmLookAt.
struct RmCamera {
  vec3 position;
  mat3 basis;   // columns: right, up, forward (determinant -1: forward is the view direction)
  float focal;  // 1 / tan(fovY / 2)
};

// Camera at eye looking at target, +y up, vertical field of view fovY
// (radians). Looking straight up or down, or at itself, stays finite.
RmCamera rmLookAt(vec3 eye, vec3 target, float fovY) {
  vec3 forward = rmSafeNormalize(target - eye, vec3(0.0, 0.0, -1.0));
  vec3 up = abs(forward.y) > 0.9999 ? vec3(0.0, 0.0, -sign(forward.y)) : vec3(0.0, 1.0, 0.0);
  vec3 right = normalize(cross(forward, up));
  return RmCamera(eye, mat3(right, cross(right, forward), forward), 1.0 / tan(0.5 * fovY));
}

// Unit direction of the ray through fragCoord for an image of iResolution
// `resolution` (z: pixel aspect, 1 for square pixels; 0 is taken as 1).
vec3 rmCameraRay(RmCamera camera, vec2 fragCoord, vec3 resolution) {
  float aspect = resolution.z > 0.0 ? resolution.z : 1.0;
  vec2 uv = vec2((2.0 * fragCoord.x - resolution.x) * aspect, 2.0 * fragCoord.y - resolution.y) /
            max(resolution.y, 1.0);
  return normalize(camera.basis * vec3(uv, camera.focal));
}

// Half a pixel's footprint per unit of t (tan(fovY / 2) / height): the march's hit
// threshold per unit t (RmMarchSettings.cone).
float rmPixelCone(RmCamera camera, vec3 resolution) { return 1.0 / (camera.focal * max(resolution.y, 1.0)); }

// Eye position orbiting target at `distance`: yaw turns around +y from +z, pitch raises it (radians).
vec3 rmOrbit(vec3 target, float distance, float yaw, float pitch) {
  return target + distance * vec3(sin(yaw) * cos(pitch), sin(pitch), cos(yaw) * cos(pitch));
}

#endif  // RM_CAMERA_GLSL
