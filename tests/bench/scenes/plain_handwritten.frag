// plain_handwritten.frag: the scene of plain_library.frag written by hand, the
// way a tutorial would: sphere tracing with a pixel-cone threshold, a
// tetrahedron normal, Blinn-Phong from one directional light plus ambient.
float sdSphere(vec3 p, float r) { return length(p) - r; }
float sdTorus(vec3 p, vec2 t) { return length(vec2(length(p.xz) - t.x, p.y)) - t.y; }
float sdBox(vec3 p, vec3 b) {
  vec3 q = abs(p) - b;
  return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}

float map(vec3 p) {
  float d = min(sdSphere(p - vec3(-1.1, 0.05, 0.0), 0.55), sdTorus(p - vec3(0.1, 0.0, -0.3), vec2(0.45, 0.15)));
  return min(min(d, sdBox(p - vec3(1.2, -0.15, 0.2), vec3(0.35))), p.y + 0.5);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec3 ro = vec3(0.0, 1.0, 4.5);
  vec3 forward = normalize(vec3(0.0, -0.2, 0.0) - ro);
  vec3 right = normalize(cross(forward, vec3(0.0, 1.0, 0.0)));
  vec3 up = cross(right, forward);
  float focal = 1.0 / tan(0.45);
  vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
  vec3 rd = normalize(forward * focal + right * uv.x + up * uv.y);
  float cone = 1.0 / (focal * iResolution.y);

  float t = 0.0;
  bool hit = false;
  for (int i = 0; i < 160; ++i) {
    float d = map(ro + rd * t);
    if (d < max(1e-4, cone * t)) { hit = true; break; }
    t += d;
    if (t > 100.0) break;
  }
  vec3 color = vec3(0.5, 0.6, 0.8);
  if (hit) {
    vec3 p = ro + rd * t;
    float e = max(1e-4, cone * t);
    vec2 k = vec2(1.0, -1.0);
    vec3 n = normalize(k.xyy * map(p + k.xyy * e) + k.yyx * map(p + k.yyx * e) +
                       k.yxy * map(p + k.yxy * e) + k.xxx * map(p + k.xxx * e));
    vec3 l = normalize(vec3(0.5, 0.8, 0.3));
    vec3 albedo = vec3(0.7, 0.5, 0.3);
    float diffuse = max(dot(n, l), 0.0);
    float specular = diffuse > 0.0 ? 0.3 * pow(max(dot(n, normalize(l - rd)), 0.0), 32.0) : 0.0;
    color = albedo * 0.12 * (0.6 + 0.4 * n.y) + albedo * diffuse + specular;
  }
  color = max(color, 0.0);
  color = clamp((color * (2.51 * color + 0.03)) / (color * (2.43 * color + 0.59) + 0.14), 0.0, 1.0);
  fragColor = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
