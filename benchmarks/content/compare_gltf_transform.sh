#!/bin/sh
# Side by side: our mesh GLB encoder (formats/gltf/mesh_glb.h, Draco) against gltf-transform's
# `draco` (npm @gltf-transform/cli 4.5.1 and the library it runs, pinned in
# benchmarks/content/node/package-lock.json, installed by `npm ci` into BUILD_DIR) on the same
# meshes: content_benchmark's city, 20,000 textured Soho buildings grouped in level-15 cells.
#   ours        mesh_cells encodes each cell's content (encode_mesh_glb) and writes its GLB,
#               timed in its own process (making the content from the footprints is not);
#   peer        node/draco_cells.mjs compresses each cell's uncompressed GLB (written by
#               mesh_cells with the same vertices) in one node process: the `draco` transform
#               the CLI command runs (weld included), then the GLB written; reading the input is
#               timed apart.
# Same settings: edgebreaker, speed 3 for encoding and decoding (ours), normals 10 bits, texture
# coordinates 12 bits, positions at the bits our encoder chose for each cell (1 mm over the
# cell's primitive's widest extent, 16 to 20 bits here), quantization volume: the mesh.
# `gltf-transform draco IN OUT` itself (one process per file) accepts at most 16 position bits:
# it runs on the cells where ours took 16, and its files must equal the library run's.
# Each side runs once untimed (warm caches), then RUNS (3) times alternately; medians of wall and
# CPU (user + sys) seconds; GLB bytes by part (Draco streams, images, JSON chunk, the rest of the
# binary chunk: the EXT_structural_metadata property table), and the per-object metadata alone
# (its JSON, bufferViews and property table). Both sides carry the same metadata: mesh_cells
# writes mesh_glb's property table into the plain GLBs, and gltf-transform keeps it.
# Usage: benchmarks/content/compare_gltf_transform.sh [BUILD_DIR]
set -eu
BUILD=$(cd "${1:-build}" && pwd)
HERE=$(cd "$(dirname "$0")" && pwd)
DATA=$HERE/../../../shared/data  # where mesh_cells reads the footprints
RUNS=${RUNS:-3}
[ -f "$DATA/buildings/london_soho_buildings_wgs84.geojson" ] ||
  { echo "content: $DATA/buildings is absent (no ../shared/data), skipped"; exit 0; }
[ -x "$BUILD/bin/mesh_cells" ] ||
  { echo "content: $BUILD/bin/mesh_cells not found; build the mesh_cells target" >&2; exit 1; }
command -v npm >/dev/null 2>&1 || { echo "content: npm not found, skipped"; exit 0; }

NODE_DIR=$BUILD/benchmarks/content/node
"$HERE/../npm_peers.sh" "$HERE/node" "$NODE_DIR" draco_cells.mjs

TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
python3 - "$BUILD/bin/mesh_cells" "$NODE_DIR" "$TMP" "$RUNS" <<'PY'
import json, os, shutil, statistics, struct, subprocess, sys, time

mesh_cells, node_dir, tmp, runs = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
SPEED, NORMAL, TEXCOORD = 3, 10, 12
cli = os.path.join(node_dir, "node_modules", ".bin", "gltf-transform")

def run(argv):
    return subprocess.run(argv, check=True, capture_output=True, text=True).stdout

def one_round(d):
    shutil.rmtree(d, ignore_errors=True)
    run([mesh_cells, d])
    m = json.load(open(os.path.join(d, "cells.json")))
    os.makedirs(os.path.join(d, "peer"))
    t = json.loads(run(["node", os.path.join(node_dir, "draco_cells.mjs"), os.path.join(d, "plain"),
                        os.path.join(d, "peer"), os.path.join(d, "cells.json"), str(SPEED),
                        str(NORMAL), str(TEXCOORD)]))
    return m, t

samples = []
for i in range(runs + 1):  # the first round warms caches and is not counted
    m, t = one_round(os.path.join(tmp, "run"))
    if i:
        samples.append((m, t))

def med(f): return statistics.median(f(m, t) for m, t in samples)

def parts(path):
    b = open(path, "rb").read()
    n = struct.unpack_from("<I", b, 12)[0]
    j = json.loads(b[20:20 + n])
    views = j.get("bufferViews", [])
    bin0 = 20 + n + 8
    def view(i):
        v = views[i]
        return b[bin0 + v.get("byteOffset", 0):bin0 + v.get("byteOffset", 0) + v["byteLength"]]
    draco = b"".join(view(p["extensions"]["KHR_draco_mesh_compression"]["bufferView"])
                     for mesh in j["meshes"] for p in mesh["primitives"])
    image = sum(views[i["bufferView"]]["byteLength"] for i in j.get("images", []))
    # The per-object metadata: its JSON (the compact dump with and without it) and its property
    # table's bufferViews.
    stripped = json.loads(json.dumps(j))
    ext = stripped.get("extensions", {}).pop("EXT_structural_metadata", None)
    for mesh in stripped["meshes"]:
        for p in mesh["primitives"]:
            p.get("extensions", {}).pop("EXT_mesh_features", None)
    stripped["extensionsUsed"] = [e for e in stripped.get("extensionsUsed", [])
                                  if e not in ("EXT_structural_metadata", "EXT_mesh_features")]
    meta_views = [v for t in (ext or {}).get("propertyTables", [])
                  for c in t["properties"].values() for k, v in c.items()
                  if k in ("values", "stringOffsets")]
    dump = lambda x: len(json.dumps(x, separators=(",", ":")))
    # (the JSON of the table's bufferViews too, each with its comma)
    meta = dump(j) - dump(stripped) + sum(views[i]["byteLength"] + dump(views[i]) + 1
                                          for i in meta_views)
    return {"GLB": len(b), "Draco": len(draco), "images": image, "JSON": n,
            "rest": len(b) - 20 - n - len(draco) - image, "metadata": meta,
            "GLB-metadata": len(b) - meta}, draco

