// rm/fractals.glsl: distance estimators of fractals.
// Provides: sdMenger, sdTetrahedron, sdSierpinski, sdMandelbulb.
// Needs: rm/sdf.glsl (included).
// Iterations are parameters. Float32 resolves a Menger sponge to about 14
// levels and a Sierpinski tetrahedron to about 22; more add cost, not detail.
#ifndef RM_FRACTALS_GLSL
#define RM_FRACTALS_GLSL

#include <rm/sdf.glsl>

// Menger sponge in the cube [-1, 1]^3 after `iterations` levels of holes. bound
float sdMenger(vec3 p, int iterations) {
  float d = sdBox(p, vec3(1.0));
  float scale = 1.0;
  int i = 0;
  if (i < iterations) {
    do {  // tested at the bottom (rm/common.glsl)
      // Each level cuts a cross of square holes through every sub-cube.
      vec3 a = mod(p * scale, 2.0) - 1.0;
      scale *= 3.0;
      vec3 r = abs(1.0 - 3.0 * abs(a));
      float holes = min(max(r.x, r.y), min(max(r.y, r.z), max(r.z, r.x)));
      d = max(d, (holes - 1.0) / scale);
    } while (++i < iterations);
  }
  return d;
}

// Regular tetrahedron with vertices (1,1,1), (-1,-1,1), (1,-1,-1), (-1,1,-1)
// scaled by s. bound
float sdTetrahedron(vec3 p, float s) {
  float faces = max(max(-p.x - p.y - p.z, p.x + p.y - p.z), max(-p.x + p.y + p.z, p.x - p.y + p.z));
  return (faces - s) * 0.57735027;
}

// Sierpinski tetrahedron on sdTetrahedron(p, 1)'s vertices after `iterations`
// folds. bound
float sdSierpinski(vec3 p, int iterations) {
  float scale = 1.0;
  int i = 0;
  if (i < iterations) {
    do {  // tested at the bottom (rm/common.glsl)
      // Reflect onto the side of vertex (1,1,1), then grow about it by 2.
      if (p.x + p.y < 0.0) p.xy = -p.yx;
      if (p.x + p.z < 0.0) p.xz = -p.zx;
      if (p.y + p.z < 0.0) p.yz = -p.zy;
      p = 2.0 * p - 1.0;
      scale *= 2.0;
    } while (++i < iterations);
  }
  return sdTetrahedron(p, 1.0) / scale;
}

// Mandelbulb of the given power (8 is the classic) after `iterations`; it lies
// within radius 1.2. It can exceed the distance to its surface (by up to 0.02
// in tests/stability); multiplied by 0.5 it never did. approximate, factor 2
float sdMandelbulb(vec3 p, float power, int iterations) {
  vec3 z = p;
  float dr = 1.0;  // running derivative |dz/dp|
  float r = length(z);
  int i = 0;
  if (i < iterations && r <= 2.0 && r > 1e-20) {
    do {  // tested at the bottom (rm/common.glsl): rays that escape early leave by the test
      // z -> z^power + p in spherical coordinates; atan(0, 0) is avoided by r > 0.
      float theta = acos(clamp(z.z / r, -1.0, 1.0)) * power;
      float phi = atan(z.y, z.x) * power;
      dr = min(pow(r, power - 1.0) * power * dr + 1.0, 1e30);  // capped: no inf * 0 later
      z = pow(r, power) * vec3(sin(theta) * cos(phi), sin(phi) * sin(theta), cos(theta)) + p;
      r = length(z);
    } while (++i < iterations && r <= 2.0 && r > 1e-20);
  }
  return 0.5 * log(max(r, 1e-30)) * r / dr;
}

#endif  // RM_FRACTALS_GLSL
