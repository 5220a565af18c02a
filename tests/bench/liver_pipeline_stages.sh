#!/bin/sh
# Stage table of the label map → simulation-ready body pipeline on CGAL's real liver (issue 20
# §2): `viscera segment` of liver.inr.gz (Debian libcgal-demo) at the organ's own label, then
# `viscera mesh tets --json`, whose "seconds" give every stage (surface steps, Mesh_3, embedding,
# quality; the surface runs beside Mesh_3). Prints the load, the tet count, the volume against
# the voxel volume and one line per stage.
# Usage: tests/bench/liver_pipeline_stages.sh [BUILD_DIR] [extra `mesh tets` options…]
set -eu
build="${1:-build}"
[ $# -gt 0 ] && shift
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz -C "$work" data/images/liver.inr.gz
"$build/bin/viscera" segment "$work/data/images/liver.inr.gz" -o "$work/liver.vti" \
  --threshold 255:255 --largest --json >"$work/segment.json"
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
start=$(date +%s.%N)
"$build/bin/viscera" mesh tets "$work/liver.vti" -o "$work/liver.vtu" --json "$@" >"$work/mesh.json"
end=$(date +%s.%N)
echo "load after:  $(cut -d' ' -f1-3 /proc/loadavg)"
echo "options: ${*:-(defaults)}"
echo "wall (process, incl. reading and writing): $(echo "$end - $start" | bc -l | cut -c1-6) s"
python3 - "$work/segment.json" "$work/mesh.json" <<'PY'
import json, sys
seg = json.load(open(sys.argv[1])); mesh = json.load(open(sys.argv[2]))
voxels = seg["labels"][0]["voxels"]
spacing = 0.000617188 * 0.000617188 * 0.00133333
q = mesh["quality"]
print(f"tets {q['tets']}, nodes {q['nodes']}, inverted {q['inverted']}, "
      f"min dihedral {q['min_dihedral_degrees']:.2f} deg, surface triangles {mesh['surface_triangles']}")
print(f"volume {q['total_volume_m3']*1e6:.2f} cm3 vs voxels {voxels*spacing*1e6:.2f} cm3: "
      f"{100*(q['total_volume_m3']/(voxels*spacing)-1):+.2f} %")
print(f"criteria {json.dumps(mesh['criteria'])}")
print("| stage | s |\n| --- | --- |")
for k, v in sorted(mesh["seconds"].items()):
    print(f"| {k} | {v:.3f} |")
PY
