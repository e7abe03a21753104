#!/bin/sh
# Painter's output against the visible map (--visible): time and SVG size per scene.
#
#   bench/visible/run.sh LIMN RUNS FILE...
#
# LIMN is the limn binary (target/release/limn), RUNS the runs per output (the median
# time is reported), FILE the scenes. Prints one Markdown table row per scene:
# faces, then for painter's output and the visible map the median total time (ms, from
# --stats), the SVG's bytes and paths, and the ratios visible / painter's. FLAGS, when
# set, is passed to every render (e.g. FLAGS="--eye 1,2,3 --fov 45").
set -eu
flags=${FLAGS:-}
limn=$1
runs=$2
shift 2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# The median of the numbers on standard input.
median() { sort -n | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }
# key FILE NAME: the number after "NAME": in a --stats file (the first one).
key() { grep -m1 "\"$2\":" "$1" | sed 's/.*: *//; s/,$//'; }
echo "| scene | faces | painter's ms | visible ms | time × | painter's SVG | visible SVG | size ÷ | paths | hidden parts |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for f in "$@"; do
    for mode in painter visible; do
        flag=""
        [ "$mode" = visible ] && flag="--visible"
        : > "$tmp/$mode.times"
        i=0
        while [ "$i" -lt "$runs" ]; do
            "$limn" render "$f" -o "$tmp/$mode.svg" $flag $flags --stats "$tmp/$mode.json" -q
            key "$tmp/$mode.json" total >> "$tmp/$mode.times"
            i=$((i + 1))
        done
        median < "$tmp/$mode.times" > "$tmp/$mode.ms"
    done
    p_ms=$(cat "$tmp/painter.ms")
    v_ms=$(cat "$tmp/visible.ms")
    p_b=$(key "$tmp/painter.json" bytes_out)
    v_b=$(key "$tmp/visible.json" bytes_out)
    awk -v n="$(basename "$f")" -v faces="$(key "$tmp/painter.json" faces_in)" \
        -v pm="$p_ms" -v vm="$v_ms" -v pb="$p_b" -v vb="$v_b" \
        -v pp="$(key "$tmp/painter.json" paths_out)" -v vp="$(key "$tmp/visible.json" paths_out)" \
        -v h="$(key "$tmp/visible.json" fragments_hidden)" 'BEGIN {
        printf "| %s | %d | %.0f | %.0f | %.2f | %.2f MB | %.2f MB | %.1f | %d → %d | %d |\n",
            n, faces, pm, vm, vm / pm, pb / 1e6, vb / 1e6, pb / vb, pp, vp, h
    }'
done
