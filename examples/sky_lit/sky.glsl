// sky.glsl: the sun and the sky, shared by the pass that draws the sky into
// a cube map (cube_a.frag) and the scene lit by it (image.frag), so that the
// sun in the sky and the light on the objects agree. The sun circles slowly.
vec3 sunDirection() {
  float a = 0.15 * iTime + 0.8;
  return normalize(vec3(cos(a), 0.55, sin(a)));
}

float skyHash(vec3 p) { return fract(sin(dot(p, vec3(127.1, 311.7, 74.7))) * 43758.5453); }

// Value noise on a lattice, smooth between corners.
float skyNoise(vec3 p) {
  vec3 i = floor(p), f = fract(p);
  f = f * f * (3.0 - 2.0 * f);
  return mix(mix(mix(skyHash(i), skyHash(i + vec3(1, 0, 0)), f.x),
                 mix(skyHash(i + vec3(0, 1, 0)), skyHash(i + vec3(1, 1, 0)), f.x), f.y),
             mix(mix(skyHash(i + vec3(0, 0, 1)), skyHash(i + vec3(1, 0, 1)), f.x),
                 mix(skyHash(i + vec3(0, 1, 1)), skyHash(i + vec3(1, 1, 1)), f.x), f.y), f.z);
}

// Linear radiance seen along rd: a blue gradient with a sun and soft clouds
// above the horizon, warm ground light below it.
vec3 sky(vec3 rd) {
  vec3 sun = sunDirection();
  float up = max(rd.y, 0.0);
  vec3 color = mix(vec3(0.75, 0.82, 0.92), vec3(0.18, 0.36, 0.78), sqrt(up));
  float clouds = 0.0;
  for (int o = 0; o < 4; ++o) clouds += skyNoise(rd * 4.0 * exp2(float(o))) / exp2(float(o) + 1.0);
  color = mix(color, vec3(0.95), smoothstep(0.45, 0.8, clouds) * smoothstep(0.0, 0.25, up));
  color += vec3(8.0, 7.0, 5.5) * pow(max(dot(rd, sun), 0.0), 400.0);
  color += vec3(0.4, 0.3, 0.2) * pow(max(dot(rd, sun), 0.0), 8.0);
  return rd.y < 0.0 ? mix(vec3(0.38, 0.33, 0.28), color, exp(12.0 * rd.y)) : color;
}
