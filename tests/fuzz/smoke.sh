#!/usr/bin/env bash
# ctest's fuzz smoke run: builds the fuzz targets into BUILD_DIR, replays
# every seed whole (among them the crashes found before, kept as regression
# inputs), then fuzzes the preprocessor for 15 s, Shadertoy's JSON reader
# for 10 s and a take's reader for 5 s from the seed corpora; any crash
# fails the test.
# (scripts/fuzz runs the long version.)
set -euo pipefail
source_dir="$(cd "$(dirname "$0")" && pwd)"
build_dir="$1"
# Quiet when it builds; the whole log when it does not.
quietly() { local log; log=$("$@" 2>&1) || { printf '%s\n' "$log" >&2; echo "smoke.sh: failed: $*" >&2; return 1; }; }
CXX=clang++ quietly cmake -S "$source_dir" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
quietly cmake --build "$build_dir"
rm -rf "$build_dir/corpus" && cp -r "$source_dir/corpus" "$build_dir/corpus"
rm -rf "$build_dir/corpus-json" && cp -r "$source_dir/corpus-json" "$build_dir/corpus-json"
cp "$source_dir"/../data/shadertoy/*.json "$build_dir/corpus-json"
rm -rf "$build_dir/corpus-take" && cp -r "$source_dir/corpus-take" "$build_dir/corpus-take"
cd "$build_dir"
./source_fuzz corpus/* 2>&1 | tail -1
./check_fuzz corpus/* 2>&1 | tail -1
./source_fuzz -max_total_time=15 -max_len=4096 -timeout=10 corpus 2>&1 | tail -3
./json_fuzz corpus-json/* 2>&1 | tail -1
./json_fuzz -max_total_time=10 -max_len=4096 -timeout=10 -dict="$source_dir/json.dict" corpus-json 2>&1 | tail -3
./take_fuzz corpus-take/* 2>&1 | tail -1
./take_fuzz -max_total_time=5 -max_len=4096 -timeout=10 -dict="$source_dir/take.dict" corpus-take 2>&1 | tail -3
