#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""CTest (verify_coated_decks): the committed decks are make_decks.py's output, and the mesh-convergence decks
of case 1 refine the coating with the mesh (issue 52, README.md "What tilts the FE's f": with 6 layers at every
element size the study's refinement left the coating's thickness unresolved and the penalty per area grew as
1/h^2, and f at small loads did not converge).

  /usr/bin/python3 verification/coated/check_decks.py      # exit 0: both hold; 1: a difference, printed
"""
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_decks import HERE, RUNS, write  # noqa: E402

CONVERGENCE = ("case1_h0.5", "case1", "case1_h0.3", "case1_h0.2")
RATIO_SPREAD = 0.25  # layer thickness / h may differ from the production deck's by this fraction (rounding to whole layers)


def stale_decks():
    """Names of the runs whose committed deck differs from what make_decks.py writes now."""
    out = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, run in RUNS.items():
            write(name, run, tmp)
            committed = os.path.join(HERE, "decks", name + ".i")
            if not os.path.exists(committed) or open(committed).read() != open(os.path.join(tmp, name + ".i")).read():
                out.append(name)
    return out


def layer_ratio(name):
    """Coating layer thickness over the element size at the contact, read from the committed deck."""
    text = open(os.path.join(HERE, "decks", name + ".i")).read()
    thickness = float(re.search(r"coating thickness = ([0-9.]+) nm", text).group(1))
    layers = int(re.search(r"coating layers = (\d+)", text).group(1))
    h = float(re.search(r"element size = ([0-9.]+) nm", text).group(1))
    return thickness / layers / h


def main():
    fails = [f"decks/{n}.i is not make_decks.py's output (run /usr/bin/python3 verification/coated/make_decks.py)"
             for n in stale_decks()]
    base = layer_ratio("case1")
    for name in CONVERGENCE:
        r = layer_ratio(name)
        print(f"{name}: coating layer thickness / element size = {r:.3f} (case1: {base:.3f})")
        if abs(r / base - 1) > RATIO_SPREAD:
            fails.append(f"{name}: the coating's layers are {r:.2f} h thick against {base:.2f} h at 0.4 nm: "
                         "the mesh study must refine the coating with the mesh")
    for f in fails:
        print("FAIL: " + f)
    print("PASS" if not fails else f"{len(fails)} failure(s)")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
