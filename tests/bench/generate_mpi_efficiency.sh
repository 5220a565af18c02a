#!/bin/sh
# MPI efficiency of `viscera generate` at 2 ranks (issue 6 §6): the same batch on 1 and on 2
# ranks; efficiency = t(1 rank) / (2 × t(2 ranks)). Prints both wall times, the rates and the
# efficiency. Usage: tests/bench/generate_mpi_efficiency.sh [BUILD_DIR] [COUNT]
set -eu
build="${1:-build}"
count="${2:-12}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
root=""
[ "$(id -u)" = 0 ] && root="--allow-run-as-root"
run() {
  start=$(date +%s.%N)
  mpirun $root --oversubscribe -n "$1" "$build/bin/viscera" generate --template hysteroscopy \
    --count "$count" --seed 1 -o "$work/n$1" >/dev/null
  end=$(date +%s.%N)
  echo "$end - $start" | bc -l
}
t1=$(run 1)
t2=$(run 2)
cmp -s "$work/n1/index.json" "$work/n2/index.json" || { echo "outputs differ" >&2; exit 1; }
echo "patients $count"
echo "1 rank:  $t1 s, $(echo "60 * $count / $t1" | bc -l | cut -c1-6) patients/min"
echo "2 ranks: $t2 s, $(echo "60 * $count / $t2" | bc -l | cut -c1-6) patients/min"
echo "efficiency $(echo "$t1 / (2 * $t2)" | bc -l | cut -c1-5)"
