#!/usr/bin/env bash
# The main job on the shipped example data: a stand's statistics, a virtual forest from it, and
# 100 block runs down the stand-in slope without forest. Results land in out/.
set -euo pipefail
cd "$(dirname "$0")/.."
exe=${1:-build/apps/sylvarock}
mkdir -p out
echo "== Stand GR1: inventory statistics (out/GR1-stats.json, out/GR1-figures/)"
"$exe" stats --stems data/stands/GR1_stems.csv --plots data/stands/GR1_plots.csv --plot-dir out/GR1-figures
"$exe" stats --stems data/stands/GR1_stems.csv --plots data/stands/GR1_plots.csv --json > out/GR1-stats.json
echo "== A virtual aggregated forest over the forested part of the slope (out/GR1-A.csv)"
"$exe" generate --stems data/stands/GR1_stems.csv --plots data/stands/GR1_plots.csv --structure aggregated \
  --extent 130,0,630,200 --seed 1 --out out/GR1-A.csv
echo "== 100 blocks down the stand-in slope without forest (out/no-forest/)"
"$exe" simulate --scene data/scenes/no-forest.ini --runs 100 --seed 1 --out out/no-forest
