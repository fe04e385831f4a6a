#!/usr/bin/env python3
"""The single-tree matrix of issue 11: every impact of DBH x speed x height x eccentricity at several
node spacings, through the CLI as a user runs it; writes a CSV and an SVG figure.

    python3 scripts/stem_matrix.py [--exe build/apps/sylvarock] [--spacings 0.5,0.25,0.125]
        [--threads 2] [--set key=value ...] [--volume-at-height 0.5:0.1] [--out docs/figures/stem-matrix]

The tree's energy is that of the impact (energy.json impact_dissipated_j: bending plasticity,
bending damping, root plasticity, rupture from first contact to the block leaving), so broken pieces
are not followed to rest (forest.piece_max_time_s = 0): what they do later is not the impact's.
"""
import concurrent.futures, csv, itertools, json, os, statistics, subprocess, sys, tempfile, time

from single_tree import ROOT, arguments, simulate_command
TREE_TERMS = ("bending_plasticity", "bending_damping", "axial_damping", "root_plasticity", "rupture")
CROWN_SHARE = 0.40642  # L_C / H_T, the paper's Eq. 12


def run_one(exe, extra, dbh, speed, height, ecc, h, volume):
    with tempfile.TemporaryDirectory() as out:
        cmd = simulate_command(exe, out, dbh, speed, height, ecc, h, ["forest.piece_max_time_s=0"] + list(extra))
        if volume:
            cmd += ["--set", f"block.volume_m3={volume}"]
        start = time.process_time()
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode:
            return {"error": r.stderr.strip().splitlines()[-1] if r.stderr.strip() else f"exit {r.returncode}"}
        j = json.load(open(os.path.join(out, "energy.json")))
    if not j.get("impacts"):
        return {"impacts": 0}
    tree = sum(j["impact_dissipated_j"].get(k, 0.0) for k in TREE_TERMS)  # axial_damping: absent before it existed
    # Broken below its crown (Eq. 12: the crown is the top 0.40642 H_T), or only a whipped top
    # snapping in the crown.
    below_crown = j["break_height_m"] is not None and j["break_height_m"] < (1 - CROWN_SHARE) * j["stem_height_m"]
    return {"impacts": j["impacts"], "tree_j": tree, "before_j": j["kinetic_before_j"],
            "after_j": j["kinetic_after_j"], "broken": int(j["stem_broken"]), "bole_broken": int(below_crown),
            "break_m": "" if j["break_height_m"] is None else round(j["break_height_m"], 2),
            "root_failed": int(j.get("root_failed", False)), "breaks": j.get("stem_breaks", "")}


