#!/usr/bin/env python3
"""Wall time of one assess campaign on 1, 2 and 4 MPI ranks (one thread each), and on one process with
as many threads as cores, repeated and interleaved; prints the medians and their ratios to one rank.

  python3 bench/mpi_scaling.py [REPEATS] [STAND ...]     (from the project root, after the build)

Defaults: 3 repeats, stand GR1, 8 runs x 2 realisations x A/NA + 50 runs without forest on the
shipped slope (data/scenes/no-forest.ini). Ranks beyond the cores are oversubscribed: on this 2-core
machine 4 ranks measure the coordination's overhead, not a speed-up. Each configuration's PF50 values
are compared with the first one's: they must be identical.
"""
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

PROJECT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
exe = os.path.join(PROJECT, "build/apps/sylvarock")
repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 3
stands = sys.argv[2:] or ["GR1"]
design = ["assess", "--scene", os.path.join(PROJECT, "data/scenes/no-forest.ini"), "--runs", "8", "--realisations", "2",
          "--baseline-runs", "50", "--seed", "4", "--bootstrap", "500"]
for s in stands:
    design += ["--stand", os.path.join(PROJECT, "data/stands", s)]
mpirun = shutil.which("mpirun")
if not mpirun:
    sys.exit("mpirun not found: apt-get install openmpi-bin (scripts/install-deps.sh)")
root = ["--allow-run-as-root"] if os.geteuid() == 0 else []
cores = os.cpu_count() or 1
configs = {
    "1 rank": [mpirun] + root + ["-np", "1", exe] + design + ["--threads", "1"],
    "2 ranks": [mpirun] + root + ["--oversubscribe", "-np", "2", exe] + design + ["--threads", "1"],
    "4 ranks": [mpirun] + root + ["--oversubscribe", "-np", "4", exe] + design + ["--threads", "1"],
    f"1 process, {cores} threads": [exe] + design + ["--threads", str(cores)],
}


def pf50s(out):
    j = json.load(open(os.path.join(out, "results.json")))
    return [(s["name"], s["structure"], s["pf50"]) for s in j["stands"]]


walls = {k: [] for k in configs}
reference = None
tmp = tempfile.mkdtemp(prefix="sylvarock-mpi-bench-")
try:
    for rep in range(repeats):
        for name, cmd in configs.items():
            out = os.path.join(tmp, f"{rep}-{len(walls[name])}-{name.replace(' ', '_').replace(',', '')}")
            t0 = time.time()
            subprocess.run(cmd + ["--out", out], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            walls[name].append(time.time() - t0)
            values = pf50s(out)
            if reference is None:
                reference = values
            elif values != reference:
                sys.exit(f"{name}: PF50 differ from the first configuration's: {values} vs {reference}")
            shutil.rmtree(out)
finally:
    shutil.rmtree(tmp, ignore_errors=True)

base = statistics.median(walls["1 rank"])
print(f"assess {' '.join(stands)}: 8 runs x 2 realisations x A/NA + 50 without forest; {repeats} repeats, {cores} cores")
for name, w in walls.items():
    m = statistics.median(w)
    print(f"  {name:<24} median wall {m:6.1f} s  (runs {', '.join(f'{x:.1f}' for x in w)})  speed-up {base / m:.2f}")
print(f"PF50 identical in every configuration: {reference}")
