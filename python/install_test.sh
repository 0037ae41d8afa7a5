#!/bin/sh
# CTest python_install: `cmake --install` puts a package that /usr/bin/python3 imports, in a
# directory that is on its sys.path for the default prefix /usr/local, and the CLI in bin/.
# Usage: install_test.sh BUILD_DIR INSTALL_SUBDIR SCRATCH_DIR
set -eu
build=$1 subdir=$2 scratch=$3
rm -rf "$scratch"
cmake --install "$build" --prefix "$scratch" >/dev/null
"$scratch/bin/hullinspect" --version >/dev/null
cd /
PYTHONPATH="$scratch/$subdir" /usr/bin/python3 -c "
import hullinspect
assert hullinspect.__file__.startswith('$scratch/'), hullinspect.__file__
r = hullinspect.run_mission(seed=3)
assert r.complete and r.T_m > 0, r
"
/usr/bin/python3 -c "
import sys
assert '/usr/local/$subdir' in sys.path, ('/usr/local/$subdir is not on sys.path', sys.path)
"
rm -rf "$scratch"
echo "installed into $subdir: imports, and /usr/local/$subdir is on sys.path; bin/hullinspect runs"
