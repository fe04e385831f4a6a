#!/usr/bin/env bash
# Installs what sylvarock needs on Debian 12 (run as root, or with sudo available).
set -euo pipefail
pkgs=(g++ cmake make libeigen3-dev libgsl-dev libcgal-dev libboost-program-options-dev libgtest-dev libsqlite3-dev nlohmann-json3-dev libgdal-dev gdal-bin gnuplot-nox python3 libopenmpi-dev openmpi-bin clang libclang-rt-14-dev)
missing=()
for p in "${pkgs[@]}"; do dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p"); done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO=sudo
  echo "installing: ${missing[*]}"
  $SUDO apt-get update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
fi
