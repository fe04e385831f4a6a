#!/usr/bin/env python3
"""Writes the hazard example of data/hazard/ (README, docs/hazard.md): a 5 m DTM made from the stand-in
slope's mean shape (data/slopes/standin-smooth.csv) with a shallow gully down its middle, placed in
RGF93 v1 / Lambert-93 (EPSG:2154) near Grenoble; a release polygon; two stand polygons (an aggregated MO1
above a random GR1 with a clearing) for `hazard --stands`; two check lines, above the forest and in it; the trees of an aggregated MO1 forest
(sylvarock generate) moved into the same CRS, for `hazard --trees`. It is a made-up slope in a real CRS, not a survey.

    python3 data/hazard/make_example.py build/apps/sylvarock      (needs gdal_translate, from gdal-bin)
"""
import csv, json, math, os, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
exe = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build/apps/sylvarock")
X0, Y0, CELL, NC, NR = 925000.0, 6460000.0, 5.0, 126, 40     # west edge, south edge, cell, columns, rows
LAMBERT93 = ('PROJCS["RGF93 v1 / Lambert-93",GEOGCS["RGF93 v1",DATUM["Reseau_Geodesique_Francais_1993_v1",'
             'SPHEROID["GRS 1980",6378137,298.257222101]],PRIMEM["Greenwich",0],UNIT["degree",0.0174532925199433]],'
             'PROJECTION["Lambert_Conformal_Conic_2SP"],PARAMETER["latitude_of_origin",46.5],PARAMETER["central_meridian",3],'
             'PARAMETER["standard_parallel_1",49],PARAMETER["standard_parallel_2",44],PARAMETER["false_easting",700000],'
             'PARAMETER["false_northing",6600000],UNIT["metre",1],AUTHORITY["EPSG","2154"]]')

profile = [(float(r["x"]), float(r["z"])) for r in csv.DictReader(l for l in open(os.path.join(ROOT, "data/slopes/standin-smooth.csv")) if not l.startswith("#"))]
def z_profile(x):
    for (xa, za), (xb, zb) in zip(profile, profile[1:]):
        if xa <= x <= xb:
            return za + (zb - za) * (x - xa) / (xb - xa)
    return profile[-1][1] if x > profile[-1][0] else profile[0][1]
def z(x, y):  # a gully 4 m deep and ~60 m wide down the middle of the 200 m wide slope
    return z_profile(x) - 4.0 * math.exp(-((y - 100.0) / 30.0) ** 2)

asc = os.path.join(HERE, "slope.asc")
with open(asc, "w") as f:
    f.write(f"ncols {NC}\nnrows {NR}\nxllcorner {X0}\nyllcorner {Y0}\ncellsize {CELL}\nNODATA_value -9999\n")
    for r in range(NR):
        yc = (NR - r - 0.5) * CELL
        f.write(" ".join(f"{z((c + 0.5) * CELL, yc):.2f}" for c in range(NC)) + "\n")
open(os.path.join(HERE, "slope.prj"), "w").write(LAMBERT93)
subprocess.run(["gdal_translate", "-q", "-of", "GTiff", "-co", "COMPRESS=DEFLATE", "-a_srs", "EPSG:2154", asc,
                os.path.join(HERE, "slope.tif")], check=True)
os.remove(asc); os.remove(os.path.join(HERE, "slope.prj"))

ring = [[X0 + 90, Y0 + 70], [X0 + 110, Y0 + 70], [X0 + 110, Y0 + 130], [X0 + 90, Y0 + 130], [X0 + 90, Y0 + 70]]
json.dump({"type": "FeatureCollection", "name": "release",
           "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::2154"}},
           "features": [{"type": "Feature", "properties": {"name": "cliff foot"}, "geometry": {"type": "Polygon", "coordinates": [ring]}}]},
          open(os.path.join(HERE, "release.geojson"), "w"), indent=1)

def moved(points):
    return [[X0 + x, Y0 + y] for x, y in points]
upper = [(130, 5), (280, 5), (270, 100), (280, 195), (130, 195), (130, 5)]
lower = [(280, 5), (430, 5), (430, 195), (280, 195), (270, 100), (280, 5)]
clearing = [(340, 80), (370, 80), (370, 120), (340, 120), (340, 80)]
json.dump({"type": "FeatureCollection", "name": "stands",
           "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::2154"}},
           "features": [{"type": "Feature", "properties": {"stand": "../stands/MO1", "structure": "A"},
                         "geometry": {"type": "Polygon", "coordinates": [moved(upper)]}},
                        {"type": "Feature", "properties": {"stand": "../stands/GR1", "structure": "NA"},
                         "geometry": {"type": "Polygon", "coordinates": [moved(lower), moved(clearing)]}}]},
          open(os.path.join(HERE, "stands.geojson"), "w"), indent=1)

# Where a barrier could go: across the slope above the forest, and in it.
json.dump({"type": "FeatureCollection", "name": "check-lines",
           "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::2154"}},
           "features": [{"type": "Feature", "properties": {"name": "above the forest (125 m)"},
                         "geometry": {"type": "LineString", "coordinates": moved([(125, 2.5), (125, 197.5)])}},
                        {"type": "Feature", "properties": {"name": "in the forest (250 m)"},
                         "geometry": {"type": "LineString", "coordinates": moved([(250, 2.5), (250, 197.5)])}}]},
          open(os.path.join(HERE, "check-lines.geojson"), "w"), indent=1)

local = os.path.join(HERE, "trees-local.csv")
subprocess.run([exe, "generate", "--stems", os.path.join(ROOT, "data/stands/MO1_stems.csv"), "--plots",
                os.path.join(ROOT, "data/stands/MO1_plots.csv"), "--structure", "aggregated", "--extent", "130,5,430,195",
                "--seed", "3", "--out", local], check=True, stdout=subprocess.DEVNULL)
with open(local) as f, open(os.path.join(HERE, "trees.csv"), "w") as out:
    out.write("# MO1 aggregated forest (sylvarock generate --extent 130,5,430,195 --seed 3) moved into EPSG:2154\n")
    rows = csv.DictReader(l for l in f if not l.startswith("#"))
    w = csv.DictWriter(out, fieldnames=["stem", "x", "y", "dbh_cm", "species", "stool"])
    w.writeheader()
    for r in rows:
        w.writerow({"stem": r["stem"], "x": f"{float(r['x']) + X0:.3f}", "y": f"{float(r['y']) + Y0:.3f}", "dbh_cm": r["dbh_cm"],
                    "species": r["species"], "stool": r["stool"]})
os.remove(local)
print("wrote", ", ".join(sorted(f for f in os.listdir(HERE) if not f.endswith(".py"))))
