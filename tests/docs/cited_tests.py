#!/usr/bin/env python3
"""Every test the docs and the README name (`Suite.TestName`, or `Suite.Prefix...` for the tests that
start so) exists: a renamed test leaves its evidence unfindable (`ctest -R` on the old name runs
nothing). Names of suites that no test binary has are not test names (e.g. `Stem.cpp`) and are left.

    cited_tests.py SOURCE_DIR TEST_BINARY...    (exit 1 and each stale name with its file and line)"""
import glob, os, re, subprocess, sys

root, binaries = sys.argv[1], sys.argv[2:]
known = set()
for binary in binaries:
    suite = None
    listing = subprocess.run([binary, "--gtest_list_tests"], capture_output=True, text=True, check=True).stdout
    for line in listing.splitlines():
        if not line.startswith(" "):
            suite = line.strip().rstrip(".")
        else:
            known.add(f"{suite}.{line.split()[0]}")
suites = {name.split(".")[0] for name in known}

cited = re.compile(r"\b([A-Z][A-Za-z0-9]+)\.([A-Z][A-Za-z0-9_]+)(\.\.\.|…)?")
stale = []
pages = sorted(glob.glob(os.path.join(root, "docs", "*.md"))) + [os.path.join(root, "README.md")]
for page in pages:
    with open(page, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            for m in cited.finditer(line):
                suite, name, prefix = m.group(1), m.group(0).rstrip(".…"), m.group(3)
                if suite not in suites:
                    continue
                found = any(k.startswith(name) for k in known) if prefix else name in known
                if not found:
                    stale.append(f"{os.path.relpath(page, root)}:{number}: {m.group(0)} names no test")
for s in stale:
    print(s)
print(f"{len(known)} tests; {len(stale)} stale names in {len(pages)} pages")
sys.exit(1 if stale else 0)
