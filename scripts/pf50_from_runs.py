#!/usr/bin/env python3
"""PF50 of forested `simulate` runs against runs without forest, with percentile bootstrap intervals.

    python3 scripts/pf50_from_runs.py BARE_DIR FOREST_DIR [FOREST_DIR ...] [--replicates 2000] [--seed 1]

PF50 = 1 - Dist50(forest) / Dist50(no forest) (the paper's Eq. 26), Dist50 the median run-out
(runs.csv `runout_m`). The interval resamples the runs of both folders; with two or more forest
folders the difference of each from the first is given too, resampled the same way. Runs that
failed (no run-out) are left out and counted. `assess` does this for whole campaigns; this is for
comparing `simulate` runs of one forest under two settings (e.g. two node spacings).
"""
import argparse, csv, os, random, statistics


def runouts(folder):
    values, failed = [], 0
    with open(os.path.join(folder, "runs.csv")) as f:
        for row in csv.DictReader(f):
            try:
                x = float(row["runout_m"])
            except ValueError:
                x = float("nan")
            if x != x:
                failed += 1
            else:
                values.append(x)
    if not values:
        raise SystemExit(f"{folder}/runs.csv: no run with a run-out")
    return values, failed


def interval(samples, confidence=0.95):
    s = sorted(samples)
    lo = s[int((1 - confidence) / 2 * (len(s) - 1))]
    hi = s[int((1 + confidence) / 2 * (len(s) - 1))]
    return lo, hi


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("bare")
    ap.add_argument("forests", nargs="+")
    ap.add_argument("--replicates", type=int, default=2000)
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    rng = random.Random(a.seed)
    bare, _ = runouts(a.bare)
    forests = [runouts(f) for f in a.forests]
    resample = lambda xs: statistics.median(rng.choices(xs, k=len(xs)))
    boot = [[] for _ in forests]
    for _ in range(a.replicates):
        d0 = resample(bare)
        for k, (xs, _) in enumerate(forests):
            boot[k].append(1 - resample(xs) / d0)
    d0 = statistics.median(bare)
    print(f"{a.bare}: Dist50 {d0:.1f} m over {len(bare)} runs")
    pf = []
    for folder, (xs, failed), b in zip(a.forests, forests, boot):
        pf.append(1 - statistics.median(xs) / d0)
        lo, hi = interval(b)
        print(f"{folder}: {len(xs)} runs ({failed} failed), Dist50 {statistics.median(xs):.1f} m, "
              f"PF50 {pf[-1]:.3f} [{lo:.3f}, {hi:.3f}]")
    for k in range(1, len(forests)):
        lo, hi = interval([x - y for x, y in zip(boot[k], boot[0])])
        print(f"{a.forests[k]} - {a.forests[0]}: PF50 {pf[k] - pf[0]:+.3f} [{lo:+.3f}, {hi:+.3f}]")


if __name__ == "__main__":
    main()
