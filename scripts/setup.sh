#!/usr/bin/env bash
# Fresh Debian 12 machine -> dependencies installed, sylvarock built, the example job run.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
scripts/example.sh build/apps/sylvarock
