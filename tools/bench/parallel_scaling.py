#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Parallel scaling of `tribex run` (tools/bench/README.md "Parallel runs"), from summary.json:

  /usr/bin/python3 tools/bench/parallel_scaling.py build/bin/tribex OUT [--strong-n 60] [--weak-n 40]
      [--hertz verification/hertz/hertz_coarse.i --hertz-time 60ps] [--repeat 3]

strong: the scaling_block.i block of strong-n^3 elements on 1 and 2 ranks; weak: weak-n^3 elements
per rank on 1, 2, 4 ranks (4 ranks oversubscribe a 2-core machine); hertz: the Hertz deck cut to
--hertz-time on 1 and 2 ranks. Prints loop time (best of --repeat), efficiency and rank 0's
communication share of the loop.
"""
import argparse
import json
import os
import re
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))


def run(tribex, deck, out, ranks):
    cmd = [tribex, "run", deck, "-o", out, "--quiet"]
    if ranks > 1:
        cmd = ["mpiexec", "-n", str(ranks), "--oversubscribe"] + (["--allow-run-as-root"] if os.geteuid() == 0 else []) + cmd
    env = dict(os.environ, OMPI_MCA_mpi_yield_when_idle="1", OMPI_MCA_hwloc_base_binding_policy="none")
    subprocess.run(cmd, check=True, env=env, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def best(tribex, deck, out, ranks, repeat):
    runs = [run(tribex, deck, f"{out}_r{k}", ranks) for k in range(repeat)]
    return min(runs, key=lambda s: s["loop_time_s"])


def block_deck(out, nx, ny, nz):
    text = open(os.path.join(HERE, "scaling_block.i")).read()
    text = text.replace("size = 60 60 60 nm", f"size = {nx} {ny} {nz} nm").replace("intervals = 60 60 60", f"intervals = {nx} {ny} {nz}")
    path = os.path.join(out, f"block_{nx}x{ny}x{nz}.i")
    with open(path, "w") as f:
        f.write(text)
    return path


def row(label, ranks, s, base, weak):
    t = s["loop_time_s"]
    eff = base / t if weak else base / (ranks * t)
    comm = s.get("communication_time_s", 0.0)
    print(f"| {label} | {ranks} | {s['elements']} | {s['steps']} | {t:.3f} | {s['ns_per_element_step']:.1f} | "
          f"{100 * eff:.0f} % | {100 * comm / t if t > 0 else 0:.1f} % |")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("tribex")
    ap.add_argument("out")
    ap.add_argument("--strong-n", type=int, default=60)
    ap.add_argument("--weak-n", type=int, default=40)
    ap.add_argument("--hertz", default="")
    ap.add_argument("--hertz-time", default="60 ps")
    ap.add_argument("--repeat", type=int, default=3)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    print("| case | ranks | elements | steps | loop s (best) | ns/element/step | efficiency | communication |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- |")
    n = a.strong_n
    deck = block_deck(a.out, n, n, n)
    s1 = best(a.tribex, deck, os.path.join(a.out, "strong1"), 1, a.repeat)
    row(f"strong, block {n}^3", 1, s1, s1["loop_time_s"], False)
    s2 = best(a.tribex, deck, os.path.join(a.out, "strong2"), 2, a.repeat)
    row(f"strong, block {n}^3", 2, s2, s1["loop_time_s"], False)
    if a.hertz:
        text = open(a.hertz).read()
        text = re.sub(r"termination time = [^\n]*", f"termination time = {a.hertz_time}", text)
        hdeck = os.path.join(a.out, "hertz_short.i")
        with open(hdeck, "w") as f:
            f.write(text)
        h1 = best(a.tribex, hdeck, os.path.join(a.out, "hertz1"), 1, a.repeat)
        row(f"strong, Hertz to {a.hertz_time}", 1, h1, h1["loop_time_s"], False)
        h2 = best(a.tribex, hdeck, os.path.join(a.out, "hertz2"), 2, a.repeat)
        row(f"strong, Hertz to {a.hertz_time}", 2, h2, h1["loop_time_s"], False)
    w = a.weak_n
    base = None
    for ranks, dims in ((1, (w, w, w)), (2, (w, w, 2 * w)), (4, (w, 2 * w, 2 * w))):
        s = best(a.tribex, block_deck(a.out, *dims), os.path.join(a.out, f"weak{ranks}"), ranks, a.repeat)
        base = base or s["loop_time_s"]
        row(f"weak, {w}^3 per rank" + (" (oversubscribed)" if ranks > 2 else ""), ranks, s, base, True)


if __name__ == "__main__":
    main()
