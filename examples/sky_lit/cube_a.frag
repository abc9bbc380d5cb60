// cube_a.frag: Cube A of the sky_lit project. It draws the sky of sky.glsl
// into a cube map once per frame; image.frag reads it for its background and
// its reflections instead of evaluating the clouds once per ray.
#include "sky.glsl"

void mainCubemap(out vec4 color, in vec2 fragCoord, in vec3 rayOrigin, in vec3 rayDirection) {
  color = vec4(sky(rayDirection), 1.0);
}
