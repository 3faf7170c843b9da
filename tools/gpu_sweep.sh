#!/usr/bin/env bash
# #14's real-GPU sweep in one run, for a lent machine whose time is short (15 minutes in all,
# start-up included): the device, then the visibility path at 2000 to 1,000,000 characters
# with the simulation run serially and overlapped with the GPU's frame, then a million
# characters rendered under the validation layer. A benchmark: it prints figures and asserts
# nothing; each step's output also goes to OUT_DIR, and a step that fails is said and the
# rest still run.
set -u

usage() {
    cat <<'EOF'
usage: tools/gpu_sweep.sh OUT_DIR

Environment:
  THRONG      the throng binary                (default: build/release/throng under the repository)
  CHARACTERS  crowd sizes of the sweep          (default: 2000,10000,100000,1000000)
  FRAMES      timed frames per row              (default: 20)
  WARMUP      untimed frames first              (default: 5)

Writes OUT_DIR/devices.txt, OUT_DIR/visibility_serial.{txt,csv},
OUT_DIR/visibility_overlapped.{txt,csv}, OUT_DIR/auto.{txt,csv} (--body auto, up to 100,000)
and OUT_DIR/million_validation.{txt,png}.
EOF
}
case "${1:-}" in
    -h | --help) usage; exit 0 ;;
    "") usage >&2; exit 2 ;;
esac

root=$(cd "$(dirname "$0")/.." && pwd)
throng=${THRONG:-$root/build/release/throng}
out=$1
characters=${CHARACTERS:-2000,10000,100000,1000000}
frames=${FRAMES:-20}
warmup=${WARMUP:-5}
mkdir -p "$out" || exit 2
[ -x "$throng" ] || { echo "gpu_sweep: no throng binary at $throng (build it, or set THRONG)" >&2; exit 2; }

# Runs "$@" with its output to OUT_DIR/$name.txt and the terminal, saying how it ended.
step() {
    local name=$1 start status
    shift
    echo "== $name: $*"
    start=$SECONDS
    "$@" 2>&1 | tee "$out/$name.txt"
    status=${PIPESTATUS[0]}
    echo "== $name: exit $status after $((SECONDS - start)) s"
}

step devices "$throng" devices
step visibility_serial "$throng" bench --modes visibility -n "$characters" --frames "$frames" --warmup "$warmup" \
    --csv "$out/visibility_serial.csv"
step visibility_overlapped "$throng" bench --modes visibility -n "$characters" --frames "$frames" --warmup "$warmup" \
    --overlap-simulation --csv "$out/visibility_overlapped.csv"
step auto "$throng" bench --modes visibility --body auto -n 2000,10000,100000 --frames "$frames" --warmup "$warmup" \
    --csv "$out/auto.csv"
step million_validation env THRONG_VALIDATION=1 "$throng" render --path visibility --characters 1000000 \
    --out "$out/million_validation.png"
