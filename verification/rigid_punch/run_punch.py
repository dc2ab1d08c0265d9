#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""One rigid-punch run: the mesh (make_mesh.py --cells N --domain L) and a copy of rigid_punch.i.in as
OUT/rigid_punch.i, then
`tribex run OUT/rigid_punch.i -o OUT/run --set L=L`.

  /usr/bin/python3 run_punch.py --tribex build/bin/tribex --cells 8 --domain 10 --out punch_n8_L10
"""
import argparse
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import make_mesh  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--tribex", default=os.path.join(HERE, "..", "..", "build", "bin", "tribex"))
    ap.add_argument("--cells", type=int, required=True)
    ap.add_argument("--domain", type=float, required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    nodes, hexes, surfaces = make_mesh.build(a.cells, a.domain)
    make_mesh.write_msh(os.path.join(a.out, "punch.msh"), nodes, hexes, surfaces)
    shutil.copy(os.path.join(HERE, "rigid_punch.i.in"), os.path.join(a.out, "rigid_punch.i"))
    print(f"{a.out}: {len(nodes)} nodes, {len(hexes)} hex8", flush=True)
    cmd = [a.tribex, "run", os.path.join(a.out, "rigid_punch.i"), "-o", os.path.join(a.out, "run"), "--quiet",
           "--set", f"L={a.domain:g}"]
    sys.exit(subprocess.call(cmd))


if __name__ == "__main__":
    main()
