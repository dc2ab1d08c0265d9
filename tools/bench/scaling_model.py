#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Scaling model of a parallel tribex run (issue 25): time and memory per rank per step against the
rank count, for the replicated set-up and contact (before issue 25) and for the distributed design as built,
from measured inputs (docs/measurements/2026-11-26-bench-scaling-model.md lists them and their
commands). A model, not a measurement: it says where each design stops scaling and why.

Per rank and step (N ranks, E elements, S slave nodes in the contact zone, K nodes per cube side):
  elements      E/N x c_el                                   (c_el: ns per element per step)
  halo          6 neighbours x (latency + 24 B x (K / N^(1/3))^2 / bandwidth)   (cube subdomains)
  contact       replicated: S x c_node on every rank; distributed (owner computes, the frictionless
                and adhesive laws): its share S / min(N, N_c) x c_node (N_c the ranks the
                contact-weighted partition spreads the zone over, S / 16 by default); with --tangential
                (junction, Coulomb) the share grown by one node on every side (the contact shares read
                the gaps around); with --redundant (mortar) every slave node of the region: the share as
                a square patch grown by the region's reach h (node spacings) on every side,
                (sqrt(share) + 2 h)^2, at most S
  surface data  replicated: MPI_Allgatherv of 72 B x all surface nodes to every rank
                (recursive doubling: log2 N latencies + the whole surface over the link);
                distributed: the ghost rows of the region's band (both surfaces) from <= 8 neighbours:
                owner computes 24 B a row (positions; the frictionless and adhesive laws read nothing
                else); --tangential 72 B (positions, velocities, forces); --redundant 72 B. Sparse rows
                (only those a rank's pairs touch: the ring of nodes around its share, both surfaces):
                the forces sent back, 32 B a row (its list position and 3 values), and --tangential the
                pairs' completion, 40 B each way, in three more exchanges
  reductions    the stable step every 10 steps: one MPI_Allreduce, log2 N latencies
Memory per rank: replicated set-up holds the whole model on every rank (M_1, measured);
distributed: (M_1 - M_0) / N + M_0, M_0 the part that does not divide (code, libraries, MPI buffers).

The set-up and output stages (issue 57; distributed set-up `set-up = distributed`, results.h5 written
collectively, inputs measured 2026-11-29, docs/measurements/2026-11-29-output-memory.md):
  set-up        once: E/N x c_setup (generation, partition, the parts; c_setup in core time per element
                of a rank's part, the fewest-rank measurement: a lower bound, see the log)
  output step   every output: E/N x c_out (fields, block exchange, compression) + one MPI_Alltoallv
                (N latencies + b_out x E/N over the link) + b_out x E / the file system's aggregate
                bandwidth (the one term that does not divide: every byte reaches the disks)
  memory        the peak of a rank with results output on, set-up and output steps included:
                m_el x E/N + M_out (fitted to the counts at 4-128 ranks on 1 M and 4 M elements)
  largest model at G GB per rank: E = (G - M_out) / m_el x N, and at most 2^31 - 1 nodes and elements
                (mesh/mesh.hpp's indices and results.h5's connectivity are 32-bit)

usage: scaling_model.py [--elements E] [--slave-nodes S] [--slave-nodes-per-rank n] [--halo-nodes h]
                        [--redundant | --tangential]
                        [--ns-element C] [--ns-slave-node C]
                        [--serial-rss-mb M] [--surface-nodes NS] [--latency-us L] [--bandwidth-gbs B]
                        [--rank-memory-gb G] [--csv FILE]
                        [--setup-us-element C] [--output-us-element C] [--output-bytes-element B]
                        [--fs-gbs F] [--output-bytes-element-rank M] [--output-fixed-mb M0]
"""
import argparse
import csv
import math
import sys

RANKS = [1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024]
# The set-up and output stages' measured inputs (docs/measurements/2026-11-29-output-memory.md).
SETUP_US, OUTPUT_US, OUTPUT_B, OUTPUT_FIXED_MB = 16.6, 0.2, 1114.0, 98.0


def step_costs(n, a):
    """Seconds per step per rank of each part, and memory per rank (bytes), for both designs."""
    lat, bw = a.latency_us * 1e-6, a.bandwidth_gbs * 1e9
    elements = a.elements / n * a.ns_element * 1e-9
    side = round(a.elements ** (1 / 3)) + 1  # nodes per side of the cube block
    halo = 0.0 if n == 1 else min(6, 2 * math.ceil(math.log2(n))) * (lat + 24 * (side / n ** (1 / 3)) ** 2 / bw)
    reduce = 0.0 if n == 1 else math.ceil(math.log2(n)) * lat / 10
    contact_rep = a.slave_nodes * a.ns_slave_node * 1e-9
    gather = 0.0 if n == 1 else math.ceil(math.log2(n)) * lat + 72 * a.surface_nodes / bw
    # Distributed: the contact zone shared by at most n ranks (a contact-weighted partition), each
    # computing the slave nodes of its region (its share grown by the reach) and receiving the region's
    # ghost rows of both surfaces from at most 8 neighbours.
    share = a.slave_nodes / min(n, max(1.0, a.slave_nodes / a.slave_nodes_per_rank))
    region = a.slave_nodes if n == 1 else min(a.slave_nodes, (math.sqrt(share) + 2 * a.halo_nodes) ** 2)
    # The ring of nodes around a rank's share that its pairs touch (the rows of the sparse exchanges).
    ring = min(a.slave_nodes, (math.sqrt(share) + 2) ** 2) - share
    if a.redundant:  # every slave node of the region; rows of x, v, f; nothing sent back
        computed, row, sparse_row, rounds = region, 72, 0, 1
    elif a.tangential:  # own nodes and the ring around them (contact shares); rows of x, v, f; forces
        # back, and the pairs' completion (4 values each way), sparse: three more exchanges
        computed = share + (0 if n == 1 else ring)
        row, sparse_row, rounds = 72, 32 + 2 * 40, 3
    else:
        computed, row, sparse_row, rounds = share, 24, 32, 1
    contact_dist = computed * a.ns_slave_node * 1e-9
    ghosts = 0.0 if n == 1 else (rounds * min(8, n - 1) * lat + 2 * (region - share) * row / bw
                                 + 2 * ring * sparse_row / bw)
    mem_rep = a.serial_rss_mb * 1e6
    mem_dist = (a.serial_rss_mb - a.fixed_rss_mb) * 1e6 / n + a.fixed_rss_mb * 1e6
    rep = {"elements": elements, "halo": halo, "reductions": reduce, "contact": contact_rep, "surface": gather}
    dist = {"elements": elements, "halo": halo, "reductions": reduce, "contact": contact_dist, "surface": ghosts}
    return rep, dist, mem_rep, mem_dist


def stage_costs(n, a):
    """Set-up seconds (once), output seconds per output step and peak MB per rank with output on."""
    share = a.elements / n
    setup = share * a.setup_us_element * 1e-6
    exchange = 0.0 if n == 1 else n * a.latency_us * 1e-6 + a.output_bytes_element * share / (a.bandwidth_gbs * 1e9)
    disk = a.output_bytes_element * a.elements / (a.fs_gbs * 1e9)
    output = share * a.output_us_element * 1e-6 + exchange + disk
    memory = a.output_bytes_element_rank * share / 1e6 + a.output_fixed_mb
    return setup, output, disk, memory


def print_stages(a):
    """The set-up and output stages' table and the largest model that fits a rank with output on."""
    print(f"set-up and output stages: {a.setup_us_element:g} us/element set-up, {a.output_us_element:g} us/element "
          f"and {a.output_bytes_element:g} B/element per output, file system {a.fs_gbs:g} GB/s, "
          f"{a.output_bytes_element_rank:g} B/element + {a.output_fixed_mb:g} MB per rank with output on")
    print(f"{'ranks':>6} | {'set-up s':>9} {'output s/step':>13} {'of it disk':>10} {'RSS MB, output on':>17}")
    rows = []
    for n in RANKS:
        setup, output, disk, memory = stage_costs(n, a)
        rows.append({"ranks": n, "setup_s": setup, "output_s": output, "output_disk_s": disk, "output_rss_mb": memory})
        print(f"{n:>6} | {setup:>9.2f} {output:>13.3f} {disk:>10.3f} {memory:>17.0f}")
    cap = 2**31 - 1  # 32-bit node and element indices (mesh/mesh.hpp, results.h5's connectivity)
    per_rank = (a.rank_memory_gb * 1e3 - a.output_fixed_mb) * 1e6 / a.output_bytes_element_rank  # elements a rank holds
    print(f"largest model with results output on at {a.rank_memory_gb:g} GB per rank: {per_rank / 1e6:.2f} M elements "
          f"per rank; {per_rank * RANKS[-1] / 1e9:.2f} G elements at {RANKS[-1]} ranks by memory, but at most "
          f"{cap / 1e9:.2f} G (32-bit indices), reached from {math.ceil(cap / per_rank)} ranks")
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--elements", type=float, default=1_009_000, help="E (counts_indenter.i)")
    ap.add_argument("--slave-nodes", type=float, default=961, help="S: slave nodes in the contact zone")
    ap.add_argument("--slave-nodes-per-rank", type=float, default=16,
                    help="the fewest slave nodes a contact-weighted partition gives a contact rank")
    ap.add_argument("--halo-nodes", type=float, default=5.7,
                    help="h: the contact region's reach in slave-node spacings (counts_indenter.i, owner computes: "
                         "5.7 nm / 1 nm; a tangential law's redundant region about 4 hops of 3.6 nm)")
    ap.add_argument("--redundant", action="store_true",
                    help="mortar's redundant region (every slave node of the region computed)")
    ap.add_argument("--tangential", action="store_true",
                    help="owner computes for the tangential laws (junction, Coulomb): the ring of slave nodes around a "
                         "rank's own projected too, 72 B per ghost row and 112 B per ring row a step, three more exchanges")
    ap.add_argument("--surface-nodes", type=float, default=11_162, help="contact surface nodes (both surfaces)")
    ap.add_argument("--ns-element", type=float, default=85.0, help="c_el, ns per element per step")
    ap.add_argument("--ns-slave-node", type=float, default=340.0, help="c_node, ns per slave node per step")
    ap.add_argument("--serial-rss-mb", type=float, default=850.0, help="peak RSS of a rank holding the whole model, MB")
    ap.add_argument("--fixed-rss-mb", type=float, default=60.0, help="per-rank memory that does not divide, MB")
    ap.add_argument("--latency-us", type=float, default=1.5, help="message latency, us (InfiniBand class)")
    ap.add_argument("--bandwidth-gbs", type=float, default=12.0, help="link bandwidth per rank pair, GB/s")
    ap.add_argument("--rank-memory-gb", type=float, default=4.0, help="memory per rank of the cluster, GB")
    ap.add_argument("--setup-us-element", type=float, default=SETUP_US,
                    help="c_setup, core us per element of a rank's part for the distributed set-up")
    ap.add_argument("--output-us-element", type=float, default=OUTPUT_US,
                    help="c_out, core us per element of a rank's part per results.h5 output step")
    ap.add_argument("--output-bytes-element", type=float, default=96.0,
                    help="b_out, bytes written per element per output (displacement 24 B/node + stress 72 B, uncompressed)")
    ap.add_argument("--fs-gbs", type=float, default=5.0, help="the file system's aggregate write bandwidth, GB/s (assumed)")
    ap.add_argument("--output-bytes-element-rank", type=float, default=OUTPUT_B,
                    help="m_el, peak bytes per element of a rank's part with results output on")
    ap.add_argument("--output-fixed-mb", type=float, default=OUTPUT_FIXED_MB,
                    help="M_out, the peak per rank with output on that does not divide, MB")
    ap.add_argument("--csv", help="write the table as CSV (columns: see the header row)")
    a = ap.parse_args()
    rows = []
    t1 = None
    for n in RANKS:
        rep, dist, mem_rep, mem_dist = step_costs(n, a)
        t_rep, t_dist = sum(rep.values()), sum(dist.values())
        if t1 is None:
            t1 = t_rep
        rows.append({"ranks": n, "replicated_us": 1e6 * t_rep, "replicated_contact_us": 1e6 * (rep["contact"] + rep["surface"]),
                     "replicated_efficiency": t1 / (n * t_rep), "replicated_rss_mb": mem_rep / 1e6,
                     "distributed_us": 1e6 * t_dist, "distributed_contact_us": 1e6 * (dist["contact"] + dist["surface"]),
                     "distributed_efficiency": t1 / (n * t_dist), "distributed_rss_mb": mem_dist / 1e6})
    print(f"model: {a.elements:.0f} elements, {a.slave_nodes:.0f} slave nodes in contact, {a.ns_element:g} ns/element/step, "
          f"{a.ns_slave_node:g} ns/slave node/step, latency {a.latency_us:g} us, {a.bandwidth_gbs:g} GB/s")
    print(f"{'ranks':>6} | {'replicated us/step':>18} {'contact+gather':>14} {'eff':>6} {'RSS MB':>7} | "
          f"{'distributed us/step':>19} {'contact+ghosts':>14} {'eff':>6} {'RSS MB':>7}")
    for r in rows:
        print(f"{r['ranks']:>6} | {r['replicated_us']:>18.1f} {r['replicated_contact_us']:>14.1f} "
              f"{r['replicated_efficiency']:>6.1%} {r['replicated_rss_mb']:>7.0f} | {r['distributed_us']:>19.1f} "
              f"{r['distributed_contact_us']:>14.1f} {r['distributed_efficiency']:>6.1%} {r['distributed_rss_mb']:>7.0f}")
    # Where each design stops: efficiency below 50 %, and the largest model that fits a rank.
    for design in ("replicated", "distributed"):
        below = [r["ranks"] for r in rows if r[f"{design}_efficiency"] < 0.5]
        print(f"{design}: parallel efficiency below 50 % from {below[0]} ranks" if below else
              f"{design}: parallel efficiency at least 50 % up to {RANKS[-1]} ranks")
    per_element = a.serial_rss_mb * 1e6 / a.elements
    print(f"largest model that fits {a.rank_memory_gb:g} GB per rank: replicated "
          f"{a.rank_memory_gb * 1e9 / per_element / 1e6:.1f} M elements at any rank count; distributed "
          f"{(a.rank_memory_gb * 1e3 - a.fixed_rss_mb) * 1e6 / per_element * RANKS[-1] / 1e9:.1f} G elements at {RANKS[-1]} ranks")
    stages = print_stages(a)
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0]) + list(stages[0])[1:])
            w.writeheader()
            w.writerows({**r, **{k: v for k, v in st.items() if k != "ranks"}} for r, st in zip(rows, stages))
    return 0


if __name__ == "__main__":
    sys.exit(main())
