#!/usr/bin/env bash
# stability.sh - `make stability`: run fixel-stability, then chart it.
#   FXL_BIN_DIR   where fixel-stability is (default build/bin)
#   FXL_STABILITY_OUT  output folder (default docs/stability)
#   FXL_STABILITY_ARGS extra arguments (e.g. --quick)
# Writes CSV tables and, when gnuplot is installed, PNG charts; without
# gnuplot it says how to get it and keeps the CSVs (exit 0).
set -euo pipefail
cd "$(dirname "$0")/../.."
bin="${FXL_BIN_DIR:-build/bin}/fixel-stability"
out="${FXL_STABILITY_OUT:-docs/stability}"
if [ ! -x "$bin" ]; then
    echo "stability.sh: $bin not found; build first (make)" >&2
    exit 1
fi
mkdir -p "$out"
# shellcheck disable=SC2086
"$bin" --out "$out" ${FXL_STABILITY_ARGS:-}
if command -v gnuplot >/dev/null 2>&1; then
    gnuplot -e "dir='$out'" host_sim/scripts/stability_charts.gp
    echo "stability.sh: charts in $out/*.png"
else
    echo "stability.sh: gnuplot not found (apt-get install gnuplot-nox); CSVs only" >&2
fi
echo "stability.sh: breaking points per method: $out/summary.csv"
