#!/bin/sh
# What limn's pictures cost the viewers people open them in, against the same picture
# drawn flat: file sizes and the CPU time (user + system, of the viewer and the
# processes it waits for) that headless Chromium and rsvg-convert take to rasterise the
# SVG, and poppler (pdftoppm) and ghostscript the PDF.
#
#   bench/viewers/run.sh LIMN RUNS SCENE...
#
# LIMN is the limn binary (target/release/limn), RUNS the runs per measurement (the
# median is reported; the picture and its flat counterpart alternate). Each SCENE is
#
#   NAME:FILE[:FLAGS]            the picture as FILE and FLAGS give it, against
#                                the same with --shading flat (instead of any
#                                --shading in FLAGS)
#   NAME:FILE[:FLAGS]:FLATFILE   against FLATFILE instead (e.g. the model with its
#                                textures taken out of its materials)
#
# FLAGS are limn render flags separated by commas ("--shading,phong"). FILE "demo"
# is `limn demo` (no flat counterpart: its ratios are left empty). Chromium's own
# start-up (a blank page's time) is taken off its times; what is left under 0.05 s is
# within the start-up's spread and gets no ratio. Prints a Markdown table.
set -eu
limn=$1
runs=$2
shift 2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
size="800x600"
median() { sort -n | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }
# cpu CMD...: the user + system seconds of CMD (and the children it waited for).
cpu() {
    /usr/bin/time -f "%U %S" -o "$tmp/time" "$@" >/dev/null 2>&1 || true
    awk '{ printf "%.3f\n", $1 + $2 }' "$tmp/time"
}
chromium_shot() {
    printf '<html><body style="margin:0"><img src="%s" width="800" height="600"></body></html>' \
        "$(basename "$1")" > "$1.html"
    cpu chromium --headless --no-sandbox --disable-gpu --no-first-run --hide-scrollbars \
        --disable-background-networking --disable-component-update --disable-sync \
        --force-device-scale-factor=1 --user-data-dir="$tmp/profile" --window-size=800,600 \
        --screenshot="$tmp/shot.png" "file://$1.html"
}
# viewer NAME FILE: one run of viewer NAME on FILE.
viewer() {
    case $1 in
        chromium) chromium_shot "$2" ;;
        rsvg) cpu rsvg-convert -w 800 -h 600 -o "$tmp/r.png" "$2" ;;
        pdftoppm) cpu pdftoppm -r 72 -png -singlefile "$2" "$tmp/p" ;;
        gs) cpu gs -q -dNOPAUSE -dBATCH -dSAFER -sDEVICE=png16m -r72 -sOutputFile="$tmp/g.png" "$2" ;;
    esac
}
# render FILE FLAGS OUT: the picture (FLAGS comma-separated).
render() {
    if [ "$1" = demo ]; then
        "$limn" demo -o "$3" -q
    else
        # shellcheck disable=SC2046
        "$limn" render "$1" --size "$size" -o "$3" -q $(echo "$2" | tr ',' ' ')
    fi
}
printf '<svg xmlns="http://www.w3.org/2000/svg" width="800" height="600"/>' > "$tmp/blank.svg"
: > "$tmp/blank.times"
i=0
while [ "$i" -lt "$runs" ]; do
    chromium_shot "$tmp/blank.svg" >> "$tmp/blank.times"
    i=$((i + 1))
done
blank=$(median < "$tmp/blank.times")
echo "Chromium's start-up (a blank page, taken off its times): $blank s"
echo
echo "| scene | output | size | flat size | viewer | CPU s | flat CPU s | × flat |"
echo "|---|---|---:|---:|---|---:|---:|---:|"
for scene in "$@"; do
    name=$(echo "$scene" | cut -d: -f1)
    file=$(echo "$scene" | cut -d: -f2)
    flags=$(echo "$scene" | cut -d: -f3)
    flatfile=$(echo "$scene" | cut -s -d: -f4)
    for ext in svg pdf; do
        render "$file" "$flags" "$tmp/a.$ext"
        if [ -n "$flatfile" ]; then
            render "$flatfile" "$flags" "$tmp/b.$ext"
        elif [ "$file" != demo ]; then
            render "$file" "$(echo "$flags" | sed 's/--shading,[a-z]*//'),--shading,flat" "$tmp/b.$ext"
        fi
        viewers="chromium rsvg"
        [ "$ext" = pdf ] && viewers="pdftoppm gs"
        for v in $viewers; do
            : > "$tmp/a.times"
            : > "$tmp/b.times"
            i=0
            while [ "$i" -lt "$runs" ]; do
                viewer "$v" "$tmp/a.$ext" >> "$tmp/a.times"
                [ -f "$tmp/b.$ext" ] && viewer "$v" "$tmp/b.$ext" >> "$tmp/b.times"
                i=$((i + 1))
            done
            a=$(median < "$tmp/a.times")
            b=$(median < "$tmp/b.times")
            if [ "$v" = chromium ]; then
                # Below 0.05 s, Chromium's time is within its start-up's spread.
                off() { echo "$1 $blank" | awk '{ d = $1 - $2; if (d < 0.05) print "< 0.05"; else printf "%.3f", d }'; }
                a=$(off "$a")
                [ -n "$b" ] && b=$(off "$b")
            fi
            sa=$(wc -c < "$tmp/a.$ext")
            sb=""
            ratio=""
            if [ -f "$tmp/b.$ext" ]; then
                sb=$(wc -c < "$tmp/b.$ext" | awk '{ printf "%.2f MB", $1 / 1e6 }')
                case "$a $b" in
                    *"<"*) ratio="" ;;
                    *) ratio=$(echo "$a $b" | awk '{ if ($2 > 0) printf "%.1f", $1 / $2 }') ;;
                esac
            fi
            echo "| $name | $ext | $(echo "$sa" | awk '{ printf "%.2f MB", $1 / 1e6 }') | $sb | $v | $a | $b | $ratio |"
        done
        rm -f "$tmp/a.$ext" "$tmp/b.$ext"
    done
done
