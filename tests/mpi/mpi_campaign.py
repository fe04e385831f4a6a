#!/usr/bin/env python3
"""A campaign spread over MPI ranks gives, bit for bit, the one-process campaign's results.

  mpi_campaign.py same     SYLVAROCK MPIRUN  assess, both models: 3 ranks x 2 threads against 1 process x 1 thread
  mpi_campaign.py resume   SYLVAROCK MPIRUN  assess: a 3-rank job whose rank 1 is killed mid-campaign,
                                             resumed on 2 ranks, against 1 process
  mpi_campaign.py simulate SYLVAROCK MPIRUN  simulate: the lumped model through a forest (2 000 runs,
                                             their tree impacts) and single-tree DEM impacts with
                                             trajectories, 3 ranks against 1 process

For simulate, every file the command writes is compared, without the columns and keys that time the
run (cpu_s, wall and CPU seconds), which no two runs share.

Compared: results.json byte for byte, and each table of the campaign store (design, campaigns,
forests, runs) as a set of rows (runs are stored in the order they finish, which depends on the
ranks; each row carries its run index, seed, values and checksum). The short test slope (tests/assess/
data/short-scene.ini) keeps each run to milliseconds; its forests are still generated and summarised
on the ranks that run them.
"""
import json
import os
import shutil
import signal
import sqlite3
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT = os.path.dirname(os.path.dirname(HERE))
mode, exe, mpirun = sys.argv[1], sys.argv[2], sys.argv[3]
# Containers often forbid the cross-process memory reads Open MPI uses for messages above 4 kB on one
# machine (simulate's batches); copying through shared memory works everywhere (docs/cluster.md).
os.environ.setdefault("OMPI_MCA_btl_vader_single_copy_mechanism", "none")


def design(runs, baseline):
    return ["assess", "--stand", os.path.join(PROJECT, "data/stands/GR1"), "--stand",
            os.path.join(PROJECT, "data/stands/PY1"), "--scene", os.path.join(PROJECT, "tests/assess/data/short-scene.ini"),
            "--runs", str(runs), "--realisations", "2", "--baseline-runs", str(baseline), "--seed", "11",
            "--bootstrap", "300"]


def mpi(ranks):
    root = ["--allow-run-as-root"] if os.geteuid() == 0 else []
    return [mpirun] + root + ["--oversubscribe", "-np", str(ranks), exe]


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    if r.returncode != 0:
        sys.exit(f"FAILED (exit {r.returncode}): {' '.join(cmd)}\n{r.stdout}\n{r.stderr}")
    return r


def contents(out):
    """What the campaign keeps: results.json and the store's tables (runs, forests, design, campaigns)."""
    found = {"results.json": open(os.path.join(out, "results.json"), "rb").read()}
    with sqlite3.connect(os.path.join(out, "campaign.sqlite")) as db:
        for table in ("design", "campaigns", "forests", "runs"):
            found[table] = sorted(db.execute(f"SELECT * FROM {table}").fetchall(), key=repr)
    return found


def compare(one, many):
    a, b = contents(one), contents(many)
    differ = [k for k in a if a[k] != b[k]]
    if differ:
        sys.exit(f"FAILED: differ between one process and MPI: {differ}")
    print(f"identical: results.json, {len(a['forests'])} forest summaries, {len(a['runs'])} runs")


def timeless(path):
    """A simulate output file without what times the run: runs.csv's cpu_s column, JSON keys on time."""
    data = open(path, "rb").read()
    if path.endswith(".csv"):
        rows = [l.split(b",") for l in data.splitlines()]
        drop = [i for i, c in enumerate(rows[0]) if c.startswith(b"cpu")] if rows else []
        return [[c for i, c in enumerate(r) if i not in drop] for r in rows]
    if path.endswith(".json"):
        def strip(o):
            if isinstance(o, dict):
                return {k: strip(v) for k, v in o.items() if not any(t in k for t in ("wall", "cpu", "phase", "seconds"))}
            if isinstance(o, list):
                return [strip(v) for v in o]
            return o
        return strip(json.loads(data))
    return data


def compare_outputs(one, many):
    files = lambda d: sorted(os.path.relpath(os.path.join(r, f), d) for r, _, fs in os.walk(d) for f in fs)
    a, b = files(one), files(many)
    if a != b:
        sys.exit(f"FAILED: files differ: {sorted(set(a) ^ set(b))}")
    differ = [f for f in a if timeless(os.path.join(one, f)) != timeless(os.path.join(many, f))]
    if differ:
        sys.exit(f"FAILED: differ between one process and MPI: {differ}")
    rows = len(open(os.path.join(one, "runs.csv")).read().splitlines()) - 1
    print(f"identical: {len(a)} files ({', '.join(a[:4])}{', ...' if len(a) > 4 else ''}), {rows} runs")


