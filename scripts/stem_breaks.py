#!/usr/bin/env python3
"""Where and when single trees break, at several node spacings (issue 11, docs/model-stems.md "A broken
stem shatters"): whole runs of the single-tree scene, head-on 1 m up, through the CLI; from each run's
energy.json `breaks`, the connections broken in the bole (D >= 5 cm) and in the top (D < 5 cm), those
within 0.2 s of the first touch (the whip, before the pieces fall), and the largest burst: breaks each
within 1 ms of the one before (a stem unzipping, one connection after the other).

    python3 scripts/stem_breaks.py [--exe build/apps/sylvarock] [--spacings 0.5,0.25,0.125]
        [--dbh 15,20,25,30] [--speeds 10,15,25] [--threads 2] [--set key=value ...]

Prints one line per impact and spacing, then the medians over the impacts per spacing.
"""
import concurrent.futures, itertools, json, os, statistics, subprocess, sys, tempfile

from single_tree import arguments, simulate_command
BOLE_CM = 5.0      # thinner is the top: where Eq. 6's strength (D^3) and a fracture energy's (D^2) vanish
BURST_S = 1e-3     # the unzipping fronts measured cross a connection in 0.06-0.8 ms; the block's touch lasts ~0.1 s
WHIP_S = 0.2       # a piece broken off 10 m up takes ~1.4 s to land


def energy_of(exe, extra, dbh, speed, h):
    with tempfile.TemporaryDirectory() as out:
        cmd = simulate_command(exe, out, dbh, speed, 1, 0, h, extra) + ["--no-figures"]
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode:
            return {"error": f"exit {r.returncode}: {r.stderr.strip()[-300:]}"}
        return json.load(open(os.path.join(out, "energy.json")))


def summary(energy):
    """None for a run that failed, stopped on its audit or missed the tree: it has no breaks to count."""
    if "error" in energy or energy.get("run_failed") or not energy.get("impacts"):
        return None
    breaks = energy.get("breaks", [])
    bole = sum(b["diameter_cm"] >= BOLE_CM for b in breaks)
    whip = sum(b["time_s"] - energy["impact_time_s"] <= WHIP_S for b in breaks)
    burst = longest = 1 if breaks else 0
    for before, b in zip(breaks, breaks[1:]):
        burst = burst + 1 if b["time_s"] - before["time_s"] <= BURST_S else 1
        longest = max(longest, burst)
    return {"breaks": len(breaks), "bole": bole, "top": len(breaks) - bole, "whip": whip, "burst": longest}


def main():
    a = arguments(__doc__, dbh="15,20,25,30", speeds="10,15,25").parse_args()
    spacings = a.spacings.split(",")
    cases = list(itertools.product(a.dbh.split(","), a.speeds.split(",")))
    with concurrent.futures.ThreadPoolExecutor(a.threads) as pool:
        runs = {(c, h): pool.submit(energy_of, a.exe, a.set, *c, h) for c in cases for h in spacings}
        got = {k: summary(f.result()) for k, f in runs.items()}
    print("DBH cm, speed m/s | " + " | ".join(f"{h} m: breaks (bole + top; in the whip), largest burst" for h in spacings))
    for c in cases:
        cells = (got[(c, h)] for h in spacings)
        print(f"{c[0]} cm, {c[1]} m/s | " + " | ".join(
            f"{s['breaks']} ({s['bole']} + {s['top']}; {s['whip']}), {s['burst']}" if s else "failed or missed the tree"
            for s in cells))
    medians = []
    for h in spacings:
        ran = [got[(c, h)] for c in cases if got[(c, h)]]
        medians.append(", ".join(f"{k} {statistics.median(s[k] for s in ran):g}" for k in ("breaks", "bole", "top", "whip", "burst"))
                       + (f" ({len(ran)} of {len(cases)} ran)" if len(ran) < len(cases) else "") if ran else "none ran")
    print("median | " + " | ".join(medians))
    missing = [(c, h, runs[(c, h)].result().get("error", "")) for c in cases for h in spacings if not got[(c, h)]]
    for c, h, why in missing:
        print(f"not counted: {c[0]} cm at {c[1]} m/s, {h} m: {why or 'the run failed or missed the tree'}", file=sys.stderr)
    sys.exit(1 if missing else 0)


if __name__ == "__main__":
    main()