d = os.path.join(tmp, "run")
manifest = json.load(open(os.path.join(d, "cells.json")))
cells = manifest["cells"]
total = {"ours": {}, "peer": {}}
same_size = 0  # Draco streams of equal length (attributes may come in another order)
for c in cells:
    streams = {}
    for side in total:
        p, streams[side] = parts(os.path.join(d, side, c["cell"] + ".glb"))
        for k, v in p.items():
            total[side][k] = total[side].get(k, 0) + v
    same_size += len(streams["ours"]) == len(streams["peer"])

# The CLI on the cells where ours took 16 position bits (its maximum): one process per file.
cli_cells = [c["cell"] for c in cells if c["position_bits"] == 16]
cli_dir = os.path.join(tmp, "cli")
os.makedirs(cli_dir)
cli_wall, cli_same = [], 0
for cell in cli_cells:
    t = time.monotonic()
    run([cli, "draco", os.path.join(d, "plain", cell + ".glb"), os.path.join(cli_dir, cell + ".glb"),
         "--method", "edgebreaker", "--encode-speed", str(SPEED), "--decode-speed", str(SPEED),
         "--quantize-position", "16", "--quantize-normal", str(NORMAL), "--quantize-texcoord",
         str(TEXCOORD), "--quantization-volume", "mesh"])
    cli_wall.append(time.monotonic() - t)
    cli_same += parts(os.path.join(cli_dir, cell + ".glb"))[1] == \
        parts(os.path.join(d, "peer", cell + ".glb"))[1]

# Both outputs of the first cell through the Khronos validator (gltf-transform validate).
def validate(path):
    out = subprocess.run([cli, "validate", path], capture_output=True, text=True)
    return "ok" if out.returncode == 0 else "FAILED:\n" + out.stdout + out.stderr

n, tris = manifest["objects"], manifest["triangles"]
bits = sorted({c["position_bits"] for c in cells})
print(f"{len(cells)} cells, {n} buildings, {tris} triangles; position bits {bits[0]}-{bits[-1]} "
      f"(1 mm over each cell), normals {NORMAL}, texcoords {TEXCOORD}, speed {SPEED}; "
      f"median of {runs} runs")
ow, oc = med(lambda m, t: m["ours_wall_s"]), med(lambda m, t: m["ours_cpu_s"])
pw, pc = med(lambda m, t: t["encode_write_wall_s"]), med(lambda m, t: t["encode_write_cpu_s"])
rw, rc = med(lambda m, t: t["read_wall_s"]), med(lambda m, t: t["read_cpu_s"])
print(f"{'':<34}{'wall s':>9}{'cpu s':>9}{'us/object cpu':>15}")
for label, w, c in (("ours: encode + write", ow, oc), ("gltf-transform: draco + write", pw, pc),
                    ("gltf-transform: read plain GLB", rw, rc)):
    print(f"{label:<34}{w:9.3f}{c:9.3f}{1e6 * c / n:15.1f}")
print(f"{'bytes':<10}" + "".join(f"{k:>12}" for k in total["ours"]))
for side, label in (("ours", "ours"), ("peer", "peer")):
    print(f"{label:<10}" + "".join(f"{v:12d}" for v in total[side].values()))
print(f"{'per object':<10}" + "".join(f"{v / n:12.1f}" for v in total["ours"].values()) + "  (ours)")
print(f"ratios ours/peer: cpu {oc / pc:.2f}x (peer with reading {oc / (pc + rc):.2f}x), "
      f"wall {ow / pw:.2f}x; GLB bytes {total['ours']['GLB'] / total['peer']['GLB']:.3f}x, "
      f"without the metadata {total['ours']['GLB-metadata'] / total['peer']['GLB-metadata']:.3f}x, "
      f"Draco streams {total['ours']['Draco'] / total['peer']['Draco']:.3f}x "
      f"(equal length in {same_size} of {len(cells)} cells)")
if cli_cells:
    print(f"CLI `gltf-transform draco` on the {len(cli_cells)} cells at 16 bits: "
          f"{statistics.median(cli_wall):.2f} s wall per file (a node process each); "
          f"Draco streams equal to the library run's: {cli_same} of {len(cli_cells)}")
first = cells[0]["cell"] + ".glb"
print(f"validator: ours {validate(os.path.join(d, 'ours', first))}, "
      f"peer {validate(os.path.join(d, 'peer', first))}")
PY
