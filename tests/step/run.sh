#!/usr/bin/env bash
# Reads the STEP files of `weft nurbs` back in a real CAD kernel,
# OpenCASCADE (the OCP bindings of cadquery-ocp, from PyPI, in a virtual
# environment of their own under target/), and checks them against Weft's
# limit surface (check_occ.py): a regular torus cage, whose patches are
# exact, at isolation 1 and 2 on a ¼ grid of every face; and a cube, whose
# patches at its corners approximate, at their corners.
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build --quiet --bin weft
weft=target/debug/weft
venv=target/step-venv
if ! "$venv/bin/python" -c "import OCP, numpy" 2>/dev/null; then
  rm -rf "$venv"
  python3 -m venv "$venv"
  "$venv/bin/pip" install --quiet --disable-pip-version-check "cadquery-ocp-novtk==8.0.1.1.0" numpy
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# A torus of 8 x 12 quads, every vertex of valence 4.
python3 - "$work/torus.obj" <<'PY'
import math, sys
nu, nv = 8, 12
with open(sys.argv[1], "w") as out:
    for i in range(nu):
        for j in range(nv):
            a, b = 2 * math.pi * i / nu, 2 * math.pi * j / nv
            r = 1 + 0.35 * math.cos(b)
            out.write(f"v {r * math.cos(a)!r} {r * math.sin(a)!r} {0.35 * math.sin(b)!r}\n")
    for i in range(nu):
        for j in range(nv):
            ids = [((i + di) % nu) * nv + (j + dj) % nv + 1 for di, dj in [(0, 0), (1, 0), (1, 1), (0, 1)]]
            out.write("f " + " ".join(map(str, ids)) + "\n")
PY
for isolation in 1 2; do
  "$weft" nurbs "$work/torus.obj" "$work/torus.step" --isolation "$isolation" --naked-edges smooth >/dev/null
  # The ¼ grid of a face refined N levels is the vertices of level N + 2.
  "$weft" subdivide "$work/torus.obj" "$work/limit.obj" --levels $((isolation + 2)) --limit --naked-edges smooth 2>/dev/null
  "$venv/bin/python" tests/step/check_occ.py "$work/torus.step" "$work/limit.obj" $((96 * 4 ** isolation)) 5
done

"$weft" primitive box "$work/box.obj" --size 2 2>/dev/null
"$weft" nurbs "$work/box.obj" "$work/box.step" --isolation 2 --naked-edges smooth
"$weft" subdivide "$work/box.obj" "$work/limit.obj" --levels 2 --limit --naked-edges smooth 2>/dev/null
"$venv/bin/python" tests/step/check_occ.py "$work/box.step" "$work/limit.obj" 96 2
