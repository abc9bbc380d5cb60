// Paint: a project of two passes. buffer_a.frag holds the canvas and feeds
// itself every frame; this pass shows it with a soft vignette. Drag with the
// left button to paint; hold 2 or 3 for other colours, press C to clear.
#pragma channel0 "buffer_a.frag" filter=nearest

void mainImage(out vec4 color, in vec2 fragCoord) {
  vec3 canvas = texelFetch(iChannel0, ivec2(fragCoord), 0).rgb;
  vec2 uv = fragCoord / iResolution.xy - 0.5;
  color = vec4(canvas * (1.0 - 0.35 * dot(uv, uv)), 1.0);
}
