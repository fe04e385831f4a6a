#!/usr/bin/env python3
"""Two runs of scripts/stem_matrix.py compared impact by impact at one node spacing: how far a change
(a build, a --set) moves the tree's energy and the block's exit energy, relative to the impact energy,
and whether the stem breaks and the root plate lets go alike. What issue 12 holds a shortcut to
(the single-tree energies within 2 %).

    python3 scripts/stem_matrix_compare.py REFERENCE.csv CHANGED.csv [--spacing 0.5] [--within 0.02]
"""
import argparse, csv, statistics, sys


def rows(path):
    with open(path, newline="") as f:
        return {(r["dbh_cm"], r["speed_m_s"], r["height_m"], r["eccentricity"]): r for r in csv.DictReader(f)}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("reference")
    ap.add_argument("changed")
    ap.add_argument("--spacing", default="0.5", help="node spacing column to compare (as written in the CSVs)")
    ap.add_argument("--within", type=float, default=0.02, help="gap counted as small, fraction of the impact energy")
    a = ap.parse_args()
    ref, new = rows(a.reference), rows(a.changed)
    h = f"{float(a.spacing):g}"
    tree, block, same, worst = [], [], 0, []
    for key in sorted(set(ref) & set(new), key=lambda k: tuple(float(x) for x in k)):
        r, n = ref[key], new[key]
        if r.get(f"tree_j@{h}", "") in ("", None) or n.get(f"tree_j@{h}", "") in ("", None):
            print(f"  {key}: missing in one of the two", file=sys.stderr)
            continue
        before = float(r["before_j"])
        dt = abs(float(r[f"tree_j@{h}"]) - float(n[f"tree_j@{h}"])) / before
        db = abs(float(r[f"after_j@{h}"]) - float(n[f"after_j@{h}"])) / before
        tree.append(dt)
        block.append(db)
        alike = r[f"broken@{h}"] == n[f"broken@{h}"] and r[f"root_failed@{h}"] == n[f"root_failed@{h}"]
        same += alike
        worst.append((max(dt, db), key, dt, db, alike))
    if not tree:
        sys.exit("no impact in both files")
    count = len(tree)
    print(f"{count} impacts at {h} m, gaps relative to the impact energy (median / worst):")
    print(f"  tree's energy  {100 * statistics.median(tree):.1f} / {100 * max(tree):.1f} %, "
          f"within {100 * a.within:g} %: {sum(g <= a.within for g in tree)} / {count}")
    print(f"  block's exit   {100 * statistics.median(block):.1f} / {100 * max(block):.1f} %, "
          f"within {100 * a.within:g} %: {sum(g <= a.within for g in block)} / {count}")
    print(f"  same break / root outcome: {same} / {count}")
    for g, key, dt, db, alike in sorted(worst, reverse=True)[:5]:
        print(f"    DBH {key[0]} cm, {key[1]} m/s, {key[2]} m, eccentricity {key[3]}: tree {100 * dt:.1f} %, "
              f"block {100 * db:.1f} %{'' if alike else ', outcome differs'}")


if __name__ == "__main__":
    main()
