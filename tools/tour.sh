#!/bin/bash
# A hostile-input tour of the cavewall command line: runs commands against bad inputs for VRPN
# tracker specs, `calibrate` pairs files, projector warp and blend files, `display --png`,
# `walls --plan-limit` and `walls --rooms`, and classifies each outcome:
#   handled         an expected refusal: exit 1 with a message naming where and what; or an
#                   expected success: exit 0 with the expected line in the output
#   crash           a signal, a sanitizer report, or exit 3 (an unexpected internal exception)
#   hang            still running after TOUR_TIMEOUT seconds (default 60)
#   accepted-wrong  exit 0 where a refusal was expected
#   unclear         any other exit, or a refusal whose message does not name what it should
# Usage: tools/tour.sh [CAVEWALL]     (default build/cavewall; needs python3 and gnuplot)
# Prints one line per case and the counts; exits 1 unless every case is handled. It takes a few
# minutes (the walls cases plan whole models), so it is not part of ctest.
set -u
cd "$(dirname "$0")/.."
exe=$(realpath "${1:-build/cavewall}")
[ -x "$exe" ] || { echo "tour: no executable at $exe (build the cavewall target first)" >&2; exit 2; }
limit=${TOUR_TIMEOUT:-60}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
declare -A count=([handled]=0 [crash]=0 [hang]=0 [accepted-wrong]=0 [unclear]=0)

# tour NAME EXPECT TEXT CMD...: EXPECT is fail (exit 1, TEXT in stderr) or ok (exit 0, TEXT in
# stdout or stderr).
tour() {
  local name=$1 expect=$2 text=$3
  shift 3
  local out=$work/$name.out err=$work/$name.err rc verdict
  (cd "$work" && timeout -k 5 "$limit" "$@" >"$out" 2>"$err")
  rc=$?
  if [ $rc -eq 124 ] || [ $rc -eq 137 ]; then verdict=hang
  elif [ $rc -gt 128 ] || [ $rc -eq 3 ] || grep -qE 'AddressSanitizer|runtime error:|terminate called' "$err"; then
    verdict=crash
  elif [ "$expect" = fail ] && [ $rc -eq 0 ]; then verdict=accepted-wrong
  elif [ "$expect" = fail ] && [ $rc -eq 1 ] && grep -qF -- "$text" "$err"; then verdict=handled
  elif [ "$expect" = ok ] && [ $rc -eq 0 ] && grep -qF -- "$text" "$out" "$err"; then verdict=handled
  else verdict=unclear
  fi
  count[$verdict]=$((count[$verdict] + 1))
  local said
  if [ "$verdict" = handled ] && [ "$expect" = ok ]; then said=$(grep -hF -- "$text" "$out" "$err" | head -n 1)
  else said=$(grep -v '^walls: planned' "$err" | head -n 1)
  fi
  said=$(printf '%s' "$said" | cut -c1-150)
  printf '%-15s %-28s exit %-3s %s\n' "$verdict" "$name" "$rc" "$said"
}

python3 - "$work" <<'EOF'
import base64, json, math, os, struct, sys, zlib
w = sys.argv[1]
def put(name, data):
    with open(os.path.join(w, name), 'wb' if isinstance(data, bytes) else 'w') as f:
        f.write(data)
def png(width, height, depth, kind, rows, idat=None):
    def chunk(t, b): return struct.pack('>I', len(b)) + t + b + struct.pack('>I', zlib.crc32(t + b) & 0xffffffff)
    raw = idat if idat is not None else zlib.compress(b''.join(b'\0' + r for r in rows), 9)
    return (b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', width, height, depth, kind, 0, 0, 0)) +
            chunk(b'IDAT', raw) + chunk(b'IEND', b''))
def pfm(width, height, nodes, header=None):
    head = header if header is not None else b'PF\n%d %d\n-1.0\n' % (width, height)
    return head + b''.join(struct.pack('<fff', *n) for n in nodes)
