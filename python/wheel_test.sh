#!/bin/sh
# CTest python_wheel (label wheel): the package builds offline as a wheel with Debian's python3
# and pip, installs into a fresh venv (--system-site-packages, for Debian's numpy and pandas), and
# works there away from the checkout: the module imports from the venv, runs a mission with a
# trace and reads the trace's DataFrames, and the `hullinspect` command runs. Then the other way,
# `pip install .`, into a second venv. HULLINSPECT_BUILD_DIR (default: BUILD_DIR) is the CMake
# build the package's backend reuses, so only what changed is compiled.
# Usage: wheel_test.sh SOURCE_DIR BUILD_DIR SCRATCH_DIR
set -eu
src=$1 build=$2 scratch=$3
export HULLINSPECT_BUILD_DIR="${HULLINSPECT_BUILD_DIR:-$build}"
export HULLINSPECT_JOBS="${HULLINSPECT_JOBS:-2}"
version=$(sed -n 's/^project(hullinspect VERSION \([0-9.]*\).*/\1/p' "$src/CMakeLists.txt")
rm -rf "$scratch"
mkdir -p "$scratch"
cd "$scratch"

/usr/bin/python3 -m venv --system-site-packages venv
venv/bin/pip wheel --quiet --no-build-isolation --no-deps --no-index -w dist "$src"
ls dist/hullinspect-"$version"-cp3*-linux_*.whl >/dev/null
venv/bin/pip install --quiet --no-index --no-deps dist/hullinspect-*.whl

check() {  # VENV: the installed package works from a directory outside the checkout
  "$1/bin/python" - "$scratch/$1" "$version" <<'PY'
import sys
import hullinspect
venv, version = sys.argv[1], sys.argv[2]
assert hullinspect.__file__.startswith(venv + "/"), hullinspect.__file__
assert hullinspect.__version__ == version, (hullinspect.__version__, version)
r = hullinspect.run_mission(algorithm="part-tsp", uavs=3, seed=3, trace="t.json")
trace = hullinspect.read_trace("t.json")
assert r.complete and len(trace.uavs) == 3 * (r.counters["steps"] + 1), (r, len(trace.uavs))
assert {"t", "k", "x", "y", "z", "mode"} <= set(trace.uavs.columns)
assert trace.map_changes["value"].isin([1, 2, 3]).all()
print("ok", hullinspect.__version__, len(trace.uavs), "UAV rows")
PY
  "$1/bin/hullinspect" --version | grep -q "$version"
  "$1/bin/hullinspect" run -a part-tsp -n 3 --seed 3 --json | grep -q '"complete":true'
}
check venv

/usr/bin/python3 -m venv --system-site-packages venv2
venv2/bin/pip install --quiet --no-build-isolation --no-deps --no-index "$src"
check venv2
cd /
rm -rf "$scratch"
echo "wheel and pip install: both venvs import, trace and run the CLI"
