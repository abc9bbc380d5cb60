#!/usr/bin/env bash
# An installed raymarching finds its bundled shaderlib (<rm/...>) and default
# scene under <prefix>/share/raymarching, not in the source tree, its
# glslang worker under <prefix>/libexec/raymarching, and its image module
# under <prefix>/lib/raymarching (the libdir).
set -euo pipefail
build_dir=$1
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build_dir" --prefix "$prefix" >/dev/null
printf '#include <rm/sdf.glsl>\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(sdSphere(vec3(f, 0.0), 1.0)); }\n' > "$prefix/scene.frag"
"$prefix/bin/raymarching" check "$prefix/scene.frag"
test -f "$prefix/share/raymarching/examples/default.frag"
test -x "$prefix/libexec/raymarching/raymarching-glslang"
# A picture written loads the installed image module (the loader's log names it).
LD_DEBUG=files "$prefix/bin/raymarching" render "$prefix/scene.frag" --size 4x4 -o "$prefix/still.png" 2>"$prefix/loads.txt"
test -f "$prefix/still.png"
grep -q "file=$prefix/lib[^ ]*/raymarching/raymarching-images.so" "$prefix/loads.txt"
# The installed copy must be the one found: hide the source tree's by renaming the lib in the prefix.
mv "$prefix/share/raymarching/shaderlib/rm/sdf.glsl" "$prefix/sdf.glsl.away"
if "$prefix/bin/raymarching" check "$prefix/scene.frag" 2>"$prefix/err.txt"; then
  echo "expected a missing include once the installed shaderlib is gone" >&2
  exit 1
fi
grep -q "scene.frag:1:10: error: cannot find include 'rm/sdf.glsl'" "$prefix/err.txt"
echo "install test passed"
