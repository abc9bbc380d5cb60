// rm/sdf.glsl: signed distance functions of 3D primitives (iq's sd* names).
// Provides: sdSphere, sdBox, sdPlane, sdTorus, sdCapsule.
// Needs: nothing.
// Every function is *exact* unless it says otherwise: its value is the
// Euclidean distance to the surface, negative inside.
#ifndef RM_SDF_GLSL
#define RM_SDF_GLSL

// Sphere of radius r at the origin. exact
float sdSphere(vec3 p, float r) { return length(p) - r; }

// Box with half-extents b, centred at the origin. exact
float sdBox(vec3 p, vec3 b) {
  vec3 q = abs(p) - b;
  return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}

// Plane through the origin with unit normal n, shifted by h along n. exact (n unit)
float sdPlane(vec3 p, vec3 n, float h) { return dot(p, n) + h; }

// Torus in the xz plane: t.x major radius, t.y tube radius. exact
float sdTorus(vec3 p, vec2 t) {
  vec2 q = vec2(length(p.xz) - t.x, p.y);
  return length(q) - t.y;
}

// Capsule: segment a-b swept by radius r. exact
float sdCapsule(vec3 p, vec3 a, vec3 b, float r) {
  vec3 pa = p - a, ba = b - a;
  float h = clamp(dot(pa, ba) / dot(ba, ba), 0.0, 1.0);
  return length(pa - ba * h) - r;
}

#endif  // RM_SDF_GLSL
