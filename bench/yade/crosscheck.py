#!/usr/bin/env python3
"""Cross-check sylvarock's block/soil core against Yade on the identical scene (issue 17).

The no-forest scene, narrowed to a strip, is exported run by run with `sylvarock scene export`
(soil spheres, block spheres, release, the block/soil law's coefficients) and run sphere for sphere in
Yade (yade_run.py, ViscElMat: the normal force floored at zero, so sylvarock runs with
soil.dashpot_pulls=false). Run-outs are chaotic: the two codes are compared as distributions, with
two-sample Kolmogorov-Smirnov tests, and run by run only over the first seconds, before chaos
separates them (as it separates Yade from itself at two time steps).

    python3 bench/yade/crosscheck.py [--yade-runs 16] [--runs 200] [--jobs 2] [--out out/yade]

Needs Yade (apt-get install yade); never run by CI. Without Yade it says so and stops.
"""
import argparse
import bisect
import csv
import json
import math
import os
import random
import shutil
import statistics
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def ks_two_sample(a, b):
    """D statistic and asymptotic p-value (Kolmogorov's distribution with Stephens' small-sample
    correction, as in Press et al., Numerical Recipes, 3rd ed., Sect. 14.3.3)."""
    a, b = sorted(a), sorted(b)
    n, m = len(a), len(b)
    d = 0.0
    for x in a + b:
        d = max(d, abs(bisect.bisect_right(a, x) / n - bisect.bisect_right(b, x) / m))
    en = math.sqrt(n * m / (n + m))
    lam = (en + 0.12 + 0.11 / en) * d
    if lam < 0.2:
        return d, 1.0
    p = 2 * sum((-1) ** (k - 1) * math.exp(-2 * k * k * lam * lam) for k in range(1, 101))
    return d, min(1.0, max(0.0, p))


def median_difference_interval(a, b, replicates=2000, confidence=0.95, seed=17):
    """Percentile bootstrap interval of median(b) - median(a): what the runs can resolve."""
    rng = random.Random(seed)
    diffs = sorted(statistics.median(rng.choices(b, k=len(b))) - statistics.median(rng.choices(a, k=len(a)))
                   for _ in range(replicates))
    lo = diffs[int((1 - confidence) / 2 * replicates)]
    hi = diffs[int((1 + confidence) / 2 * replicates) - 1]
    return lo, hi


def read_trajectory(path):
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def position_at(traj, t):
    """Centre at time t, linear between samples; None once the run has ended."""
    times = [r["t"] for r in traj]
    i = bisect.bisect_left(times, t)
    if i >= len(traj):
        return None
    if i == 0:
        r = traj[0]
        return r["x"], r["y"], r["z"]
    r0, r1 = traj[i - 1], traj[i]
    w = (t - r0["t"]) / (r1["t"] - r0["t"])
    return tuple(r0[c] + w * (r1[c] - r0[c]) for c in ("x", "y", "z"))


def quantities(summary, traj):
    q = {"top speed (m/s)": summary["max_speed_m_s"], "duration (s)": summary["duration_s"],
         "stop x (m)": summary["stop_x"], "stop y (m)": summary["stop_y"]}
    for t in (5, 10, 20):
        p = position_at(traj, t)
        q[f"x at {t} s (m)"] = p[0] if p else None
    return q


