#!/usr/bin/env bash
# Installs the dependencies (Debian 12 packages), builds ferrodyn and runs the main job:
# Manchester benchmark vehicle 1 (car body, two bogies, four wheelsets, S1002/UIC60 contact,
# chopaya creep forces) for 10 s at 200 km/h on straight track with ERRI high-level
# irregularities. The run prints a summary on the terminal and writes out/<scene>.h5 and plots of
# wheel forces, wheelset displacements and car-body accelerations in out/<scene>_plots/; run
# again, it replaces the outputs of the previous time (--overwrite). The Python module is built
# too (PYTHONPATH=build/python python3 -c "import ferrodyn").
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build build -j "$(nproc 2>/dev/null || echo 2)" --target ferrodyn ferro_python
./build/bin/ferrodyn run scenarios/scenes/manchester_straight_erri.yaml --overwrite