def rank_pids(job):
    """{rank: pid} of the processes mpirun started (read from their environment)."""
    pids = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            env = open(f"/proc/{entry}/environ", "rb").read().split(b"\0")
            stat = open(f"/proc/{entry}/stat").read()
        except OSError:
            continue
        if int(stat.rsplit(")", 1)[1].split()[1]) != job.pid:
            continue
        for kv in env:
            if kv.startswith(b"OMPI_COMM_WORLD_RANK="):
                pids[int(kv.split(b"=")[1])] = int(entry)
    return pids


def logged(out):
    """Runs stored so far, read beside the writer (SQLite's WAL lets a reader in while it writes)."""
    path = os.path.join(out, "campaign.sqlite")
    if not os.path.exists(path):
        return 0
    try:
        with sqlite3.connect(f"file:{path}?mode=ro", uri=True, timeout=5) as db:
            return db.execute("SELECT count(*) FROM runs").fetchone()[0]
    except sqlite3.Error:  # the store is still being created
        return 0


tmp = tempfile.mkdtemp(prefix="sylvarock-mpi-")
try:
    one, many = os.path.join(tmp, "one"), os.path.join(tmp, "many")
    if mode == "same":
        args = design(runs=6, baseline=60) + ["--model", "both", "--lumped-runs", "150", "--lumped-baseline-runs", "200"]
        run([exe] + args + ["--threads", "1", "--out", one])
        run(mpi(3) + args + ["--threads", "2", "--out", many])
        compare(one, many)
    elif mode == "resume":
        args = design(runs=40, baseline=2000)
        run([exe] + args + ["--threads", "1", "--out", one])
        total = 2000 + 2 * 2 * 2 * 40
        job = subprocess.Popen(mpi(3) + args + ["--threads", "1", "--out", many], stdout=subprocess.DEVNULL,
                               stderr=subprocess.PIPE, text=True)
        deadline = time.time() + 300
        while logged(many) < total // 5 and job.poll() is None and time.time() < deadline:
            time.sleep(0.05)
        pids = rank_pids(job)
        if job.poll() is not None or 1 not in pids:
            sys.exit(f"FAILED: the job ended (or rank 1 was not found) before it could be killed: {job.poll()} {pids}")
        os.kill(pids[1], signal.SIGKILL)  # a rank dies: mpirun ends the others
        job.wait(timeout=120)
        cut = logged(many)
        print(f"rank 1 killed with {cut} of {total} runs stored; mpirun exit {job.returncode}")
        if job.returncode == 0 or cut >= total:
            sys.exit("FAILED: the kill did not interrupt the campaign")
        r = run(mpi(2) + args + ["--threads", "1", "--out", many, "--resume"])
        note = [l for l in r.stderr.splitlines() if "resuming" in l]
        print(note[0] if note else "(no resume note)")
        compare(one, many)
    elif mode == "simulate":
        forest = os.path.join(tmp, "forest.csv")
        run([exe, "generate", "--stems", os.path.join(PROJECT, "data/stands/MO1_stems.csv"), "--plots",
             os.path.join(PROJECT, "data/stands/MO1_plots.csv"), "--structure", "aggregated", "--extent", "130,0,630,200",
             "--seed", "3", "--out", forest])
        cases = {
            "lumped": ["simulate", "--scene", os.path.join(PROJECT, "data/scenes/no-forest.ini"), "--model", "lumped",
                       "--forest", forest, "--runs", "2000", "--seed", "5", "--no-figures"],
            "tree": ["simulate", "--scene", os.path.join(PROJECT, "data/scenes/single-tree.ini"), "--runs", "3",
                     "--trajectory", "--set", "block.eccentricity=0.3", "--seed", "5", "--no-figures"],
        }
        for name, args in cases.items():
            a, b = os.path.join(tmp, name + "-one"), os.path.join(tmp, name + "-mpi")
            run([exe] + args + ["--threads", "1", "--out", a])
            run(mpi(3) + args + ["--threads", "1", "--out", b])
            compare_outputs(a, b)
    else:
        sys.exit(f"unknown mode {mode}")
finally:
    shutil.rmtree(tmp, ignore_errors=True)