def display(name, warp=None, blend=None, extra=None):
    s = {"name": "front", "lowerLeft": [-1.5, 0, -1.5], "lowerRight": [1.5, 0, -1.5], "upperLeft": [-1.5, 3, -1.5],
         "resolution": [64, 64], "output": {"headless": {"file": "front"}}}
    if warp: s["warp"] = warp
    if blend: s["blend"] = blend
    c = {"screens": [s]}
    c.update(extra or {})
    put(name, json.dumps(c))
grid = [(i / 2, 1 - j / 2, 0.0) for j in range(3) for i in range(3)]
put('good.pfm', pfm(3, 3, grid))
put('good.warp', 'cavewall-warp 1\n2 2\n0 0 0 0\n1 0 1 0\n0 1 0 1\n1 1 1 1\n')
put('good.png', png(4, 4, 8, 0, [bytes([255, 200, 100, 0])] * 4))
put('trunc.pfm', pfm(3, 3, grid)[:-7])
put('short-header.pfm', b'PF\n3')
put('nan.warp', 'cavewall-warp 1\n2 2\n0 0 0 0\nnan 0 1 0\n0 1 0 1\n1 1 1 1\n')
put('inf-out.warp', 'cavewall-warp 1\n2 2\n0 0 0 0\n1 0 1e39 0\n0 1 0 1\n1 1 1 1\n')
put('few-nodes.warp', 'cavewall-warp 1\n3 3\n0 0 0 0\n1 0 1 0\n')
put('huge.warp', 'cavewall-warp 1\n100000 100000\n')
put('huge.pfm', b'PF\n4096 4096\n-1.0\n')
put('over.pfm', b'PF\n99999 2\n-1.0\n')
put('negative.pfm', b'PF\n-3 3\n-1.0\n')
put('zero-scale.pfm', pfm(3, 3, grid, b'PF\n3 3\n0\n'))
put('nan-scale.pfm', pfm(3, 3, grid, b'PF\n3 3\nnan\n'))
put('uv-out.pfm', pfm(3, 3, [(5.0, 0.5, 0.0)] * 9))
put('all-invalid.pfm', pfm(3, 3, [(float('nan'), 0.0, 0.0)] * 9))
put('empty.warp', '')
put('binary.warp', bytes(range(256)))
put('rgb.png', png(2, 2, 8, 2, [bytes(6)] * 2))
put('trunc.png', png(8, 8, 8, 0, [bytes(8)] * 8)[:40])
put('not.png', b'GIF89a not a png')
put('huge-header.png', png(16384, 16384, 8, 0, [], zlib.compress(b'\0' * 64)))
put('over.png', png(20000, 2, 8, 0, [bytes(20000)] * 2))
put('zero.png', png(0, 0, 8, 0, []))
put('big.png', png(16384, 16384, 8, 0, [], zlib.compress(b'\0' * (16385 * 16384), 9)))
for name, warp, blend in [('good', 'good.pfm', 'good.png'), ('trunc-pfm', 'trunc.pfm', None),
                          ('short-header-pfm', 'short-header.pfm', None), ('nan-warp', 'nan.warp', None),
                          ('inf-out-warp', 'inf-out.warp', None), ('few-nodes-warp', 'few-nodes.warp', None),
                          ('huge-warp', 'huge.warp', None), ('huge-pfm', 'huge.pfm', None), ('over-pfm', 'over.pfm', None),
                          ('negative-pfm', 'negative.pfm', None), ('zero-scale-pfm', 'zero-scale.pfm', None),
                          ('nan-scale-pfm', 'nan-scale.pfm', None), ('uv-out-pfm', 'uv-out.pfm', None),
                          ('all-invalid-pfm', 'all-invalid.pfm', None), ('empty-warp', 'empty.warp', None),
                          ('binary-warp', 'binary.warp', None), ('folder-warp', '.', None),
                          ('rgb-blend', None, 'rgb.png'), ('trunc-blend', None, 'trunc.png'),
                          ('not-png-blend', None, 'not.png'), ('huge-header-blend', None, 'huge-header.png'),
                          ('over-blend', None, 'over.png'), ('zero-blend', None, 'zero.png'),
                          ('big-blend', None, 'big.png'), ('missing-blend', None, 'missing.png')]:
    display('d-' + name + '.json', warp, blend)
