#!/usr/bin/env python3
"""The error-against-run-time table of docs/accuracy.md from `simulate` folders of one forest.

    python3 scripts/accuracy_table.py BARE REFERENCE DEFAULT [LABEL=FOLDER ...] [--replicates 2000]

Each folder holds the runs of one setting (the same --runs and --seed, so run i of every folder
starts from the same release). Per setting: runs the energy audit stopped, median CPU per run and
its ratio to the default's (percentile bootstrap over the runs), total CPU, the paired run-out
error against the reference (|run-out - reference's run-out| run by run: chaos makes it large at
every setting, which is why the table's verdict rests on the distributions), Dist50, PF50 with its
interval (scripts/pf50_from_runs.py, Eq. 26 against BARE), PF50's difference from the reference
and from the default with theirs, and the share of the trees' energy left vibrating.
"""
import argparse, csv, json, os, random, statistics, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pf50_from_runs import interval, runouts  # noqa: E402


def rows(folder):
    """runs.csv by run index, with each run-out as a float (NaN for a failed run)."""
    with open(os.path.join(folder, "runs.csv")) as f:
        by_run = {int(r["run"]): r for r in csv.DictReader(f)}
    for r in by_run.values():
        try:
            r["runout_m"] = float(r["runout_m"])
        except ValueError:
            r["runout_m"] = float("nan")
    return by_run


def quantile(xs, q):
    s = sorted(xs)
    return s[min(len(s) - 1, int(q * (len(s) - 1) + 0.5))]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("bare")
    ap.add_argument("reference")
    ap.add_argument("default")
    ap.add_argument("settings", nargs="*", help="LABEL=FOLDER")
    ap.add_argument("--replicates", type=int, default=2000)
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    settings = [("reference", a.reference), ("defaults", a.default)]
    for s in a.settings:
        label, sep, folder = s.rpartition("=")  # labels may hold "=", folders not
        if not sep:
            raise SystemExit(f"{s}: expected LABEL=FOLDER")
        settings.append((label, folder))
    rng = random.Random(a.seed)
    bare, _ = runouts(a.bare)
    data = []
    for label, folder in settings:
        by_run = rows(folder)
        data.append((label, by_run, [r["runout_m"] for r in by_run.values() if r["runout_m"] == r["runout_m"]], folder))
    median_of = lambda xs: statistics.median(rng.choices(xs, k=len(xs)))
    pf_boot = [[] for _ in data]
    for _ in range(a.replicates):
        d0 = median_of(bare)
        for k, (_, _, xs, _) in enumerate(data):
            pf_boot[k].append(1 - median_of(xs) / d0)
    d0 = statistics.median(bare)
    ref_rows, def_rows = data[0][1], data[1][1]
    def_cpu = [float(r["cpu_s"]) for r in def_rows.values()]
    print(f"Dist50 without forest {d0:.1f} m ({len(bare)} runs); {a.replicates} bootstrap replicates\n")
    print("| setting | audit stops | CPU per run, median (÷ defaults [95 %]) | total CPU | paired run-out error vs reference, "
          "median / p90 | Dist50 | PF50 [95 %] | PF50 − reference [95 %] | PF50 − defaults [95 %] | left vibrating |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for k, (label, by_run, xs, folder) in enumerate(data):
        cpu = [float(r["cpu_s"]) for r in by_run.values()]
        ratios = sorted(median_of(cpu) / median_of(def_cpu) for _ in range(a.replicates))
        ratio = "" if k == 1 else f" ({statistics.median(cpu) / statistics.median(def_cpu):.2f} [{interval(ratios)[0]:.2f}, {interval(ratios)[1]:.2f}])"
        stops = sum(1 for r in by_run.values() if r["stop_reason"] == "failed")
        paired = [d for d in (abs(r["runout_m"] - ref_rows[i]["runout_m"]) for i, r in by_run.items() if i in ref_rows) if d == d]
        error = "—" if k == 0 else f"{statistics.median(paired):.0f} / {quantile(paired, 0.9):.0f} m"
        pf = 1 - statistics.median(xs) / d0
        lo, hi = interval(pf_boot[k])

        def diff(j):
            if j == k:
                return ""
            dlo, dhi = interval([x - y for x, y in zip(pf_boot[k], pf_boot[j])])
            return f"{pf - (1 - statistics.median(data[j][2]) / d0):+.3f} [{dlo:+.3f}, {dhi:+.3f}]"
        summary = os.path.join(folder, "summary.json")
        vibrating = json.load(open(summary)).get("left_vibrating_share_of_tree_terms") if os.path.exists(summary) else None
        share = f"{100 * vibrating:.1f} %" if vibrating is not None else ""
        print(f"| {label} | {stops} of {len(by_run)} | {statistics.median(cpu):.3f} s{ratio} | {sum(cpu):.0f} s | {error} | "
              f"{statistics.median(xs):.1f} m | {pf:.3f} [{lo:.3f}, {hi:.3f}] | {diff(0)} | {diff(1)} | {share} |")


if __name__ == "__main__":
    main()
