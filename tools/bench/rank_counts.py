#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Per-rank counts at several rank counts (issue 25 acceptance; tools/bench/README.md, "Counts per rank").

  rank_counts.py TRIBEX DECK OUT --ranks 1 4 8 16 [--run]

With --run, runs DECK under mpiexec (oversubscribed) at each rank count into OUT/npN (skipping a
rank count whose summary.json is already there); then prints one markdown row per rank count from
OUT/npN/summary.json "rank_counts": the largest per-rank figure of each count (and the smallest
where the spread matters), with the issue's memory target 1.3 x (serial peak / N) + 100 MB.
Counts, not times. Watch memory: today every rank builds the whole model during set-up.
"""
import argparse
import json
import os
import subprocess
import sys

MB = 1e6


def run(tribex, deck, out, n):
    cmd = [tribex, "run", deck, "-o", out, "--quiet"]
    if n > 1:
        cmd = ["mpiexec", "-n", str(n), "--oversubscribe"] + (["--allow-run-as-root"] if os.geteuid() == 0 else []) + cmd
    env = dict(os.environ, OMPI_MCA_mpi_yield_when_idle="1", OMPI_MCA_hwloc_base_binding_policy="none")
    p = subprocess.run(cmd, capture_output=True, text=True, env=env)
    if p.returncode != 0:
        sys.exit(f"{' '.join(cmd)} exited {p.returncode}\n{p.stdout}\n{p.stderr}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("tribex")
    ap.add_argument("deck")
    ap.add_argument("out")
    ap.add_argument("--ranks", type=int, nargs="+", default=[1, 4, 8, 16])
    ap.add_argument("--run", action="store_true")
    a = ap.parse_args()
    rows = []
    for n in a.ranks:
        out = os.path.join(a.out, f"np{n}")
        if a.run and not os.path.exists(os.path.join(out, "summary.json")):
            run(a.tribex, a.deck, out, n)
        path = os.path.join(out, "summary.json")
        if os.path.exists(path):
            with open(path) as f:
                rows.append((n, json.load(f)))
    if not rows:
        sys.exit("no summary.json found")
    serial = next((s for n, s in rows if n == 1), None)
    serial_rss = max(r["peak_rss_bytes"] for r in serial["rank_counts"]) if serial else None
    print("| ranks | elements per rank (max) | nodes per rank (max) | ghost faces (max) | peak RSS set-up, max (MB) "
          "| peak RSS, max (MB) | target 1.3 x serial/N + 100 MB | halo B/step (max sent) | contact B/step (max sent + received) "
          "| contact faces per rank (min-max) | contact pairs/step per rank (min-max) | contact pairs/step, all ranks | full searches per rank |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for n, s in rows:
        rc = s["rank_counts"]
        big = lambda k: max(r[k] for r in rc)  # noqa: E731
        target = f"{(1.3 * serial_rss / n + 100 * MB) / MB:.0f}" if serial_rss else "-"
        contact = max(r["contact_bytes_sent_per_step"] + r["contact_bytes_received_per_step"] for r in rc)
        pairs = sorted({r["contact_pairs_per_step"] for r in rc})
        pairs_text = f"{pairs[0]:.0f}" if len(pairs) == 1 else f"{pairs[0]:.0f}-{pairs[-1]:.0f}"
        faces = [r["contact_faces"] for r in rc]
        faces_text = f"{min(faces)}-{max(faces)}"
        pairs_total = sum(r["contact_pairs_per_step"] for r in rc)
        print(f"| {n} | {big('elements')} | {big('nodes')} | {big('ghost_faces')} | {big('peak_rss_setup_bytes') / MB:.0f} "
              f"| {big('peak_rss_bytes') / MB:.0f} | {target} | {big('halo_bytes_sent_per_step'):.0f} | {contact:.0f} "
              f"| {faces_text} | {pairs_text} | {pairs_total:.0f} | {big('searches')} |")


if __name__ == "__main__":
    main()
