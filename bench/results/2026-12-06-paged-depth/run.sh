#!/bin/bash
# $1: a suffix for the output folders (the repeat)
# Paged against resident depth walls, with the sheets cut and kept, with the planner's
# kept-texture fallback on (normal) and off (nokeep: a missing texture falls back to geometry).
cd /work/stereo-data
export EGL_PLATFORM=surfaceless
for bin in normal nokeep; do for kind in cut keep; do
  echo "$(date -u +%T) start $bin-$kind$1 $(cut -d' ' -f1-3 /proc/loadavg)"
  ./cavewall-$bin bench plant20k/scene.json --quick --resolution 256 --stereo separate --lod 0 \
      --frame-budget-ms 0 --alphas 10,20 --warp-alpha 20 --walls depth \
      $([ $kind = keep ] && echo --keep-sheets) --out paged/$bin-$kind$1 --cache cache20k > paged/$bin-$kind$1.log 2>&1
  echo "$(date -u +%T) end $bin-$kind$1 $(cut -d' ' -f1-3 /proc/loadavg)"
done; done
