// glslViewer's passes in one file (docs/shadertoy.md): a dot in BUFFER_0,
// its trail in DOUBLE_BUFFER_0 (which reads its own last frame), the scene
// tinted from both, and POSTPROCESSING's vignette over the scene on screen.
#ifdef GL_ES
precision mediump float;
#endif
uniform sampler2D u_buffer0;
uniform sampler2D u_doubleBuffer0;
uniform sampler2D u_scene;
uniform vec2 u_resolution;
uniform float u_time;

void main() {
  vec2 st = gl_FragCoord.xy / u_resolution;
#if defined(BUFFER_0)
  vec2 p = (gl_FragCoord.xy - 0.5 * u_resolution) / u_resolution.y;
  vec2 spot = 0.3 * vec2(cos(u_time * 1.7), sin(u_time * 2.3));
  gl_FragColor = vec4(vec3(smoothstep(0.05, 0.03, length(p - spot))), 1.0);
#elif defined(DOUBLE_BUFFER_0)
  gl_FragColor = vec4(max(texture2D(u_doubleBuffer0, st).rgb * 0.96, texture2D(u_buffer0, st).rgb), 1.0);
#elif defined(POSTPROCESSING)
  float vignette = 1.0 - 0.8 * dot(st - 0.5, st - 0.5);
  gl_FragColor = vec4(texture2D(u_scene, st).rgb * vignette, 1.0);
#else
  float trail = texture2D(u_doubleBuffer0, st).r, now = texture2D(u_buffer0, st).r;
  vec3 color = mix(vec3(0.05, 0.06, 0.1), vec3(0.2, 0.6, 1.0), trail);
  gl_FragColor = vec4(mix(color, vec3(1.0, 0.9, 0.6), now), 1.0);
#endif
}
