#!/bin/sh
# The peer comparison: cavewall's draw path against OpenSceneGraph's stock viewer
# (osgviewer) on the same generated box hall, same view and resolution, interleaved rounds.
#
#   tools/osg-compare.sh [--cavewall EXE] [--out DIR] [--rounds N] [--frames N] [--sizes "T1 T2 ..."]
#                        [--tuned-osg]
#
# Installs nothing (tools/install-deps.sh installs openscenegraph and xvfb). Per size (triangles,
# default "100000 1000000"): `cavewall generate boxes` once (glb + OBJ), `osgconv` once (OBJ ->
# .osgb, as a user would prepare a model for osgviewer): without the OBJ reader's triangle
# stripping (-O noTriStripPolygons; it takes hours on a million triangles) and with the
# optimiser's INDEX_MESH, which gives the same single indexed triangle list (one DrawElementsUInt,
# 24 vertices per box) that stripping ends in. Then --rounds rounds (default 5), each
# running, per size, osgviewer and `cavewall draw-bench` one after the other:
#  - osgviewer: under one Xvfb server, a 1024 x 1024 window (--window 0 0 1024 1024; its default
#    29.15 degree vertical field of view, home position, lighting and threading model),
#    vblank_mode=0 (no wait for vertical blank), OSG_RUN_FRAME_COUNT frames. It is run twice,
#    for 5 frames and for 5 + --frames (default 30) frames; ms per frame is the difference of
#    the two wall-clock times over --frames, so loading, window set-up and exit cancel out
#    (likewise its CPU time, user + system of all its threads).
#  - cavewall draw-bench: the same view (osgviewer's home for the model's bounding box),
#    headless (EGL), --frames timed frames after 5 warm-up frames, median wall and CPU ms with
#    back faces culled and with culling off (from its CSV, columns read by name).
# --tuned-osg gives osgviewer the heap setting cavewall sets for itself (tools/main.cpp: mallopt
# M_TRIM_THRESHOLD 1 GiB, M_MMAP_THRESHOLD 32 MiB), through GLIBC_TUNABLES, so that neither side
# pays for glibc returning llvmpipe's freed buffers to the kernel and faulting them back in.
# Prints, per size, the median over rounds of each figure as Markdown tables (also written to
# DIR/osg-compare.md) and every round's figures to DIR/rounds.csv. Default DIR: osg-compare-out.
set -eu

CAVEWALL=build/cavewall
OUT=osg-compare-out
ROUNDS=5
FRAMES=30
SIZES="100000 1000000"
SHORT=5
OSG_ENV=""
while [ $# -gt 0 ]; do
  case "$1" in
    --cavewall) CAVEWALL=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --rounds) ROUNDS=$2; shift 2 ;;
    --frames) FRAMES=$2; shift 2 ;;
    --sizes) SIZES=$2; shift 2 ;;
    --tuned-osg) OSG_ENV="GLIBC_TUNABLES=glibc.malloc.trim_threshold=1073741824:glibc.malloc.mmap_threshold=33554432"; shift ;;
    -h|--help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;;
    *) echo "osg-compare: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done

for tool in osgviewer osgconv Xvfb; do
  command -v "$tool" >/dev/null 2>&1 ||
    { echo "osg-compare: '$tool' not found (expected it installed by tools/install-deps.sh: openscenegraph, xvfb)" >&2; exit 1; }
done
[ -x "$CAVEWALL" ] || { echo "osg-compare: '$CAVEWALL' is not an executable (expected a built cavewall; --cavewall EXE)" >&2; exit 1; }

mkdir -p "$OUT"
export EGL_PLATFORM="${EGL_PLATFORM:-surfaceless}"

# Models: generated and converted once, reused by later runs.
for t in $SIZES; do
  dir="$OUT/boxes-$t"
  if [ ! -f "$dir/boxes.osgb" ]; then
    "$CAVEWALL" generate boxes --triangles "$t" --out "$dir" >/dev/null
    echo "osg-compare: converting $dir/boxes.obj for osgviewer (osgconv, once)" >&2
    OSG_OPTIMIZER="DEFAULT INDEX_MESH" osgconv -O noTriStripPolygons "$dir/boxes.obj" "$dir/boxes.osgb" >/dev/null 2>&1
  fi
done

# One X server for every osgviewer run; stopped on exit.
displayfile="$OUT/.xvfb-display"
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp 3>"$displayfile" 2>/dev/null &
XVFB_PID=$!
trap 'kill "$XVFB_PID" 2>/dev/null || true' EXIT INT TERM
tries=0
while [ ! -s "$displayfile" ]; do
  tries=$((tries + 1))
  [ "$tries" -le 100 ] || { echo "osg-compare: Xvfb did not start" >&2; exit 1; }
  sleep 0.1  # until Xvfb has written its display number (it does once it accepts clients)
done
XDISPLAY=":$(cat "$displayfile")"

