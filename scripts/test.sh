#!/usr/bin/env bash
# The whole test suite: Release build + all tests (validation tests in their short form), then the
# parsers', stores', contact laws' and stem laws' tests again under -fsanitize=address,undefined, and
# a short fuzz run of every parser (clang's libFuzzer, also under ASan and UBSan).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
jobs=$(nproc)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$jobs"
(cd build && ctest --output-on-failure -j"$jobs")
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DSYLVAROCK_SANITIZE=ON -DSYLVAROCK_BUILD_BENCH=OFF
cmake --build build-asan -j"$jobs"
# Test names follow the convention <Thing>Parser / <Thing>Reader / <Thing>Store / Contact<Law> (see
# tests/README.md); the stem's laws (BendingLaw, ConnectionBeam) are contact-law-like small types and
# run here too, and the assessment's resume tests exercise the store end to end.
(cd build-asan && ctest --output-on-failure -j"$jobs" -R '^Contact|^ConnectionBeam|^BendingLaw|Parser|Reader|Store|^AssessResume')
scripts/fuzz.sh 20000