def main():
    ap = arguments(__doc__, dbh="10,15,20,25,30,40", speeds="5,10,15,25")
    ap.add_argument("--heights", default="0.5,1,2")
    ap.add_argument("--eccentricities", default="0,0.5")
    ap.add_argument("--volume-at-height", action="append", default=None, metavar="H:V",
                    help="block volume V (m3) for the impacts at height H (m); default 0.5:0.1, as the scene's "
                         "0.5 m3 cube (bounding radius 0.54 m) cannot fly with its centre 0.5 m up")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs/figures/stem-matrix"))
    a = ap.parse_args()
    spacings = [float(x) for x in a.spacings.split(",")]
    if len(spacings) < 2:
        sys.exit("--spacings needs two or more node spacings: each impact at the first is compared with the second")
    volumes = dict(x.split(":") for x in (a.volume_at_height if a.volume_at_height is not None else ["0.5:0.1"]))
    volume_of = lambda height: next((v for hh, v in volumes.items() if float(hh) == float(height)), "")
    cases = list(itertools.product(*(a.__dict__[k].split(",") for k in ("dbh", "speeds", "heights", "eccentricities"))))
    jobs = [(c, h) for c in cases for h in spacings]
    results = {}
    with concurrent.futures.ThreadPoolExecutor(a.threads) as pool:
        futures = {pool.submit(run_one, a.exe, a.set, *c, h, volume_of(c[2])): (c, h) for c, h in jobs}
        for n, f in enumerate(concurrent.futures.as_completed(futures), 1):
            results[futures[f]] = f.result()
            print(f"\r{n}/{len(jobs)} runs", end="", file=sys.stderr, flush=True)
    print(file=sys.stderr)

    rows, worst, problems = [], {"tree": 0.0, "block": 0.0}, []
    for c in cases:
        r = [results[(c, h)] for h in spacings]
        row = dict(zip(("dbh_cm", "speed_m_s", "height_m", "eccentricity"), c))
        row["block_m3"] = volume_of(c[2]) or "scene"
        for h, x in zip(spacings, r):
            for k in ("tree_j", "after_j", "broken", "break_m", "bole_broken", "root_failed", "breaks"):
                row[f"{k}@{h:g}"] = x.get(k, "")
        row["before_j"] = r[0].get("before_j", "")
        rows.append(row)
        a0, a1 = r[0], r[1]
        if "tree_j" not in a0 or "tree_j" not in a1:
            problems.append(f"{c}: {a0.get('error', a0)} / {a1.get('error', a1)}")
            continue
        # Relative to the impact energy, the scale a block's run-out and a tree's share are read on.
        dt = abs(a0["tree_j"] - a1["tree_j"]) / a1["before_j"]
        db = abs(a0["after_j"] - a1["after_j"]) / a1["before_j"]
        worst["tree"], worst["block"] = max(worst["tree"], dt), max(worst["block"], db)
        row["tree_gap"], row["block_gap"] = round(dt, 4), round(db, 4)
        row["tree_gap_own"] = round(abs(a0["tree_j"] - a1["tree_j"]) / max(a1["tree_j"], 1.0), 4)
        row["same_outcome"] = int(a0["broken"] == a1["broken"] and a0["root_failed"] == a1["root_failed"])
        row["same_break"] = int(a0["broken"] == a1["broken"])
        row["same_bole"] = int(a0["bole_broken"] == a1["bole_broken"])
        if a0["break_m"] != "" and a1["break_m"] != "":
            row["break_shift_m"] = round(abs(a0["break_m"] - a1["break_m"]), 2)
    os.makedirs(os.path.dirname(a.out), exist_ok=True)
    with open(a.out + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()) + [k for k in ("tree_gap", "block_gap", "tree_gap_own", "same_outcome", "same_break", "same_bole", "break_shift_m") if k not in rows[0]])
        w.writeheader()
        w.writerows(rows)
    # Impacts that did not run at both spacings are listed as problems, not counted as gaps.
    valid = [r for r in rows if "tree_gap" in r]
    if not valid:
        sys.exit("no impact ran at both of the first two spacings: " + "; ".join(problems))
    gaps_t = sorted(r["tree_gap"] for r in valid)
    gaps_b = sorted(r["block_gap"] for r in valid)
    gaps_own = sorted(r["tree_gap_own"] for r in valid)
    within = lambda g, bar: sum(1 for x in g if x <= bar)
    same = sum(r.get("same_outcome", 0) for r in rows)
    h0, h1 = spacings[0], spacings[1]
    print(f"{len(valid)} of {len(rows)} impacts ran at both, {h0:g} m against {h1:g} m (gaps relative to the impact energy):")
    print(f"  tree's energy: median gap {gaps_t[len(gaps_t)//2]:.3f}, worst {worst['tree']:.3f}, "
          f"{within(gaps_t, 0.05)}/{len(valid)} within 5 %")
    print(f"  tree's energy against itself: median gap {gaps_own[len(gaps_own)//2]:.3f}, "
          f"{within(gaps_own, 0.05)}/{len(valid)} within 5 %, {within(gaps_own, 0.10)}/{len(valid)} within 10 %")
    print(f"  block's exit energy: median gap {gaps_b[len(gaps_b)//2]:.3f}, worst {worst['block']:.3f}, "
          f"{within(gaps_b, 0.05)}/{len(valid)} within 5 %")
    print(f"  same outcome (stem broken or not, root plate let go or not): {same}/{len(valid)}; "
          f"stem broken or not alone: {sum(r.get('same_break', 0) for r in rows)}/{len(valid)}")
    shifts = sorted(r["break_shift_m"] for r in rows if "break_shift_m" in r)
    if shifts:
        print(f"  broken at both: lowest break moved by median {shifts[len(shifts)//2]:.2f} m, "
              f"{within(shifts, 1.0)}/{len(shifts)} within 1 m; broken below the crown at one spacing only: "
              f"{sum(1 for r in rows if r.get('same_bole') == 0)}/{len(rows)}")
    print_breaks(rows, spacings)
    for p in problems:
        print("  problem:", p)
    print_by_height(rows, spacings)
    plot(a.out, spacings, rows)


