#!/bin/sh
# Peak resident memory (VmHWM, through /usr/bin/time -v) of `cavewall render` on every model of
# a folder, one CSV row per model: model,max_rss_kb,seconds,textures line.
# usage: peak_rss.sh CAVEWALL DISPLAY SCENES_DIR OUT_DIR [extra render flags...]
set -eu
cavewall=$1 display=$2 scenes=$3 out=$4
shift 4
mkdir -p "$out"
echo "model,max_rss_kb,seconds,textures"
find "$scenes" -name '*.gltf' -o -name '*.glb' | sort | while read -r model; do
  name=$(basename "$model")
  log="$out/$name.log"
  /usr/bin/time -v "$cavewall" render --display "$display" --scene "$model" --view-all --out "$out/$name" "$@" \
    >"$log" 2>&1 || { echo "$name,FAILED,,"; continue; }
  rss=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$log")
  wall=$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$log")
  line=$(grep '^textures:' "$log" || true)
  echo "$name,$rss,$wall,\"$line\""
done
