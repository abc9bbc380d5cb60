// phone_screen.frag: draws examples/textures/phone_screen.png, the default
// iChannel0 of optics.frag (a phone's home screen: a clock and app icons).
// Regenerate it with
//   raymarching render examples/textures/phone_screen.frag -o examples/textures/phone_screen.png --size 256x512
#include <rm/sdf2d.glsl>

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 uv = fragCoord / iResolution.y;  // 0.5 wide, 1 tall
  vec3 color = mix(vec3(0.1, 0.15, 0.35), vec3(0.55, 0.25, 0.5), uv.y);  // wallpaper
  // A clock: two rounded bars as hands and a ring.
  vec2 c = uv - vec2(0.25, 0.8);
  float ring = abs(sdCircle(c, 0.09)) - 0.006;
  float hands = min(sdSegment(c, vec2(0.0), vec2(0.0, 0.065)), sdSegment(c, vec2(0.0), vec2(0.05, -0.02))) - 0.006;
  color = mix(color, vec3(0.95), smoothstep(0.002, 0.0, min(ring, hands)));
  // A 3 x 4 grid of app icons, each its own colour.
  vec2 grid = (uv - vec2(0.045, 0.1)) / vec2(0.14, 0.13);
  vec2 cell = floor(grid);
  if (cell.x >= 0.0 && cell.x < 3.0 && cell.y >= 0.0 && cell.y < 4.0) {
    float icon = sdRoundBox((fract(grid) - 0.5) * vec2(0.14, 0.13), vec2(0.045), 0.015);
    vec3 tint = 0.55 + 0.45 * cos(vec3(0.0, 2.1, 4.2) + 1.3 * (cell.x + 3.0 * cell.y));
    color = mix(color, tint, smoothstep(0.002, 0.0, icon));
  }
  fragColor = vec4(color, 1.0);
}
