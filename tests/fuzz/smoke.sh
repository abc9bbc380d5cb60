#!/usr/bin/env bash
# ctest's fuzz smoke run: builds the fuzz targets into BUILD_DIR, replays
# every seed whole (among them the crashes found before, kept as regression
# inputs), then fuzzes the preprocessor for 15 s from the seed corpus; any
# crash fails the test.
# (scripts/fuzz runs the long version.)
set -euo pipefail
source_dir="$(cd "$(dirname "$0")" && pwd)"
build_dir="$1"
# Quiet when it builds; the whole log when it does not.
quietly() { local log; log=$("$@" 2>&1) || { printf '%s\n' "$log" >&2; echo "smoke.sh: failed: $*" >&2; return 1; }; }
CXX=clang++ quietly cmake -S "$source_dir" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
quietly cmake --build "$build_dir"
rm -rf "$build_dir/corpus" && cp -r "$source_dir/corpus" "$build_dir/corpus"
cd "$build_dir"
./source_fuzz corpus/* 2>&1 | tail -1
./check_fuzz corpus/* 2>&1 | tail -1
./source_fuzz -max_total_time=15 -max_len=4096 -timeout=10 corpus 2>&1 | tail -3