def print_breaks(rows, spacings):
    """How many connections a broken stem lost, spacing by spacing: Eq. 6's rupture is brittle, so a
    whipped stem shatters into more pieces the finer its nodes (docs/model-stems.md, "A broken stem
    shatters"). With forest.piece_max_time_s = 0 a stem the block has left may sleep before its pieces
    land and break again: then they are fewer than a whole run's."""
    counts = {h: [r[f"breaks@{h:g}"] for r in rows if r.get(f"broken@{h:g}") == 1 and r.get(f"breaks@{h:g}") != ""]
              for h in spacings}
    print("  breaks of the broken stems, median (most): " +
          ", ".join(f"{statistics.median(c):g} ({max(c)}) at {h:g} m" if c else f"none broken at {h:g} m"
                    for h, c in counts.items()))


def print_by_height(rows, spacings):
    """Each pair of successive spacings, impact height by impact height: where a spacing stops
    resolving an impact (below its first node) shows up here."""
    print("by impact height (gaps relative to the impact energy; tree | block: median, worst, within 5 %):")
    for h0, h1 in zip(spacings, spacings[1:]):
        for height in sorted({r["height_m"] for r in rows}, key=float):
            sel = [r for r in rows if r["height_m"] == height and "" not in
                   (r[f"tree_j@{h0:g}"], r[f"tree_j@{h1:g}"], r[f"after_j@{h0:g}"], r[f"after_j@{h1:g}"])]
            if not sel:
                continue
            cols = []
            for k in ("tree_j", "after_j"):
                g = sorted(abs(r[f"{k}@{h0:g}"] - r[f"{k}@{h1:g}"]) / r["before_j"] for r in sel)
                cols.append(f"{g[len(g) // 2]:.3f}, {g[-1]:.3f}, {sum(x <= 0.05 for x in g)}/{len(g)}")
            print(f"  {h0:g} against {h1:g} m, {height} m high: {' | '.join(cols)}")


def plot(out, spacings, rows):
    """Tree's energy and block's exit energy at each finer spacing against the coarsest, as fractions
    of the impact energy: converged impacts sit on the diagonal."""
    data = out + ".dat"
    with open(data, "w") as f:
        for k, h in enumerate(spacings[1:], 1):
            for r in rows:
                if r.get(f"tree_j@{h:g}", "") == "" or r.get(f"tree_j@{spacings[0]:g}", "") == "":
                    continue
                e = r["before_j"]
                f.write(f"{r[f'tree_j@{spacings[0]:g}']/e} {r[f'tree_j@{h:g}']/e} "
                        f"{r[f'after_j@{spacings[0]:g}']/e} {r[f'after_j@{h:g}']/e}\n")
            f.write("\n\n")
    series = lambda cols: ", ".join(
        f"'{data}' index {k} using {cols} with points pt {6 + k} title '{h:g} m'" for k, h in enumerate(spacings[1:]))
    script = f"""set terminal svg size 900,420 dynamic font 'sans,11'
set output '{out}.svg'
set multiplot layout 1,2 title 'Single-tree matrix ({len(rows)} impacts): finer spacing against {spacings[0]:g} m'
set size ratio -1
set xrange [0:1]; set yrange [0:1]; set grid
set xlabel 'at {spacings[0]:g} m (fraction of the impact energy)'
set ylabel 'at the finer spacing'
set key top left
set title "tree's energy over the impact"
plot x with lines lc 'gray' title 'same', 1.05*x with lines dt 2 lc 'gray' notitle, 0.95*x with lines dt 2 lc 'gray' notitle, {series('1:2')}
set title "block's kinetic energy after the tree"
plot x with lines lc 'gray' title 'same', {series('3:4')}
unset multiplot
"""
    subprocess.run(["gnuplot"], input=script, text=True, check=False)
    os.remove(data)


if __name__ == "__main__":
    main()
