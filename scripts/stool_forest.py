#!/usr/bin/env python3
"""A forest of identical two-stem stools at random places and orientations, to time or test how the
DEM handles stems standing within reach of each other (docs/stand.md, "Stools").

    python3 scripts/stool_forest.py --apart 0.15 [--stools 1000] [--dbh-cm 20] [--seed 1] --out stools.csv
    build/apps/sylvarock simulate --scene data/scenes/no-forest.ini --forest stools.csv --runs 10 --seed 9 \\
        --threads 2 --no-figures --out DIR

The stools' centres are uniform over the forest band of data/scenes/no-forest.ini (x 135-625 m,
y 5-195 m); the two stems stand `--apart` metres between centres, along a random direction.
"""
import argparse, math, random


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--apart", type=float, required=True, help="distance between a stool's two stems, m")
    ap.add_argument("--stools", type=int, default=1000)
    ap.add_argument("--dbh-cm", type=float, default=20)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    if not (a.apart > 0 and a.stools > 0 and a.dbh_cm > 0):
        ap.error("--apart, --stools and --dbh-cm must be positive")
    rng = random.Random(a.seed)
    with open(a.out, "w") as f:
        f.write("stem,x,y,dbh_cm,species,stool\n")
        stem = 0
        for stool in range(1, a.stools + 1):
            cx, cy, turn = rng.uniform(135, 625), rng.uniform(5, 195), rng.uniform(0, math.pi)
            for side in (-0.5, 0.5):
                stem += 1
                x, y = cx + side * a.apart * math.cos(turn), cy + side * a.apart * math.sin(turn)
                f.write(f"{stem},{x:.3f},{y:.3f},{a.dbh_cm:g},beech,{stool}\n")


if __name__ == "__main__":
    main()
