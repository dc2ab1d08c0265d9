#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Rank 0's set-up memory and the partition's wall time by `begin decomposition` method (issue 57 scope 1;
tools/bench/README.md "Partition by all the ranks").

  partition_methods.py TRIBEX DECK OUT --ranks 4 16 --methods metis ptscotch distributed [--results h5|both]

Method `distributed` is `method = ptscotch` with `set-up = distributed` (issue 57 scope 2: every rank
generates its slab of a generated mesh; its partition time is that of the whole distributed set-up of the
mesh: slabs, dual graph, PT-Scotch, the elements' exchange, the parts and their nodes' holders).

Runs a copy of DECK (OUT/METHOD/deck.i, with a `begin decomposition` block after its `use finite element
model` line) under mpiexec (oversubscribed) at each rank count into OUT/METHOD/npN, skipping a run whose
summary.json is already there, then prints one markdown row per run: rank 0's peak RSS at the end of
set-up, the largest of the other ranks', the partition's wall time on rank 0 and the nodes on partition
boundaries (both from the log's `parallel:` line), the elements per rank. Times are one run each on a
shared machine; the RSS is a count. Exit 2 with one line on bad arguments or a run that fails.

--results h5|both (issue 57's counts "with results output on"): the copy also writes a results output
(displacement and stress, every step; `format = both` adds results.exo) into OUT/METHOD_results-FORMAT, and the
rows gain rank 0's and the other ranks' peak RSS over the whole run (summary.json `peak_rss_bytes`), which
then includes the output steps.
"""
import argparse
import json
import os
import re
import subprocess
import sys

MB = 1e6
PARTITION = re.compile(r"(\d+)-(\d+) elements per rank; (\d+) nodes on partition boundaries; partitioned in (\S+) s")


def fail(message):
    print(f"partition_methods.py: {message}", file=sys.stderr)
    sys.exit(2)


def results_block(results):
    """A results output every step (the first output step is then inside the 5-step run), or none."""
    if not results:
        return []
    return ["      begin results output fields", "        step increment = 1",
            "        nodal variables = displacement", "        element variables = stress",
            f"        format = {'xdmf' if results == 'h5' else 'both'}", "      end results output fields"]


def deck_with_method(deck, method, out, results=None):
    """DECK with `begin decomposition` / `method = METHOD` (and a results output) in its region, written to
    OUT/deck.i."""
    try:
        with open(deck) as f:
            lines = f.read().split("\n")
    except OSError as error:
        fail(f"{deck}: {error.strerror}")
    at = next((i for i, line in enumerate(lines) if line.strip().startswith("use finite element model")), None)
    if at is None:
        fail(f"{deck}: no 'use finite element model' line to put the decomposition block after")
    # "distributed": PT-Scotch with `set-up = distributed` (every rank generates its slab, issue 57 scope 2).
    block = ["      begin decomposition", f"        method = {'ptscotch' if method == 'distributed' else method}",
             *(["        set-up = distributed"] if method == "distributed" else []), "      end decomposition",
             *results_block(results)]
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, "deck.i")
    with open(path, "w") as f:
        f.write("\n".join(lines[:at + 1] + block + lines[at + 1:]))
    return path


def run(tribex, deck, out, n):
    cmd = ["mpiexec", "-n", str(n), "--oversubscribe"] + (["--allow-run-as-root"] if os.geteuid() == 0 else [])
    cmd += [tribex, "run", deck, "-o", out, "--quiet"]
    env = dict(os.environ, OMPI_MCA_mpi_yield_when_idle="1", OMPI_MCA_hwloc_base_binding_policy="none")
    p = subprocess.run(cmd, capture_output=True, text=True, env=env)
    if p.returncode != 0:
        first = ((p.stderr.strip() or p.stdout.strip()).splitlines() or ["no output"])[0]
        fail(f"{' '.join(cmd)}: exit {p.returncode}: {first}")


def row(method, n, out, results=None):
    with open(os.path.join(out, "summary.json")) as f:
        counts = json.load(f)["rank_counts"]
    with open(os.path.join(out, "log.txt")) as f:
        line = next((line for line in f if line.startswith("parallel: ")), "")
    m = PARTITION.search(line)
    if not m:
        fail(f"{out}/log.txt: no partition line with its time")
    others = max((r["peak_rss_setup_bytes"] for r in counts[1:]), default=0)
    text = (f"| {method} | {n} | {counts[0]['peak_rss_setup_bytes'] / MB:.0f} | {others / MB:.0f} | {m.group(4)} "
            f"| {int(m.group(3)):,} | {int(m.group(1)):,}-{int(m.group(2)):,} |")
    if results:
        whole = max((r["peak_rss_bytes"] for r in counts[1:]), default=0)
        text += f" {counts[0]['peak_rss_bytes'] / MB:.0f} | {whole / MB:.0f} |"
    return text


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("tribex")
    ap.add_argument("deck")
    ap.add_argument("out")
    ap.add_argument("--ranks", type=int, nargs="+", default=[4, 16])
    ap.add_argument("--methods", nargs="+", default=["metis", "ptscotch"],
                    choices=["metis", "ptscotch", "rcb", "distributed"])
    ap.add_argument("--results", choices=["h5", "both"], default=None,
                    help="write results every step (h5: results.h5; both: and results.exo)")
    a = ap.parse_args()
    if any(n < 2 for n in a.ranks):
        fail("--ranks: 2 or more (one rank does not partition)")
    rows = []
    for n in a.ranks:
        for method in a.methods:
            out = os.path.join(a.out, method + (f"_results-{a.results}" if a.results else ""))
            run_out = os.path.join(out, f"np{n}")
            if not os.path.exists(os.path.join(run_out, "summary.json")):
                run(a.tribex, deck_with_method(a.deck, method, out, a.results), run_out, n)
            rows.append(row(method, n, run_out, a.results))
            print(rows[-1], flush=True)
    whole = " rank 0 peak RSS, whole run (MB) | other ranks, whole run (MB) |" if a.results else ""
    print("| method | ranks | rank 0 peak RSS, set-up (MB) | other ranks, max (MB) | partition wall time, rank 0 (s) "
          "| nodes on partition boundaries | elements per rank |" + whole)
    print("|---|---|---|---|---|---|---|" + ("---|---|" if a.results else ""))
    print("\n".join(rows))


if __name__ == "__main__":
    main()
