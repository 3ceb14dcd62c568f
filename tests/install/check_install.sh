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
test -x "$scratch/prefix/libexec/ferrodyn/ferrodyn-program"
test -f "$scratch/prefix/share/ferrodyn/ferroplot.py"
"$scratch/prefix/bin/ferrodyn" --version
# The Python module, when built: installed under the prefix at FERRO_PYTHON_INSTALL_DIR and
# importable from there.
if grep -q '^FERRO_BUILD_PYTHON:BOOL=ON' "$build_dir/CMakeCache.txt"; then
  pydir=$(sed -n 's/^FERRO_PYTHON_INSTALL_DIR:STRING=//p' "$build_dir/CMakeCache.txt")
  python=$(sed -n 's/^Python3_EXECUTABLE:FILEPATH=//p' "$build_dir/CMakeCache.txt")
  (cd "$scratch" && PYTHONPATH="$scratch/prefix/$pydir" "$python" -c \
    "import ferrodyn; assert ferrodyn.__file__.startswith('$scratch/prefix'); print('ferrodyn', ferrodyn.__version__)")
fi
