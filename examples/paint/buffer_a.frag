// Paint: the canvas. Each frame keeps the last one and adds a round brush
// where the left button drags. Keys (browser codes): C clears, 1-3 pick the
// colour. Open examples/paint/image.frag.
#pragma channel0 self filter=nearest
#pragma channel1 keyboard

const int KEY_C = 67, KEY_1 = 49;

bool pressed(int key) { return texelFetch(iChannel1, ivec2(key, 1), 0).x > 0.5; }
bool down(int key) { return texelFetch(iChannel1, ivec2(key, 0), 0).x > 0.5; }

void mainImage(out vec4 color, in vec2 fragCoord) {
  vec4 canvas = texelFetch(iChannel0, ivec2(fragCoord), 0);
  if (iFrame == 0 || pressed(KEY_C)) canvas = vec4(0.95, 0.93, 0.88, 1.0);
  vec3 ink = vec3(0.1, 0.2, 0.6);
  if (down(KEY_1 + 1)) ink = vec3(0.7, 0.1, 0.1);
  if (down(KEY_1 + 2)) ink = vec3(0.1, 0.5, 0.2);
  float radius = 0.012 * iResolution.y + 2.0;
  if (iMouse.z > 0.0 && distance(fragCoord, iMouse.xy) < radius) canvas.rgb = ink;
  color = canvas;
}
