#!/usr/bin/env bash
# Installs the dependencies (Debian 12 packages), builds ferrodyn and runs the main job:
# the wheelset hunting scene (summary on the terminal, HDF5 + CSV in out/, plots in
# out/wheelset_hunting_plots/) and its eigenvalue critical-speed sweep.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build build -j "$(nproc 2>/dev/null || echo 2)" --target ferrodyn
scene=scenarios/scenes/wheelset_hunting.yaml
./build/bin/ferrodyn run "$scene"
./build/bin/ferrodyn eig "$scene"
