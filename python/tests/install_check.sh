#!/usr/bin/env bash
# The two ways a user installs the Python module, each into a fresh place outside the source and build trees,
# then imported from there by a python that does not see the build tree:
#   pip install --no-build-isolation .   into a venv (--system-site-packages: Debian's NumPy), reusing the
#                                        build tree given as $1 (FRICTIONVIZ_BUILD_DIR: no second compile)
#   cmake --install $1 --component python   into a prefix, then PYTHONPATH=<prefix>/<platlib>
# Usage: install_check.sh BUILD_DIR SOURCE_DIR PYTHON
set -euo pipefail
build=$(cd "$1" && pwd); src=$(cd "$2" && pwd); python=$3
work=$(mktemp -d "$build/python-install.XXXXXX")
trap 'rm -rf "$work"' EXIT
unset PYTHONPATH

# What the installed module must do: load from where it was installed, compute r_x of the rigid model against
# Eq. (10) at theta = 0 (2/pi asin(zeta) for zeta <= 1), a Dahl point with status ok, and render a PNG.
probe='
import os, sys, math
import frictionviz as fv
where = os.path.realpath(fv.__file__)
assert where.startswith(os.path.realpath(sys.argv[1])), where
r, _ = fv.rigid_ratio(0.5, 0)
assert abs(float(r) - 2 / math.pi * math.asin(0.5)) < 1e-12, r
res = fv.ratio(0.15, 90, 2, 1)
assert res.status == "ok", res.status
png = fv.render("fig5").data
assert png[:8] == b"\x89PNG\r\n\x1a\n", png[:8]
print("ok", where)
'

"$python" -m venv --system-site-packages "$work/venv"
(cd "$src" && FRICTIONVIZ_BUILD_DIR="$build" "$work/venv/bin/python" -m pip install --quiet --no-index \
   --no-build-isolation --disable-pip-version-check "$src")
(cd "$work" && "$work/venv/bin/python" -c "$probe" "$work/venv")

cmake --install "$build" --component python --prefix "$work/prefix" >/dev/null
init=$(find "$work/prefix" -path '*/frictionviz/__init__.py')
platlib=$(dirname "$(dirname "$init")")
case ${platlib#"$work/prefix/"} in
    lib/python3*/site-packages | lib/python3*/dist-packages) ;;
    *) echo "python_install: cmake --install put the package in $platlib, not the interpreter's layout" >&2; exit 1 ;;
esac
(cd "$work" && PYTHONPATH="$platlib" "$python" -c "$probe" "$work/prefix")
