#!/bin/bash
# ctest `cluster.sweep_on_slurm`: a one-node Slurm cluster (tools/slurm-local), an 8-point sweep submitted as
# a job array and merged, the same grid run locally with --jobs 2: the merged results must be equal but
# for timings; then the cluster stops and leaves no process behind. Skipped (77) when not root.
# usage: sweep_on_slurm.sh CLOTHBENCH SOURCE_DIR WORK_DIR
set -uo pipefail
bin=$1 src=$2 work=$3
[ "$(id -u)" = 0 ] || { echo "SKIP: the local Slurm cluster needs root (slurmd runs jobs as their user)"; exit 77; }
rm -rf "$work" && mkdir -p "$work"
cluster=$work/cluster
# ports of its own per build folder: two checkouts testing at once get two clusters
export SLURM_LOCAL_PORT=$((20000 + $(printf %s "$work" | cksum | cut -d' ' -f1) % 20000 * 2))
grid=(--collider is-cpu,brute --set garment.vertices=100,150 --set solver.limit=velocity,directional
      --set stop.max_iterations=20)
stop() { "$src/tools/slurm-local" stop "$cluster"; }
fail() { echo "FAIL: $*"; stop; exit 1; }

eval "$("$src/tools/slurm-local" start "$cluster")" || fail "the cluster did not start"
"$bin" sweep "$src/scenes/dressing/skirt.toml" "${grid[@]}" --slurm --out "$work/slurm" || fail "sweep --slurm"
"$bin" sweep "$src/scenes/dressing/skirt.toml" "${grid[@]}" --jobs 2 --out "$work/local" || fail "sweep --jobs 2"
python3 "$src/tests/cluster/same_except_timings.py" "$work/slurm/merged.json" "$work/local/merged.json" ||
  fail "the Slurm and the local sweep differ"
stop || { echo "FAIL: the cluster did not stop"; exit 1; }
left=$(pgrep -af -- "$cluster" || true)
[ -z "$left" ] || { echo "FAIL: processes left behind: $left"; exit 1; }
echo "OK: 8 points on Slurm equal the local run but for timings; the cluster stopped cleanly"
