#!/usr/bin/env python3
"""A hazard map at the size of a real study (issue 15): a 1 km x 1 km DTM at 2 m (250 000 cells), a release
area of 1 000 cells at the top, 80-900 m down the slope and 800 m across under an aggregated MO1 forest drawn
from a stand polygon (~126 000 stems), 10 blocks per release cell (10 000 blocks). Prints the wall time and the peak memory
of each `sylvarock hazard` run (GNU time), the model's per-block cost, and for the DEM the time 10 000 blocks
would take at the measured rate, and at the cost of one more block (from the progress lines) plus the start and
end a map pays once.

    python3 bench/hazard_1km2.py build/apps/sylvarock [dem_blocks=50] [section.key=value ...]   (needs gdal-bin, /usr/bin/time)

Scene keys go to both runs as --set (e.g. stem.upper_spacing_factor=2).

The DTM is made up (a 35-to-5 degree concave slope with gullies across it), in Lambert-93, written to /tmp."""
import json, math, os, re, subprocess, sys, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
exe = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build/apps/sylvarock")
args = sys.argv[2:]
dem_blocks = int(args.pop(0)) if args and "=" not in args[0] else 50
sets = [a for key in args for a in ("--set", key)]
tmp = tempfile.mkdtemp(prefix="sylvarock-1km2-")
X0, Y0, CELL, N = 900000.0, 6400000.0, 2.0, 500

def height(x, y):  # x downhill from the top edge, y across; a gully every 200 m, 3 m deep
    slope = sum(math.tan(math.radians(5 + 30 * math.exp(-s / 300.0))) for s in range(int(x))) + \
        math.tan(math.radians(5 + 30 * math.exp(-x / 300.0))) * (x - int(x))
    return 800 - slope - 3.0 * math.cos(2 * math.pi * y / 200.0) ** 8

asc = os.path.join(tmp, "dtm.asc")
# Heights along x once (the cumulative sum is the costly part), then the gullies across.
drop = [height((c + 0.5) * CELL, 100.0) + 3.0 for c in range(N)]
gully = [3.0 * math.cos(2 * math.pi * ((N - r - 0.5) * CELL) / 200.0) ** 8 for r in range(N)]
with open(asc, "w") as f:
    f.write(f"ncols {N}\nnrows {N}\nxllcorner {X0}\nyllcorner {Y0}\ncellsize {CELL}\nNODATA_value -9999\n")
    for r in range(N):
        f.write(" ".join(f"{drop[c] - gully[r]:.2f}" for c in range(N)) + "\n")
dtm = os.path.join(tmp, "dtm.tif")
subprocess.run(["gdal_translate", "-q", "-a_srs", "EPSG:2154", asc, dtm], check=True)
os.remove(asc)

def polygon(name, x0, y0, x1, y1, props):
    ring = [[X0 + x0, Y0 + y0], [X0 + x1, Y0 + y0], [X0 + x1, Y0 + y1], [X0 + x0, Y0 + y1], [X0 + x0, Y0 + y0]]
    path = os.path.join(tmp, name)
    json.dump({"type": "FeatureCollection", "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::2154"}},
               "features": [{"type": "Feature", "properties": props, "geometry": {"type": "Polygon", "coordinates": [ring]}}]},
              open(path, "w"))
    return path

release = polygon("release.geojson", 20, 450, 60, 550, {})                       # 20 x 50 cells of 2 m
stands = polygon("stands.geojson", 80, 100, 900, 900, {"stand": os.path.join(ROOT, "data/stands/MO1"), "structure": "A"})

def hazard(label, runs_per_cell, model, release):
    out = os.path.join(tmp, label)
    cmd = ["/usr/bin/time", "-v", exe, "hazard", "--dtm", dtm, "--release", release, "--stands", stands,
           "--scene", os.path.join(ROOT, "data/scenes/no-forest.ini"), "--model", model, "--runs-per-cell", str(runs_per_cell),
           "--seed", "1", "--threads", "2", "--out", out] + sets
    t0 = time.time()
    r = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.time() - t0
    if r.returncode != 0:
        sys.exit(f"{label}: exit {r.returncode}: {r.stderr[-500:]}")
    peak = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", r.stderr).group(1)) / 1024
    s = json.load(open(os.path.join(out, "summary.json")))
    blocks = s["passes"]["forest"]["blocks"]
    print(f"{label:8s} {blocks:6d} blocks, {s['trees']} trees: wall {wall:7.1f} s, peak memory {peak:6.0f} MB, "
          f"{wall / blocks * 1e3:7.1f} ms per block; path p50 {s['passes']['forest']['path_length_m']['p50']:.0f} m", flush=True)
    # The progress lines' times between the first printed (each tenth of the runs, after the first 5 s) and
    # the last give the cost of one more block, without the start (DTM, forest, soil bed) and the end
    # (rasters, figures) that a larger map pays once. The times are whole seconds: the resolution is printed.
    ticks = [(int(n), int(t)) for n, t in re.findall(r"runs (\d+)/\d+ \(\d+ %\), (\d+) s", r.stderr)]
    if len(ticks) >= 2 and ticks[-1][0] > ticks[0][0]:
        (n0, t0), (n1, t1) = ticks[0], ticks[-1]
        marginal = (t1 - t0) / (n1 - n0)
        print(f"{'':8s} one more block {marginal * 1e3:.1f} ms (+-{1e3 / (n1 - n0):.1f} ms, runs {n0} to {n1}); "
              f"start and end {wall - marginal * blocks:.1f} s", flush=True)
        return wall, blocks, marginal
    return wall, blocks, None

print(f"1 km2 DTM of {N} x {N} cells of {CELL:g} m in {tmp}")
hazard("lumped", 10, "lumped", release)
# The DEM: one block from each of `dem_blocks` cells in the middle of the release area (5 cells down the
# slope), its rate scaled to 10 000 blocks.
middle = polygon("release-dem.geojson", 20, 500 - dem_blocks / 5, 30, 500 + dem_blocks / 5, {})
wall, blocks, marginal = hazard("dem", 1, "dem", middle)
print(f"dem: 10 000 blocks would take {wall / blocks * 10000 / 60:.0f} min at this rate on 2 threads", end="")
if marginal is not None:
    print(f", {(wall - marginal * blocks + marginal * 10000) / 60:.0f} min at one more block's cost plus the start and end", end="")
print()