display('d-nan-corner.json', extra={"viewer": {"headPosition": [0, 1.7, 0], "near": 1e-300}})
put('d-not-json.json', '{"screens": [')
put('d-no-screens.json', '{"screens": []}')
put('d-deep.json', '[' * 5000 + ']' * 5000)
put('d-collinear.json', json.dumps({"screens": [{"name": "a", "lowerLeft": [0, 0, 0], "lowerRight": [1, 0, 0],
                                                  "upperLeft": [2, 0, 0], "resolution": [8, 8]}]}))
put('d-far.json', json.dumps({"screens": [{"name": "a", "lowerLeft": [-1e200, 0, 0], "lowerRight": [1e200, 0, 0],
                                            "upperLeft": [-1e200, 1, 0], "resolution": [8, 8]}]}))
put('d-overflow.json', '{"screens": [{"name": "a", "lowerLeft": [1e999, 0, 0], "lowerRight": [1, 0, 0], '
                       '"upperLeft": [0, 1, 0], "resolution": [8, 8]}]}')
# Calibration pairs: cave4's floor and front corners, the tracker turned 90 degrees and moved.
cave = [[-1.5, 0, -1.5], [1.5, 0, -1.5], [-1.5, 3, -1.5], [1.5, 3, -1.5], [-1.5, 0, 1.5]]
tr = lambda p, s=1.0: [s * p[2] + 0.1, s * p[1] - 0.05, -s * p[0] + 1.2]
pairs = lambda pts, f=tr: {"pairs": [{"tracker": f(c), "cave": c} for c in pts]}
put('p-good.json', json.dumps(pairs(cave)))
put('p-two.json', json.dumps(pairs(cave[:2])))
put('p-none.json', '{"pairs": []}')
put('p-same.json', json.dumps(pairs([cave[0]] * 4)))
put('p-collinear.json', json.dumps(pairs([[x, 0, -1.5] for x in (-1.5, 0, 1.5, 0.7)])))
put('p-mirror.json', json.dumps(pairs(cave, lambda p: [-p[0], p[1], p[2]])))
put('p-nan.json', json.dumps(pairs(cave)).replace('[-1.4,', '[NaN,', 1))
put('p-overflow.json', json.dumps(pairs(cave)).replace('[-1.4,', '[1e999,', 1))
put('p-huge.json', json.dumps(pairs(cave, lambda p: [1e300 * v for v in p])))
put('p-tiny.json', json.dumps(pairs(cave, lambda p: [1e-300 * v for v in p])))
put('p-far.json', json.dumps(pairs(cave, lambda p: [v + 1e12 for v in p])))
put('p-short-point.json', '{"pairs": [{"tracker": [1, 2], "cave": [1, 2, 3]}]}')
put('p-string.json', '{"pairs": [{"tracker": ["1", 2, 3], "cave": [1, 2, 3]}]}')
put('p-not-json.json', '{"pairs": [')
put('p-empty.json', '')
put('p-scale.json', json.dumps(pairs(cave, lambda p: tr(p, 10.0))))
d = pairs(cave); d["screens"] = {"front": {"lowerLeft": tr(cave[0]), "lowerRight": tr(cave[0]), "upperLeft": tr(cave[0])}}
put('p-screen-point.json', json.dumps(d))
d = pairs(cave); d["screens"] = {"front": {"lowerLeft": tr(cave[0]), "lowerRight": tr(cave[1]), "upperLeft": tr(cave[1])}}
put('p-screen-collinear.json', json.dumps(d))
d = pairs(cave); d["screens"] = {"nosuch": {"lowerLeft": tr(cave[0]), "lowerRight": tr(cave[1]), "upperLeft": tr(cave[2])}}
put('p-screen-unknown.json', json.dumps(d))
d = pairs(cave); d["screens"] = {"front": {"lowerLeft": tr(cave[0]), "lowerRight": [1e300, 0, 0], "upperLeft": tr(cave[2])}}
put('p-screen-far.json', json.dumps(d))
# Models for `walls`: glTF with one mesh of the given triangles (positions as float32).
def gltf(name, tris):
    flat = [c for t in tris for p in t for c in p]
    data = struct.pack('<%df' % len(flat), *flat)
    fin = [v for v in flat if math.isfinite(v)] or [0.0]
    acc = {"bufferView": 0, "componentType": 5126, "count": len(flat) // 3, "type": "VEC3"}
    if flat:
        acc["min"] = [min(flat[i::3]) if all(math.isfinite(v) for v in flat[i::3]) else 0 for i in range(3)]
        acc["max"] = [max(flat[i::3]) if all(math.isfinite(v) for v in flat[i::3]) else 0 for i in range(3)]
    g = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
         "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], "accessors": [acc],
         "bufferViews": [{"buffer": 0, "byteLength": max(len(data), 4)}],
         "buffers": [{"byteLength": max(len(data), 4),
                      "uri": "data:application/octet-stream;base64," + base64.b64encode(data or bytes(4)).decode()}]}
    if not flat:
        g["meshes"] = []; g["nodes"] = [{}]; del g["accessors"]; del g["bufferViews"]; del g["buffers"]
    put(name, json.dumps(g))
