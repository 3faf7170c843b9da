#!/usr/bin/env bash
# A signal that arrives while an output's temporary file exists must not leave it behind.
# `throng render` writes its PNG to out.png.tmp-XXXXXX, then its instance dump in place to a
# FIFO that nobody reads, so it waits there, temporary written, until the signal comes.
# Usage: signal_cleanup.sh THRONG DIR SIGNAL (INT, TERM or HUP)
set -euo pipefail
set -m  # job control: a background job keeps SIGINT instead of starting with it ignored
throng=$1 dir=$2 signal=$3
fail() { echo "signal_cleanup: $signal: FAIL: $*" >&2; exit 1; }
rm -rf "$dir"
mkdir -p "$dir"
mkfifo "$dir/dump.json"
"$throng" render --device llvmpipe --characters 2 --width 16 --height 16 --out "$dir/out.png" \
    --dump-instances "$dir/dump.json" 2>"$dir/stderr" &
pid=$!
for _ in $(seq 160); do
    compgen -G "$dir/out.png.tmp-*" >/dev/null && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.05
done
if ! compgen -G "$dir/out.png.tmp-*" >/dev/null; then
    kill -KILL "$pid" 2>/dev/null || true
    cat "$dir/stderr" >&2
    fail "throng never got to writing its output"
fi
kill -"$signal" "$pid"
rc=0
wait "$pid" || rc=$?
expected=$((128 + $(kill -l "$signal")))
[ "$rc" -eq "$expected" ] || fail "exit status $rc, expected $expected (killed by SIG$signal)"
leftovers=$(cd "$dir" && ls | grep -v -x -e dump.json -e stderr || true)
[ -z "$leftovers" ] || fail "left behind: $leftovers"
echo "signal_cleanup: SIG$signal removed the temporary: PASS"
