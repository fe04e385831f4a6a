#!/usr/bin/env bash
# The main job on the shipped example data: a stand's statistics, a virtual forest from it, 100 block
# runs down the stand-in slope without forest, and the mission's answer: the protection index PF50
# of two stands, aggregated and not, with intervals and a ranking. Results land in out/.
set -euo pipefail
cd "$(dirname "$0")/.."
exe=${1:-build/apps/sylvarock}
mkdir -p out
echo "== Stand GR1: inventory statistics (out/GR1-stats.json, out/GR1-figures/)"
"$exe" stats --stems data/stands/GR1_stems.csv --plots data/stands/GR1_plots.csv --plot-dir out/GR1-figures
"$exe" stats --stems data/stands/GR1_stems.csv --plots data/stands/GR1_plots.csv --json > out/GR1-stats.json
echo "== Virtual forests over the forested part of the slope, aggregated (out/GR1-A.csv) and not (out/GR1-NA.csv),"
echo "   their g(r) against the inventory's (out/GR1-A-figures/, out/GR1-NA-figures/)"
"$exe" generate --stems data/stands/GR1_stems.csv --plots data/stands/GR1_plots.csv --structure aggregated \
  --extent 130,0,630,200 --seed 1 --out out/GR1-A.csv --plot-dir out/GR1-A-figures
"$exe" generate --stems data/stands/GR1_stems.csv --plots data/stands/GR1_plots.csv --structure random \
  --extent 130,0,630,200 --seed 1 --out out/GR1-NA.csv --plot-dir out/GR1-NA-figures
echo "== 100 blocks down the stand-in slope without forest (out/no-forest/)"
"$exe" simulate --scene data/scenes/no-forest.ini --runs 100 --seed 1 --out out/no-forest
echo "== PF50 of stands GR1 and PY1, aggregated (A) and random (NA): a small campaign, ~30 s on 2 cores (out/assess/)"
echo "   (15 runs x 2 forests per stand and structure: wide intervals; the paper's design is --runs 100 --realisations 5)"
# --resume: a second run of this script finishes or reuses the campaign instead of refusing out/assess.
"$exe" assess --stand data/stands/GR1 --stand data/stands/PY1 --scene data/scenes/no-forest.ini \
  --runs 15 --realisations 2 --baseline-runs 200 --seed 1 --resume --out out/assess
echo "== Hazard maps on a DTM (out/hazard/): blocks from a release polygon through two stands (MO1 A above GR1 NA, their"
echo "   forests drawn in their polygons) and without them, two check lines; the lumped-mass model (seconds; --model dem"
echo "   for the DEM's trees, minutes); GeoTIFF rasters on the DTM's grid, check_lines_summary.csv, map.png"
rm -rf out/hazard
"$exe" hazard --dtm data/hazard/slope.tif --release data/hazard/release.geojson --stands data/hazard/stands.geojson \
  --check-lines data/hazard/check-lines.geojson --scene data/scenes/no-forest.ini --model lumped --runs-per-cell 20 \
  --compare-bare --seed 1 --out out/hazard