now_ns() { date +%s%N; }

# "wall cpu": wall-clock and CPU (user + system, all threads) milliseconds of one osgviewer run
# of $2 frames of model $1. The subshell's `times` reports its children: osgviewer alone.
osg_run_ms() {
  start=$(now_ns)
  cpu=$( (DISPLAY="$XDISPLAY" vblank_mode=0 OSG_RUN_FRAME_COUNT="$2" OSG_NOTIFY_LEVEL=FATAL \
            env $OSG_ENV osgviewer --window 0 0 1024 1024 "$1" >/dev/null 2>&1; times) |
         awk 'NR == 2 { split($1, u, /[ms]/); split($2, k, /[ms]/); printf "%.3f", (u[1] * 60 + u[2] + k[1] * 60 + k[2]) * 1e3 }')
  end=$(now_ns)
  echo "$start $end $cpu" | awk '{ printf "%.3f %.3f", ($2 - $1) / 1e6, $3 }'
}

# Column $2 of the CSV row whose first column is $3, columns looked up by name.
csv_value() {
  awk -F, -v col="$2" -v key="$3" 'NR == 1 { for (i = 1; i <= NF; i++) idx[$i] = i; next }
                                   $1 == key && (!("lighting" in idx) || $(idx["lighting"]) == "default") { print $(idx[col]) }' "$1"
}

echo "round,triangles,osgviewer_ms,cavewall_culled_ms,cavewall_both_ms,osgviewer_cpu_ms,cavewall_culled_cpu_ms,cavewall_both_cpu_ms" >"$OUT/rounds.csv"
r=1
while [ "$r" -le "$ROUNDS" ]; do
  for t in $SIZES; do
    dir="$OUT/boxes-$t"
    short=$(osg_run_ms "$dir/boxes.osgb" "$SHORT")
    long=$(osg_run_ms "$dir/boxes.osgb" $((SHORT + FRAMES)))
    osg=$(echo "$short $long $FRAMES" | awk '{ printf "%.2f", ($3 - $1) / $5 }')
    osgcpu=$(echo "$short $long $FRAMES" | awk '{ printf "%.2f", ($4 - $2) / $5 }')
    "$CAVEWALL" draw-bench "$dir/boxes.glb" --frames "$FRAMES" --warmup "$SHORT" --resolution 1024 \
      --csv "$dir/draw-bench.csv" >"$dir/draw-bench.txt"
    culled=$(csv_value "$dir/draw-bench.csv" median_ms on)
    both=$(csv_value "$dir/draw-bench.csv" median_ms off)
    culledcpu=$(csv_value "$dir/draw-bench.csv" cpu_median_ms on)
    bothcpu=$(csv_value "$dir/draw-bench.csv" cpu_median_ms off)
    echo "$r,$t,$osg,$culled,$both,$osgcpu,$culledcpu,$bothcpu" >>"$OUT/rounds.csv"
    echo "osg-compare: round $r, $t triangles: osgviewer $osg ms, cavewall $culled ms (culled), $both ms (culling off)" >&2
  done
  r=$((r + 1))
done

# Median over rounds (the lower middle for an even count, like display/timing.h).
median_of() {
  awk -F, -v t="$1" -v col="$2" 'NR == 1 { for (i = 1; i <= NF; i++) idx[$i] = i; next }
                                  $2 == t { print $(idx[col]) }' "$OUT/rounds.csv" |
    sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'
}

table() {  # $1: title word, $2..$4: columns of osgviewer, cavewall culled, cavewall culling off
  echo "| triangles | osgviewer $1 | cavewall $1 (back faces culled) | osg / cavewall | cavewall $1, culling off (same work as osgviewer) | osg / cavewall |"
  echo "| --- | --- | --- | --- | --- | --- |"
  for t in $SIZES; do
    echo "$t $(median_of "$t" "$2") $(median_of "$t" "$3") $(median_of "$t" "$4")" |
      awk '{ printf "| %d | %.1f | %.1f | %.2f | %.1f | %.2f |\n", $1, $2, $3, $2 / $3, $4, $2 / $4 }'
  done
}

{
  table "ms" osgviewer_ms cavewall_culled_ms cavewall_both_ms
  echo
  table "CPU ms" osgviewer_cpu_ms cavewall_culled_cpu_ms cavewall_both_cpu_ms
  echo
  echo "Per frame, medians of $ROUNDS interleaved rounds, 1024 x 1024, $FRAMES frames each; wall clock"
  echo "(first table) and process CPU time of all threads (second; steady when other processes share"
  echo "the cores); $(grep -m1 GL_RENDERER "$OUT/boxes-$(echo $SIZES | awk '{print $1}')/draw-bench.txt")."
  if [ -n "$OSG_ENV" ]; then echo "osgviewer ran with $OSG_ENV (--tuned-osg)."; else echo "osgviewer ran stock."; fi
} | tee "$OUT/osg-compare.md"
