#!/usr/bin/env bash
# Installs the build tree into a scratch prefix and builds tests/install/consumer against it.
set -euo pipefail
build_dir=$1
source_dir=$2
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cmake --install "$build_dir" --prefix "$scratch/prefix" > "$scratch/install.log"
cmake -S "$source_dir/tests/install/consumer" -B "$scratch/consumer" -G Ninja \
  -DCMAKE_PREFIX_PATH="$scratch/prefix" > "$scratch/configure.log"
cmake --build "$scratch/consumer" > "$scratch/build.log"
"$scratch/consumer/consumer"
test -x "$scratch/prefix/bin/ferrodyn"
test -x "$scratch/prefix/libexec/ferrodyn/ferrodyn"
test -f "$scratch/prefix/share/ferrodyn/ferroplot.py"
"$scratch/prefix/bin/ferrodyn" --version
