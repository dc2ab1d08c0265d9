#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Per-rank counts at several rank counts (issue 25 acceptance; tools/bench/README.md, "Counts per rank").

  rank_counts.py TRIBEX DECK OUT --ranks 1 4 8 16 [--run] [--termination "3 ps"]

With --run, runs DECK under mpiexec (oversubscribed) at each rank count into OUT/npN (skipping a
rank count whose summary.json is already there); then prints one line per run (steps, full
searches) and one markdown row per rank count from OUT/npN/summary.json "rank_counts": the largest
per-rank figure of each count (and the smallest where the spread matters), with the issue's memory
target 1.3 x (serial peak / N) + 100 MB. Counts, not times.

--termination TIME runs a copy of DECK (OUT/DECK's name) whose `termination time` line says TIME
instead: the per-step byte counts average over the steps, and the search steps move the whole ghost
band, so a run of a few steps carries more of it than a long one
(docs/measurements/2026-11-27-bench-rank-counts.md, "The acceptance's bytes line"). Exit 2 with one line on bad arguments, a deck without the line, or a run
that fails (its first error line).
"""
import argparse
import json
import os
import re
import subprocess
import sys

MB = 1e6
TERMINATION = re.compile(r"^(\s*termination time\s*=\s*)(.*?)(\s*(#.*)?)$", re.MULTILINE)
# The lines whose file names resolve against the deck's folder (docs/deck_reference.md): in the copy they
# become absolute, so the copy in OUT reads the same files.
FILE_NAME = re.compile(r"^(\s*(?:include\s+|(?:database name|file|summit file)\s*=\s*))(\S.*?)(\s*(#.*)?)$",
                       re.MULTILINE | re.IGNORECASE)


def fail(message):
    print(f"rank_counts.py: {message}", file=sys.stderr)
    sys.exit(2)


def run(tribex, deck, out, n):
    cmd = [tribex, "run", deck, "-o", out, "--quiet"]
    if n > 1:
        cmd = ["mpiexec", "-n", str(n), "--oversubscribe"] + (["--allow-run-as-root"] if os.geteuid() == 0 else []) + cmd
    env = dict(os.environ, OMPI_MCA_mpi_yield_when_idle="1", OMPI_MCA_hwloc_base_binding_policy="none")
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, env=env)
    except OSError as error:
        fail(f"{cmd[0]}: {error.strerror}; give the path of a tribex executable (and mpiexec on PATH for --ranks above 1)")
    if p.returncode != 0:
        first = ((p.stderr.strip() or p.stdout.strip()).splitlines() or ["no output"])[0]
        fail(f"{' '.join(cmd)}: exit {p.returncode}: {first}")


def deck_with_termination(deck, time, out):
    """A copy of DECK in OUT whose `termination time` is TIME (the deck's path if TIME is None)."""
    if time is None:
        return deck
    try:
        with open(deck) as f:
            text = f.read()
    except OSError as error:
        fail(f"{deck}: {error.strerror}; give the path of an input deck")
    text, count = TERMINATION.subn(lambda m: m.group(1) + time + m.group(3), text)
    if count != 1:
        fail(f"{deck}: {count} 'termination time' lines; --termination needs exactly one")
    folder = os.path.dirname(os.path.abspath(deck))
    text = FILE_NAME.sub(lambda m: m.group(1) + os.path.join(folder, m.group(2)) + m.group(3), text)
    os.makedirs(out, exist_ok=True)
    copy = os.path.join(out, os.path.basename(deck))
    with open(copy, "w") as f:
        f.write(text)
    return copy


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("tribex")
    ap.add_argument("deck")
    ap.add_argument("out")
    ap.add_argument("--ranks", type=int, nargs="+", default=[1, 4, 8, 16])
    ap.add_argument("--run", action="store_true")
    ap.add_argument("--termination", help="run a copy of DECK ending at this time (deck units, e.g. \"3 ps\")")
    a = ap.parse_args()
    if any(n < 1 for n in a.ranks):
        fail(f"--ranks {' '.join(map(str, a.ranks))}: rank counts must be 1 or more")
    if a.termination is not None and not a.run:
        fail(f"--termination {a.termination} changes the runs, and there are none without --run; add --run")
    deck = deck_with_termination(a.deck, a.termination, a.out) if a.run else a.deck
    rows = []
    for n in a.ranks:
        out = os.path.join(a.out, f"np{n}")
        if a.run and not os.path.exists(os.path.join(out, "summary.json")):
            run(a.tribex, deck, out, n)
        path = os.path.join(out, "summary.json")
        if os.path.exists(path):
            with open(path) as f:
                rows.append((n, json.load(f)))
    if not rows:
        fail(f"no summary.json under {a.out}/npN for --ranks {' '.join(map(str, a.ranks))}; add --run to run the deck")
    for n, s in rows:
        searches = max(r["searches"] for r in s["rank_counts"])
        print(f"{n} rank(s): {s['steps']} steps to {s['final_time']:g} s, at most {searches} full searches per rank")
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
