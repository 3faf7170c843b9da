#!/usr/bin/env bash
# Builds the libFuzzer targets with clang and fuzzes each for a share of a bounded time
# (default 60 s, split evenly: 20 s each for the BVH parser and baker, the scene reader with
# a few crowd steps, and the command-line parser). Working corpora live in the build tree;
# the committed seeds (tests/fuzz/seeds/<target>) stay as they are.
# Usage: tools/fuzz.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
targets=(bvh scene cli)
share=$(( seconds / ${#targets[@]} ))
[ "$share" -ge 1 ] || share=1
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz --target bvh_fuzz scene_fuzz cli_fuzz

for target in "${targets[@]}"; do
  mkdir -p "build/fuzz/corpus/$target"
  seeds=("tests/fuzz/seeds/$target")
  max_len=4096
  if [ "$target" = bvh ]; then
    max_len=65536
    # The shared captures make good seeds when they are beside the checkout (small ones only).
    if [ -d ../shared/mocap ]; then
      mkdir -p build/fuzz/shared-seeds
      find ../shared/mocap -name '*.bvh' -size -64k -exec cp {} build/fuzz/shared-seeds/ \;
      seeds+=(build/fuzz/shared-seeds)
    fi
  fi
  echo "fuzz.sh: ${target}_fuzz for ${share} s"
  "build/fuzz/${target}_fuzz" -max_total_time="$share" -timeout=10 -rss_limit_mb=2048 -max_len="$max_len" \
    -print_final_stats=1 "build/fuzz/corpus/$target" "${seeds[@]}"
done