def run(cmd, **kw):
    r = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if r.returncode != 0:
        sys.exit(f"failed: {' '.join(cmd)}\n{r.stdout[-2000:]}\n{r.stderr[-2000:]}")
    return r


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", default=os.path.join(ROOT, "build/apps/sylvarock"))
    ap.add_argument("--scene", default=os.path.join(ROOT, "data/scenes/no-forest.ini"))
    ap.add_argument("--width", type=float, default=40, help="strip width, m (the release sits in its middle)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--yade-runs", type=int, default=16)
    ap.add_argument("--runs", type=int, default=200, help="sylvarock runs")
    ap.add_argument("--dt", type=float, default=1e-3, help="Yade's time step, s")
    ap.add_argument("--self-check-dt", type=float, default=0.5e-3,
                    help="the first 2 Yade runs again at this step, to show Yade's own chaos (0: skip)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--out", default="out/yade-crosscheck")
    a = ap.parse_args()

    yade = shutil.which("yade")
    if not yade:
        print("Yade is not installed (apt-get install yade): nothing to compare against.")
        return 0
    os.makedirs(a.out, exist_ok=True)
    sets = ["--set", f"terrain.width_m={a.width}", "--set", f"release.y_m={a.width / 2}",
            "--set", "soil.dashpot_pulls=false"]

    ours_dir = os.path.join(a.out, "sylvarock")
    r = run([a.exe, "simulate", "--scene", a.scene, "--runs", str(a.runs), "--seed", str(a.seed), "--trajectory",
             "--no-figures", "--out", ours_dir] + sets)
    print("sylvarock: " + next((l for l in r.stdout.splitlines() if "Dist50" in l), "").strip())
    with open(os.path.join(ours_dir, "runs.csv")) as f:
        ours_runs = list(csv.DictReader(f))
    ours = []
    for row in ours_runs:
        s = {"max_speed_m_s": float(row["max_speed_m_s"]), "duration_s": float(row["duration_s"]),
             "stop_x": float(row["stop_x"]), "stop_y": float(row["stop_y"])}
        traj = read_trajectory(os.path.join(ours_dir, "trajectories", f"run_{int(row['run']):04d}.csv"))
        ours.append((s, traj))

    # Yade runs i = 0..N-1 start from our runs' releases, so the first seconds can be paired.
    def yade_run(i, dt, tag):
        scene_dir = os.path.join(a.out, f"scene_{i:03d}")
        if not os.path.exists(os.path.join(scene_dir, "soil_contact.csv")):
            run([a.exe, "scene", "export", "--scene", a.scene, "--seed", str(a.seed), "--run", str(i), "--out", scene_dir]
                + sets)
        prefix = os.path.join(a.out, f"yade_{tag}_{i:03d}")
        if not os.path.exists(prefix + ".json"):
            run([yade, "-n", "-x", "-j1", os.path.join(HERE, "yade_run.py"), scene_dir, repr(dt), prefix],
                env=dict(os.environ, OMP_NUM_THREADS="1"))
        with open(prefix + ".json") as f:
            summary = json.load(f)
        print(f"  Yade run {i} (dt {dt:g} s): {summary['stop_reason']} after {summary['duration_s']:.1f} s at "
              f"x = {summary['stop_x']:.1f} m", flush=True)
        return summary, read_trajectory(prefix + ".csv")

    jobs = [(i, a.dt, "dt") for i in range(a.yade_runs)]
    if a.self_check_dt > 0:
        jobs += [(i, a.self_check_dt, "half") for i in range(min(2, a.yade_runs))]
    with ThreadPoolExecutor(a.jobs) as pool:
        results = list(pool.map(lambda j: yade_run(*j), jobs))
    yade = results[:a.yade_runs]
    yade_half = results[a.yade_runs:]

    print(f"\nDistributions: {len(yade)} Yade runs (dt {a.dt:g} s) against {len(ours)} sylvarock runs "
          f"(campaign seed {a.seed}; strip {a.width:g} m wide)")
    print(f"{'quantity':<18} {'Yade median':>12} {'sylvarock median':>17} {'difference':>11} "
          f"{'95 % interval':>17} {'KS D':>6} {'p':>6}")
    qy = [quantities(*y) for y in yade]
    qo = [quantities(*o) for o in ours]
    for key in qy[0]:
        ay = [q[key] for q in qy if q[key] is not None]
        ao = [q[key] for q in qo if q[key] is not None]
        if len(ay) < 3 or len(ao) < 3:
            print(f"{key:<18} too few runs last that long ({len(ay)} Yade, {len(ao)} sylvarock)")
            continue
        my, mo = statistics.median(ay), statistics.median(ao)
        d, p = ks_two_sample(ay, ao)
        lo, hi = median_difference_interval(ay, ao)
        if key != "stop y (m)":  # across the strip the position has no natural zero: absolute
            rel = f"{100 * (mo - my) / abs(my):+.1f} %"
            interval = f"[{100 * lo / abs(my):+.1f}, {100 * hi / abs(my):+.1f}] %"
        else:
            rel, interval = f"{mo - my:+.2f}", f"[{lo:+.2f}, {hi:+.2f}]"
        print(f"{key:<18} {my:>12.2f} {mo:>17.2f} {rel:>11} {interval:>17} {d:>6.2f} {p:>6.2f}   (n = {len(ay)}, {len(ao)})")

    def separation(t1, t2, horizon):
        """Largest distance between two runs' centres over [0, horizon] s (0.05 s samples)."""
        worst, t = 0.0, 0.0
        while t <= horizon:
            p1, p2 = position_at(t1, t), position_at(t2, t)
            if p1 and p2:
                worst = max(worst, math.dist(p1, p2))
            t += 0.05
        return worst

    print("\nRun by run, same release: largest distance between the block centres")
    for horizon in (1, 2, 3, 5):
        seps = [separation(yade[i][1], ours[i][1], horizon) for i in range(min(len(yade), len(ours)))]
        line = f"  over the first {horizon} s: Yade vs sylvarock median {statistics.median(seps):.3f} m, max {max(seps):.3f} m"
        if yade_half:
            own = [separation(yade[i][1], yade_half[i][1], horizon) for i in range(len(yade_half))]
            line += f"; Yade vs itself at dt {a.self_check_dt:g} s: max {max(own):.3f} m"
        print(line)
    return 0


if __name__ == "__main__":
    sys.exit(main())
