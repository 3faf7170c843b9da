#!/usr/bin/env bash
# Builds the libFuzzer target with clang and fuzzes the BVH parser and baker for a bounded
# time (default 60 s). The working corpus lives in the build tree; the committed seeds stay
# as they are. Usage: tools/fuzz.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz --target bvh_fuzz
mkdir -p build/fuzz/corpus
seeds=(tests/fuzz/seeds)
# The shared captures make good seeds when they are beside the checkout (small ones only).
if [ -d ../shared/mocap ]; then
  mkdir -p build/fuzz/shared-seeds
  find ../shared/mocap -name '*.bvh' -size -64k -exec cp {} build/fuzz/shared-seeds/ \;
  seeds+=(build/fuzz/shared-seeds)
fi
build/fuzz/bvh_fuzz -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
  -print_final_stats=1 build/fuzz/corpus "${seeds[@]}"
