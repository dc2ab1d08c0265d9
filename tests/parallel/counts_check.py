#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""summary.json's rank_counts (issue 25, scope 3), checked against what the run must have done.

  counts_check.py TRIBEX DECK OUT --ranks N

runs DECK (a contact deck) on N ranks and checks, from OUT/summary.json:
  - one entry per rank, in rank order; elements sum to the model's; owned nodes sum to the model's
    nodes, held nodes at least that (shared nodes counted by every holder);
  - one rank: nodes and elements are the model's, nothing shared, no ghost face, 0 bytes exchanged;
  - several ranks: every rank sends and receives halo bytes, 24 B (3 doubles) per shared node and
    neighbour on 2 ranks, and the bytes sent over all ranks equal those received (halo and surface
    ghost rows); every rank sends and receives contact ghost rows; each contact face is owned by exactly
    one rank (sum of contact_faces - ghost_faces = the one-rank run's faces) and some are ghosts; no
    region holds more faces or evaluates more pairs than the one-rank run, and all ranks together
    evaluate at least its pairs;
  - contact (one interaction pass): one evaluation per step plus the initial one, each a full search
    or a reuse of the candidates, plus the set-up search; pairs evaluated > 0; every rank searches at
    the same steps;
  - peak RSS > 0 and at the close >= at the end of set-up;
  - contact_balance (the busiest rank's pairs over the even share, summed over the evaluations) between
    the figure the ranks' mean pairs give and N; 1 on one rank;
  - with --scaling (issue 25's acceptance on a large model with owner-computes contact, e.g.
    tools/bench/counts_indenter.i at 16 ranks): every rank's peak RSS at most 1.3 x the one-rank
    peak / N + 100 MB; the largest rank's contact pairs at most twice the even share (one-rank pairs
    / N), and all ranks together exactly the one-rank pairs (each slave node computed once).
"""
import argparse
import json
import os
import shutil
import sys

import parallel_check  # the launcher and run of the other parallel tests (same folder)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("tribex")
    ap.add_argument("deck")
    ap.add_argument("out")
    ap.add_argument("--ranks", type=int, default=2)
    ap.add_argument("--scaling", action="store_true", help="also the per-rank memory and pairs falling as 1/N")
    a = ap.parse_args()
    shutil.rmtree(a.out, ignore_errors=True)

    def run(out, ranks):
        parallel_check.run(a.tribex, a.deck, out, ranks)  # exits with the command's output on failure
        with open(os.path.join(out, "summary.json")) as f:
            return json.load(f)

    s = run(a.out, a.ranks)
    rc = s["rank_counts"]
    # Several ranks: the one-rank run of the same deck gives the whole surfaces' faces and pairs.
    whole = run(os.path.join(a.out, "np1"), 1)["rank_counts"][0] if a.ranks > 1 else rc[0]
    failures = []

    def expect(ok, what):
        if not ok:
            failures.append(what)

    n = a.ranks
    expect(s["ranks"] == n and len(rc) == n, f"{len(rc)} entries for {s['ranks']} ranks, expected {n}")
    expect([r["rank"] for r in rc] == list(range(n)), "entries not in rank order")
    expect(sum(r["elements"] for r in rc) == s["elements"], "elements do not sum to the model's")
    expect(sum(r["owned_nodes"] for r in rc) == s["nodes"], "owned nodes do not sum to the model's")
    expect(sum(r["nodes"] for r in rc) >= s["nodes"], "held nodes fewer than the model's")
    byte_keys = ["halo_bytes_sent_per_step", "halo_bytes_received_per_step", "contact_bytes_sent_per_step",
                 "contact_bytes_received_per_step"]
    if n == 1:
        r = rc[0]
        expect(r["nodes"] == s["nodes"] and r["elements"] == s["elements"], "serial: not the whole model")
        expect(r["shared_nodes"] == 0 and r["ghost_faces"] == 0, "serial: shared nodes or ghost faces")
        expect(all(r[k] == 0 for k in byte_keys), "serial: bytes exchanged")
    else:
        for r in rc:
            expect(r["shared_nodes"] > 0, f"rank {r['rank']}: no shared node")
            expect(all(r[k] > 0 for k in byte_keys), f"rank {r['rank']}: a byte count is 0")
            if n == 2:
                expect(r["halo_bytes_sent_per_step"] == 24 * r["shared_nodes"], f"rank {r['rank']}: halo bytes != 24 x shared")
        for kind in ("halo", "contact"):
            sent = sum(r[f"{kind}_bytes_sent_per_step"] for r in rc)
            received = sum(r[f"{kind}_bytes_received_per_step"] for r in rc)
            expect(sent == received, f"{kind}: {sent} B sent but {received} B received per step")
        faces = whole["contact_faces"]
        expect(sum(r["contact_faces"] - r["ghost_faces"] for r in rc) == faces, "contact faces not owned once each")
        expect(all(r["ghost_faces"] > 0 for r in rc), "a rank without ghost faces (surfaces not split)")
        # Distributed contact: a rank's region holds at most the whole surfaces, and every slave node's
        # candidates are evaluated on some rank (the regions overlap: at least the one-rank pairs in all).
        expect(all(r["contact_faces"] <= faces for r in rc), "a region with more faces than the surfaces")
        expect(all(r["contact_pairs_per_step"] <= whole["contact_pairs_per_step"] for r in rc),
               "a rank evaluating more pairs than the one-rank run")
        expect(sum(r["contact_pairs_per_step"] for r in rc) >= whole["contact_pairs_per_step"],
               "fewer pairs over all ranks than on one rank")
        if a.scaling:
            target = 1.3 * whole["peak_rss_bytes"] / n + 100e6
            for r in rc:
                expect(r["peak_rss_bytes"] <= target, f"rank {r['rank']}: peak RSS {r['peak_rss_bytes'] / 1e6:.1f} MB above "
                       f"1.3 x {whole['peak_rss_bytes'] / 1e6:.1f} / {n} + 100 = {target / 1e6:.1f} MB")
            even = whole["contact_pairs_per_step"] / n
            largest = max(r["contact_pairs_per_step"] for r in rc)
            expect(largest <= 2 * even, f"largest rank's contact pairs {largest} above twice the even share {even:.0f}")
            total = sum(r["contact_pairs_per_step"] for r in rc)
            expect(total == whole["contact_pairs_per_step"], f"{total} pairs over the ranks, one rank "
                   f"{whole['contact_pairs_per_step']} (a slave node computed twice or not at all)")
            print(f"scaling: peak RSS largest {max(r['peak_rss_bytes'] for r in rc) / 1e6:.1f} MB (target "
                  f"{target / 1e6:.1f}); contact pairs largest {largest} (even share {even:.0f}), all {total}")
    # contact_balance: the busiest rank's pairs over the even share, summed over the evaluations. Summing
    # the per-step maximum gives at least the maximum of the ranks' sums: at least the mean-based figure
    # from contact_pairs_per_step, at most n; exactly 1 on one rank.
    mean_based = max(r["contact_pairs_per_step"] for r in rc) * n / sum(r["contact_pairs_per_step"] for r in rc)
    balance = s["contact_balance"]
    print(f"contact_balance {balance:.4f} (from the mean pairs per rank {mean_based:.4f})")
    expect(mean_based * (1 - 1e-12) <= balance <= n * (1 + 1e-12), f"contact_balance {balance} outside "
           f"[{mean_based}, {n}]")
    expect(n > 1 or balance == 1.0, f"one rank: contact_balance {balance}, not 1")
    steps_run = s["steps"] - s["first_step"]
    for r in rc:
        expect(r["contact_evaluations"] == steps_run + 1, f"rank {r['rank']}: {r['contact_evaluations']} contact "
               f"evaluations for {steps_run} steps")
        expect(r["contact_pairs_per_step"] > 0 and r["searches"] >= 1, f"rank {r['rank']}: no contact work")
        # One pass: each evaluation either searched or kept the candidates; plus the set-up search.
        expect(r["searches"] + r["search_reuses"] == r["contact_evaluations"] + 1, f"rank {r['rank']}: searches + reuses "
               f"!= evaluations + 1")
        expect(r["searches"] == rc[0]["searches"], "searches differ between ranks (the decision is global)")
        expect(0 < r["peak_rss_setup_bytes"] <= r["peak_rss_bytes"], f"rank {r['rank']}: peak RSS")
        expect(0 <= r["exchange_peers"] <= n - 1, f"rank {r['rank']}: {r['exchange_peers']} exchange peers of {n} ranks")
    for r in rc:
        print(json.dumps(r))
    if failures:
        sys.exit("FAIL:\n  " + "\n  ".join(failures))
    print(f"{n} rank(s): rank_counts consistent with the model ({s['elements']} elements, {s['nodes']} nodes)")
    print("PASS")


if __name__ == "__main__":
    main()