def quad(a, b, c, d): return [(a, b, c), (a, c, d)]
def box(x0, y0, z0, x1, y1, z1):
    p = lambda x, y, z: (x, y, z)
    return (quad(p(x0, y0, z0), p(x1, y0, z0), p(x1, y0, z1), p(x0, y0, z1)) +
            quad(p(x0, y1, z0), p(x0, y1, z1), p(x1, y1, z1), p(x1, y1, z0)) +
            quad(p(x0, y0, z0), p(x0, y1, z0), p(x1, y1, z0), p(x1, y0, z0)) +
            quad(p(x0, y0, z1), p(x1, y0, z1), p(x1, y1, z1), p(x0, y1, z1)) +
            quad(p(x0, y0, z0), p(x0, y0, z1), p(x0, y1, z1), p(x0, y1, z0)) +
            quad(p(x1, y0, z0), p(x1, y1, z0), p(x1, y1, z1), p(x1, y0, z1)))
floor = lambda s: quad((-s, 0, -s), (-s, 0, s), (s, 0, s), (s, 0, -s))
gltf('m-empty.gltf', [])
gltf('m-point.gltf', [((1, 1, 1), (1, 1, 1), (1, 1, 1))] * 4)
gltf('m-floor-only.gltf', floor(10))
gltf('m-closed-box.gltf', box(-5, 0, -5, 5, 3, 5))
gltf('m-slab.gltf', floor(10) + box(-0.1, 0, -10, 0.1, 3, 10))
gltf('m-nan.gltf', floor(10) + [((0, 0, 0), (float('nan'), 1, 0), (0, 1, 0))])
gltf('m-walls-only.gltf', box(-0.1, 0, -10, 0.1, 3, 10) + box(5, 0, -10, 5.2, 3, 10))
gltf('m-huge-floor.gltf', floor(15000) + box(-0.1, 0, -15000, 0.1, 3, 15000))
gltf('m-storeys.gltf', [tuple((x, y + 0.05 * k, z) for (x, y, z) in t) for k in range(60) for t in floor(8)])
gltf('m-needle.gltf', floor(10) + box(0, 0, 0, 1e-7, 3, 1e-7))
EOF
[ $? -eq 0 ] || { echo "tour: python3 could not write the inputs" >&2; exit 2; }

