#!/usr/bin/env bash
# Configures and builds a CMake preset (CMakePresets.json):
#   scripts/build.sh            default: build/, RelWithDebInfo (BUILD_TYPE overrides)
#   scripts/build.sh sanitize   build-sanitize/, with AddressSanitizer and UBSan
#   scripts/build.sh thread     build-thread/, with ThreadSanitizer
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-default}"
cmake --preset "$preset" ${BUILD_TYPE:+-DCMAKE_BUILD_TYPE="$BUILD_TYPE"} >/dev/null
cmake --build --preset "$preset" --parallel
