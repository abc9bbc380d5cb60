// rm/optics.glsl: reflection and refraction directions, Fresnel and Beer
// absorption. rm/render.glsl follows these rays in a bounded loop (GLSL has
// no recursion).
// Provides: rmReflect, rmRefract, rmFresnelF0, rmFresnelSchlick, rmFresnel,
//   rmBeer.
// Needs: nothing.
// Conventions: rd is the unit ray direction, n the unit outward normal of the
// surface, ior the index of refraction inside relative to outside. Whether the
// ray enters or leaves is read from dot(rd, n).
#ifndef RM_OPTICS_GLSL
#define RM_OPTICS_GLSL

// Mirror direction of rd about the surface with normal n (either side).
vec3 rmReflect(vec3 rd, vec3 n) { return reflect(rd, n); }

// Refracted direction (Snell's law) of rd through the surface; on total
// internal reflection it sets tir and returns the reflected direction.
vec3 rmRefract(vec3 rd, vec3 n, float ior, out bool tir) {
  bool entering = dot(rd, n) < 0.0;
  vec3 facing = entering ? n : -n;
  float eta = entering ? 1.0 / ior : ior;
  vec3 r = refract(rd, facing, eta);
  tir = dot(r, r) == 0.0;  // refract() returns 0 past the critical angle
  return tir ? reflect(rd, facing) : r;
}

// Reflectance at normal incidence between media whose ratio of indices is ior.
float rmFresnelF0(float ior) {
  float r = (ior - 1.0) / (ior + 1.0);
  return r * r;
}

// Schlick's approximation of reflectance for the cosine of the angle on the
// optically thinner side and reflectance f0 at normal incidence.
float rmFresnelSchlick(float cosTheta, float f0) {
  return f0 + (1.0 - f0) * pow(clamp(1.0 - cosTheta, 0.0, 1.0), 5.0);
}

// Share of light reflected where rd meets the surface (1 under total internal
// reflection); the rest is refracted.
float rmFresnel(vec3 rd, vec3 n, float ior) {
  float cosI = abs(dot(rd, n));
  if (dot(rd, n) > 0.0) {
    // Leaving the denser medium: Schlick needs the angle on the thin side.
    float sin2T = ior * ior * (1.0 - cosI * cosI);
    if (sin2T >= 1.0) return 1.0;
    cosI = sqrt(1.0 - sin2T);
  }
  return rmFresnelSchlick(cosI, rmFresnelF0(ior));
}

// Fraction of light left after travelling `distance` through a medium with
// per-channel absorption coefficients.
vec3 rmBeer(vec3 absorption, float distance) { return exp(-absorption * max(distance, 0.0)); }

#endif  // RM_OPTICS_GLSL