echo "== VRPN tracker specs (track --tracker)"
track() { tour "$1" "$2" "$3" "$exe" track --seconds 0.3 --rate 10 --tracker "$4"; }
track vrpn-no-at fail "DEVICE@HOST" 'vrpn:Tracker0'
track vrpn-empty-device fail "DEVICE@HOST" 'vrpn:@localhost'
track vrpn-empty-host fail "DEVICE@HOST" 'vrpn:Tracker0@'
track vrpn-colon-only fail "host" 'vrpn:Tracker0@:3883'
track vrpn-port-0 fail "port" 'vrpn:Tracker0@localhost:0'
track vrpn-port-70000 fail "port" 'vrpn:Tracker0@localhost:70000'
track vrpn-port-negative fail "port" 'vrpn:Tracker0@localhost:-1'
track vrpn-port-text fail "port" 'vrpn:Tracker0@localhost:http'
track vrpn-port-empty fail "port" 'vrpn:Tracker0@localhost:'
track vrpn-port-huge fail "port" 'vrpn:Tracker0@localhost:99999999999999999999'
track vrpn-ipv6 fail "::1" 'vrpn:Tracker0@[::1]:3883'
track vrpn-bad-host fail "no-such-host.invalid" 'vrpn:Tracker0@no-such-host.invalid'
track vrpn-bad-ip fail "999.1.1.1" 'vrpn:Tracker0@999.1.1.1'
track vrpn-head-negative fail "head" 'vrpn:Tracker0@localhost?head=-2'
track vrpn-head-huge fail "head" 'vrpn:Tracker0@localhost?head=1e12'
track vrpn-head-text fail "head" 'vrpn:Tracker0@localhost?head=x'
track vrpn-head-is-hand fail "head and hand" 'vrpn:Tracker0@localhost?head=1&hand=1'
track vrpn-udp-2 fail "udp" 'vrpn:Tracker0@localhost?udp=2'
track vrpn-stale-nan fail "stale" 'vrpn:Tracker0@localhost?stale=nan'
track vrpn-stale-zero fail "stale" 'vrpn:Tracker0@localhost?stale=0'
track vrpn-retry-inf fail "retry" 'vrpn:Tracker0@localhost?retry=inf'
track vrpn-unknown-param fail "bogus" 'vrpn:Tracker0@localhost?bogus=1'
track vrpn-volume-bad fail "volume" 'vrpn:Tracker0@localhost?volume=1,2'
track vrpn-long-device ok "Connection refused" "vrpn:$(printf 'T%.0s' $(seq 1 5000))@127.0.0.1:1"
track vrpn-refused ok "Connection refused" 'vrpn:Tracker0@127.0.0.1:1'
track vrpn-udp-refused ok "vrpn" 'vrpn:Tracker0@127.0.0.1:1?udp=1'

echo "== calibrate"
cal() { tour "$1" "$2" "$3" "$exe" calibrate --pairs "$4" --display cave4 --out "$work/cal-$1.json" "${@:5}"; }
cal cal-good ok "rms_mm" p-good.json
cal cal-missing fail "p-missing.json" p-missing.json
cal cal-empty fail "p-empty.json" p-empty.json
cal cal-not-json fail "p-not-json.json" p-not-json.json
cal cal-none fail "p-none.json" p-none.json
cal cal-two fail "p-two.json" p-two.json
cal cal-same fail "p-same.json" p-same.json
cal cal-collinear fail "collinear" p-collinear.json
cal cal-mirror fail "mirror" p-mirror.json
cal cal-nan fail "p-nan.json" p-nan.json
cal cal-overflow fail "p-overflow.json" p-overflow.json
cal cal-huge fail "p-huge.json" p-huge.json
cal cal-tiny fail "p-tiny.json" p-tiny.json
cal cal-far fail "p-far.json" p-far.json
cal cal-short-point fail "pairs[0].tracker" p-short-point.json
cal cal-string fail "pairs[0].tracker" p-string.json
cal cal-scale-refused fail "scale" p-scale.json --scale
cal cal-scale-unasked fail "p-scale.json" p-scale.json
cal cal-screen-point fail "front" p-screen-point.json
cal cal-screen-collinear fail "front" p-screen-collinear.json
cal cal-screen-unknown fail "nosuch" p-screen-unknown.json
cal cal-screen-far fail "front" p-screen-far.json
cal cal-noise-zero fail "--noise" p-good.json --noise 0
cal cal-noise-nan fail "--noise" p-good.json --noise nan
tour cal-out-is-pairs fail "--out" "$exe" calibrate --pairs p-good.json --display cave4 --out p-good.json
tour cal-out-folder fail "--out" "$exe" calibrate --pairs p-good.json --display cave4 --out "$work"

