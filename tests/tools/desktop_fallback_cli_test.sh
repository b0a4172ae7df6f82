#!/bin/sh
# The desktop fallback end to end, in a real window under Xvfb: `cavewall run --tracker desktop
# --window --nav fly`, the W key held through the X server (xdotool) from the window's focus
# until the run ends (no fixed durations: a loaded machine only shortens the flight), and
# frames.csv must show the viewer flown forward (-Z in the world, the CAVE's front) and not
# sideways. Usage: desktop_fallback_cli_test.sh CAVEWALL MODEL OUT_DIR (run under xvfb-run).
set -eu
cavewall=$1 model=$2 out=$3
rm -rf "$out"
"$cavewall" run --scene "$model" --display desktop --tracker desktop --window --nav fly --frames 150 \
  --out "$out" > "$out.log" 2>&1 &
pid=$!
win=$(xdotool search --sync --name monitor | head -n 1)
# The window may not accept focus until it is mapped (BadMatch): try until it does or the run ends.
until xdotool windowfocus --sync "$win" 2>/dev/null; do kill -0 "$pid" 2>/dev/null || break; done
xdotool keydown w
status=0
wait "$pid" || status=$?
xdotool keyup w
[ "$status" -eq 0 ] || { cat "$out.log"; exit 1; }
# Last row: world_x unchanged, world_z at least 0.2 m ahead (columns found by their names).
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next } { x = $col["world_x"]; z = $col["world_z"] }
  END {
    if (!("world_x" in col) || !("world_z" in col)) { print "frames.csv: no world_x or world_z column"; exit 1 }
    if (x + 0 != 0 || z + 0 > -0.2) { print "expected a flight forward, got world x " x ", z " z; exit 1 }
    print "flew to z = " z }' "$out/frames.csv"
