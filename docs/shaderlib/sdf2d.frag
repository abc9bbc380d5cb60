// rm/sdf2d.glsl: the 2D shapes as distance fields: orange inside, blue
// outside, a band every 0.1 units, white on the zero line.
#include <rm/sdf2d.glsl>

float shape(int i, vec2 p) {
  switch (i) {
    case 0: return sdCircle(p, 0.35);
    case 1: return sdBox(p, vec2(0.35, 0.22));
    case 2: return sdRoundBox(p, vec2(0.35, 0.22), 0.1);
    case 3: return sdSegment(p, vec2(-0.3, -0.2), vec2(0.3, 0.2)) - 0.05;
    case 4: return sdHexagon(p, 0.3);
    case 5: return sdEquilateralTriangle(p, 0.35);
    case 6: return sdTrapezoid(p, 0.35, 0.15, 0.25);
    default: return min(sdCircle(p - vec2(0.15, 0.0), 0.2), sdBox(p + vec2(0.15, 0.0), vec2(0.15)));
  }
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 uv = fragCoord / iResolution.y * 2.0;  // 2 units tall: 4 columns by 2 rows of unit cells
  vec2 cell = floor(uv);
  float d = shape(int(cell.x) + 4 * int(1.0 - cell.y), uv - cell - 0.5);
  vec3 color = d > 0.0 ? vec3(0.65, 0.85, 1.0) : vec3(0.95, 0.6, 0.3);
  color *= 1.0 - exp(-12.0 * abs(d));                 // darker toward the surface
  color *= 0.85 + 0.15 * cos(d * RM_TAU * 10.0);      // iso-distance bands
  color = mix(color, vec3(1.0), 1.0 - smoothstep(0.0, 0.012, abs(d)));
  fragColor = vec4(color, 1.0);
}
