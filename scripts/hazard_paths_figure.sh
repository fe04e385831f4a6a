#!/bin/bash
# docs/figures/hazard-example-paths.png: the example's block paths in plan from trajectories.gpkg (the
# --trajectories output), read back with GDAL's ogr2ogr as a GIS would, through the stands and without
# them. Usage: scripts/hazard_paths_figure.sh [build/apps/sylvarock]   (needs gdal-bin and gnuplot)
set -euo pipefail
cd "$(dirname "$0")/.."
exe=${1:-build/apps/sylvarock}
out=$(mktemp -d)
"$exe" hazard --dtm data/hazard/slope.tif --release data/hazard/release.geojson --stands data/hazard/stands.geojson \
  --scene data/scenes/no-forest.ini --model lumped --runs-per-cell 2 --compare-bare --trajectories --seed 1 --out "$out/hz" > /dev/null
for pass in forest bare; do
  ogr2ogr -f CSV "$out/$pass.csv" "$out/hz/trajectories.gpkg" "paths_$pass" -lco GEOMETRY=AS_WKT
  # One block of "x_m y_m z_m" per path (metres from the DTM's south-west corner), a blank line between paths.
  python3 - "$out/$pass.csv" > "$out/$pass.dat" <<'PY'
import csv, sys
for row in csv.DictReader(open(sys.argv[1])):
    wkt = row["WKT"]
    if not wkt.startswith("LINESTRING"):
        continue
    for p in wkt[wkt.index("(") + 1:wkt.rindex(")")].split(","):
        x, y, z = map(float, p.split())
        print(f"{x - 925000:.2f} {y - 6460000:.2f} {z:.2f}")
    print()
PY
done
gnuplot <<GP
set terminal pngcairo size 1100,440 noenhanced font 'sans,10'
set output 'docs/figures/hazard-example-paths.png'
set title 'The example: 96 block paths through the stands (red) and the same blocks without them (grey), from trajectories.gpkg'
set size ratio -1
set xrange [0:630]
set yrange [0:200]
set xlabel 'm east of 925000'
set ylabel 'm north of 6460000'
set object 1 rect from 130,5 to 430,195 fc rgb '#e8f5e9' fs solid 1.0 noborder behind
set label 1 'the two stands, 130-430 m' at 280,188 center
plot '$out/bare.dat' using 1:2 with lines lc rgb '#999999' notitle, '$out/forest.dat' using 1:2 with lines lc rgb '#b2182b' notitle
GP
rm -rf "$out"
echo "wrote docs/figures/hazard-example-paths.png"