echo "== warp and blend files (display CONFIG)"
disp() { tour "$1" "$2" "$3" "$exe" display "$4"; }
disp warp-good ok "warp 3 x 3 nodes" d-good.json
for c in trunc-pfm:trunc.pfm short-header-pfm:short-header.pfm nan-warp:nan.warp inf-out-warp:inf-out.warp \
         few-nodes-warp:few-nodes.warp huge-warp:huge.warp huge-pfm:huge.pfm over-pfm:over.pfm \
         negative-pfm:negative.pfm zero-scale-pfm:zero-scale.pfm nan-scale-pfm:nan-scale.pfm uv-out-pfm:uv-out.pfm \
         empty-warp:empty.warp binary-warp:binary.warp folder-warp:warp rgb-blend:rgb.png \
         trunc-blend:trunc.png not-png-blend:not.png huge-header-blend:huge-header.png over-blend:over.png \
         zero-blend:zero.png missing-blend:missing.png; do
  disp "${c%%:*}" fail "${c#*:}" "d-${c%%:*}.json"
done
disp all-invalid-pfm fail "no grid cell has four valid nodes" d-all-invalid-pfm.json
disp big-blend ok "blend 16384 x 16384 px" d-big-blend.json

echo "== display CONFIG --png"
png() { tour "$1" "$2" "$3" "$exe" display "$4" --png "$work/$1.png" "${@:5}"; }
png png-good ok "wrote" d-good.json
png png-not-json fail "d-not-json.json" d-not-json.json
png png-no-screens fail "screens" d-no-screens.json
png png-deep fail "d-deep.json" d-deep.json
png png-collinear fail "collinear" d-collinear.json
png png-far fail "d-far.json" d-far.json
png png-overflow fail "d-overflow.json" d-overflow.json
png png-near-tiny fail "near" d-nan-corner.json
png png-size-tiny fail "--size" d-good.json --size 1x1
png png-size-huge fail "--size" d-good.json --size 100000x100000
png png-size-text fail "--size" d-good.json --size big
tour png-to-folder fail "--png" "$exe" display d-good.json --png "$work"
tour png-to-config fail "--png" "$exe" display d-good.json --png d-good.json
tour png-missing-config fail "nosuch.json" "$exe" display nosuch.json --png "$work/x.png"

echo "== walls --plan-limit and --rooms"
"$exe" generate house --out "$work/house" --triangles 20000 >/dev/null 2>&1
house=$work/house/house.glb
walls() { tour "$1" "$2" "$3" "$exe" walls "$4" --out "$work/w-$1.json" "${@:5}"; }
walls limit-zero fail "--plan-limit" "$house" --plan-limit 0
walls limit-negative fail "--plan-limit" "$house" --plan-limit -5
walls limit-nan fail "--plan-limit" "$house" --plan-limit nan
walls limit-inf fail "--plan-limit" "$house" --plan-limit inf
walls limit-text fail "--plan-limit" "$house" --plan-limit lots
walls limit-over fail "--plan-limit" "$house" --plan-limit 1e12
walls limit-one ok "over --plan-limit" "$house" --plan-limit 1
walls limit-max ok "wrote" "$house" --plan-limit 1e9
walls rooms-house ok "<- chosen  (" "$house" --rooms
walls rooms-empty fail "m-empty.gltf" m-empty.gltf --rooms
walls rooms-point fail "m-point.gltf" m-point.gltf --rooms
walls rooms-floor-only ok "--rooms: storey 0 is cut by grid" m-floor-only.gltf --rooms
walls rooms-closed-box ok "wrote" m-closed-box.gltf --rooms
walls rooms-slab ok "wrote" m-slab.gltf --rooms
walls rooms-nan fail "vertex 7 is not finite" m-nan.gltf --rooms
walls rooms-walls-only ok "no rooms were found" m-walls-only.gltf --rooms
walls rooms-huge-floor ok "wrote" m-huge-floor.gltf --rooms
walls rooms-storeys ok "wrote" m-storeys.gltf --rooms
walls rooms-needle ok "wrote" m-needle.gltf --rooms
walls rooms-limit-one ok "over --plan-limit" m-slab.gltf --rooms --plan-limit 1

echo "== counts"
total=0
for v in handled crash hang accepted-wrong unclear; do
  printf '%-15s %d\n' "$v" "${count[$v]}"
  total=$((total + count[$v]))
done
printf '%-15s %d\n' total "$total"
[ "${count[handled]}" -eq "$total" ]
