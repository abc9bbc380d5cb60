// shadertoy.frag: a shader in pure Shadertoy form, no shaderlib: paste it into
// shadertoy.com or run it here as it is. A torus and a sphere on a floor,
// sphere-traced, with soft shadows and ambient occlusion. Drag with the left
// mouse button to move the light.

float sdSphere(vec3 p, float r) { return length(p) - r; }
float sdTorus(vec3 p, vec2 t) { return length(vec2(length(p.xz) - t.x, p.y)) - t.y; }

// Distance to the scene (x) and the id of the nearest object (y).
vec2 scene(vec3 p) {
  float floor_ = p.y + 1.0;
  float bob = 0.15 * sin(iTime * 1.3);
  float sphere = sdSphere(p - vec3(1.3, -0.35 + bob, 0.2), 0.65);
  // The torus spins slowly around y and tilts around x.
  float a = iTime * 0.4;
  vec3 q = p - vec3(-0.7, 0.0, 0.0);
  q.xz = mat2(cos(a), -sin(a), sin(a), cos(a)) * q.xz;
  q.yz = mat2(0.8, -0.6, 0.6, 0.8) * q.yz;
  float torus = sdTorus(q, vec2(0.8, 0.25));
  vec2 hit = vec2(floor_, 0.0);
  if (sphere < hit.x) hit = vec2(sphere, 1.0);
  if (torus < hit.x) hit = vec2(torus, 2.0);
  return hit;
}

float map(vec3 p) { return scene(p).x; }

vec3 normal_at(vec3 p, float t) {
  // Tetrahedron taps; the epsilon grows with distance so far points keep a gradient.
  vec2 e = vec2(1.0, -1.0) * 5e-4 * max(1.0, t);
  return normalize(e.xyy * map(p + e.xyy) + e.yyx * map(p + e.yyx) +
                   e.yxy * map(p + e.yxy) + e.xxx * map(p + e.xxx));
}

// Sphere tracing; the hit threshold follows the pixel footprint (t * px).
float march(vec3 ro, vec3 rd, float px) {
  float t = 0.0;
  for (int i = 0; i < 128; i++) {
    float d = map(ro + rd * t);
    if (d < px * t + 1e-4) return t;
    t += d;
    if (t > 40.0) break;
  }
  return -1.0;
}

// iq's soft shadow: k * h / t measures how close the shadow ray passes.
float soft_shadow(vec3 ro, vec3 rd, float k) {
  float shade = 1.0, t = 0.02;
  for (int i = 0; i < 48 && t < 12.0; i++) {
    float h = map(ro + rd * t);
    shade = min(shade, k * h / t);
    if (shade < 0.001) break;
    t += clamp(h, 0.02, 0.5);
  }
  return clamp(shade, 0.0, 1.0);
}

float ambient_occlusion(vec3 p, vec3 n) {
  float occlusion = 0.0, weight = 1.0;
  for (int i = 1; i <= 5; i++) {
    float h = 0.03 + 0.12 * float(i);
    occlusion += weight * (h - map(p + n * h));
    weight *= 0.7;
  }
  return clamp(1.0 - 2.0 * occlusion, 0.0, 1.0);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
  vec3 ro = vec3(0.0, 0.6, 4.2);
  vec3 forward = normalize(vec3(0.0, -0.15, 0.0) - ro);
  vec3 right = normalize(cross(forward, vec3(0.0, 1.0, 0.0)));
  vec3 up = cross(right, forward);
  vec3 rd = normalize(forward * 1.8 + right * uv.x + up * uv.y);

  // The light follows the mouse: x turns it around the scene, y raises it.
  vec2 m = iMouse.z != 0.0 || iMouse.x > 0.0 ? iMouse.xy / iResolution.xy : vec2(0.3, 0.7);
  float az = 6.2831 * m.x, el = mix(0.15, 1.4, m.y);
  vec3 light = normalize(vec3(cos(az) * cos(el), sin(el), sin(az) * cos(el)));

  vec3 sky = mix(vec3(0.55, 0.65, 0.8), vec3(0.2, 0.3, 0.5), clamp(rd.y * 1.5, 0.0, 1.0));
  vec3 color = sky;
  float t = march(ro, rd, 1.5 / iResolution.y);
  if (t > 0.0) {
    vec3 p = ro + rd * t;
    vec3 n = normal_at(p, t);
    float id = scene(p).y;  // the material is looked up once, at the hit
    vec3 albedo = id == 0.0 ? mix(vec3(0.35), vec3(0.6), mod(floor(p.x) + floor(p.z), 2.0))
                : id == 1.0 ? vec3(0.85, 0.35, 0.2)
                            : vec3(0.25, 0.55, 0.85);
    float diffuse = max(dot(n, light), 0.0);
    float shadow = diffuse > 0.0 ? soft_shadow(p + n * 0.002 * max(1.0, t), light, 10.0) : 0.0;
    float specular = pow(max(dot(n, normalize(light - rd)), 0.0), 48.0) * shadow;
    float ao = ambient_occlusion(p, n);
    color = albedo * (0.18 * ao * (0.6 + 0.4 * n.y) + 1.1 * diffuse * shadow) + 0.4 * specular;
    color = mix(color, sky, 1.0 - exp(-0.004 * t * t));  // distance fog
  }
  fragColor = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
