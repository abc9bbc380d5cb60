// progressive: a shaderlib scene, path-sampled a little more every frame.
// buffer_a.frag adds one jittered sample per pixel per frame (antialiasing
// and depth of field); this pass shows the average. Leave it still and it
// converges; docs/shadertoy.md charts its error against the number of samples.
#pragma channel0 "buffer_a.frag" filter=nearest

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  // Texel (0, 0) holds the buffer's size, not a sum: its neighbour's is shown.
  ivec2 texel = ivec2(fragCoord);
  if (texel == ivec2(0)) texel.x = 1;
  vec4 sum = texelFetch(iChannel0, texel, 0);
  vec3 color = sum.rgb / max(sum.a, 1.0);
  color = color / (1.0 + color);  // Reinhard: this pass needs no scene, so not rm/lighting's ACES
  fragColor = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
