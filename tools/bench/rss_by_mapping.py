#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Where a parallel run's resident memory is (issue 57, "with results output on"): runs a command (an
mpiexec of tribex), samples /proc/PID/status of every tribex process it starts every --interval seconds,
and whenever a rank's resident set reaches a new high (by --step MB) reads that rank's /proc/PID/smaps and
sums Rss and Pss by the kind of mapping. At the end it prints, per rank, the sampled peak beside the
kernel's high-water mark (VmHWM, what getrusage reports; a peak shorter than the interval is missed, and the
difference says how much), and the peak's resident set by kind:

  heap       [heap] (glibc's brk arena)
  anon>=1M   anonymous mappings of 1 MiB or more (glibc's mmap'd blocks, MPI and HDF5 buffers)
  anon<1M    smaller anonymous mappings (thread stacks' guard neighbours, malloc arenas' pieces)
  shm        /dev/shm and SysV shared memory (Open MPI's vader/sm segments; PSS divides them among sharers)
  libs       mapped files ending .so* (code and data of the libraries)
  files      other mapped files
  stack      [stack]
  other      the rest ([vdso], [vvar], ...)

  rss_by_mapping.py [--interval S] [--step MB] [--csv FILE] [--timeline FILE] -- mpiexec -n 16 build/bin/tribex run DECK -o OUT

and the number of shared-memory mappings with resident pages at that peak (Open MPI's vader BTL: the rank's
own segment plus one per peer it has received from through shared memory). RSS counts a shared page in
every process that touched it; PSS shares it among them (RSS / sharers). The
command's own exit status is returned; exit 2 with one line when no tribex process was seen.
"""
import argparse
import csv
import os
import subprocess
import sys
import time

KINDS = ["heap", "anon>=1M", "anon<1M", "shm", "libs", "files", "stack", "other"]


def kind_of(name, size_kb):
    if name == "[heap]":
        return "heap"
    if name == "[stack]":
        return "stack"
    if name == "" or name.startswith("[anon"):
        return "anon>=1M" if size_kb >= 1024 else "anon<1M"
    if name.startswith("/dev/shm") or name.startswith("/SYSV") or "vader" in name or "shared_mem" in name:
        return "shm"
    if name.startswith("/"):
        base = os.path.basename(name.split(" (deleted)")[0])
        return "libs" if ".so" in base else "files"
    return "other"


def smaps_by_kind(pid):
    """{kind: [rss_kb, pss_kb]}, the largest anonymous mappings (size, rss) of one process and the number of
    its shared-memory mappings with resident pages (Open MPI's vader: its own segment and every peer's it has
    read a message from)."""
    totals = {k: [0, 0] for k in KINDS}
    touched = 0
    big = []
    kind, size = "other", 0
    with open(f"/proc/{pid}/smaps") as f:
        for line in f:
            head = line.split(None, 1)[0]
            if "-" in head and not head.endswith(":"):  # a mapping's first line: range perms offset dev inode [name]
                parts = line.split(None, 5)
                lo, hi = (int(x, 16) for x in parts[0].split("-"))
                size = (hi - lo) // 1024
                name = parts[5].strip() if len(parts) > 5 else ""
                kind = kind_of(name, size)
            elif head == "Rss:":
                rss = int(line.split()[1])
                totals[kind][0] += rss
                if kind.startswith("anon") or kind == "shm":
                    big.append((rss, size, kind))
                touched += kind == "shm" and rss > 0
            elif head == "Pss:":
                totals[kind][1] += int(line.split()[1])
    big.sort(reverse=True)
    return totals, big[:4], touched


def status_kb(pid):
    vals = {}
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith(("VmRSS:", "VmHWM:")):
                vals[line.split(":")[0]] = int(line.split()[1])
    return vals.get("VmRSS", 0), vals.get("VmHWM", 0)


def rank_of(pid):
    with open(f"/proc/{pid}/environ", "rb") as f:
        for item in f.read().split(b"\0"):
            if item.startswith(b"OMPI_COMM_WORLD_RANK="):
                return int(item.split(b"=", 1)[1])
    return 0  # a serial run


def parent_of(pid):
    with open(f"/proc/{pid}/stat") as f:
        return int(f.read().rsplit(")", 1)[1].split()[1])  # the field after the state


def tribex_pids(root):
    """The tribex processes descended from `root` (other sessions' runs on the machine are not ours)."""
    pids = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/comm") as f:
                    if not f.read().startswith("tribex"):  # a copied binary (tribex_old) counts too
                        continue
                pid = int(entry)
                while pid > 1 and pid != root:
                    pid = parent_of(pid)
                if pid == root:
                    pids.append(int(entry))
            except (OSError, ValueError, IndexError):
                pass
    return pids


def sample(root, ranks, step_kb, t, timeline):
    """One pass over the tribex processes: new highs re-read smaps."""
    for pid in tribex_pids(root):
        try:
            rss, hwm = status_kb(pid)
            r = ranks.setdefault(pid, {"rank": rank_of(pid), "max": 0, "hwm": 0, "kinds": None, "big": [], "at": 0,
                                       "touched": 0})
            r["hwm"] = max(r["hwm"], hwm)
            if timeline is not None:
                timeline.append((round(t, 2), r["rank"], rss / 1000))
            if rss > r["max"] + step_kb or r["kinds"] is None:
                r["kinds"], r["big"], r["touched"] = smaps_by_kind(pid)
                r["max"], r["at"] = max(r["max"], sum(v[0] for v in r["kinds"].values())), t
        except (OSError, ValueError):
            pass  # the process ended between the listing and the read


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--interval", type=float, default=0.05, help="seconds between samples")
    ap.add_argument("--step", type=float, default=1.0, help="MB a rank's RSS must grow by to re-read its smaps")
    ap.add_argument("--csv", help="one row per rank: rank, hwm_mb, sampled_mb, then RSS and PSS MB of each kind")
    ap.add_argument("--timeline", help="every sample: time_s (since the start), rank, rss_mb")
    ap.add_argument("command", nargs=argparse.REMAINDER)
    a = ap.parse_args()
    cmd = a.command[1:] if a.command[:1] == ["--"] else a.command
    if not cmd:
        print("rss_by_mapping.py: no command after --", file=sys.stderr)
        return 2
    ranks, timeline = {}, [] if a.timeline else None
    start = time.monotonic()
    p = subprocess.Popen(cmd)
    while p.poll() is None:
        sample(p.pid, ranks, int(a.step * 1000), time.monotonic() - start, timeline)
        time.sleep(a.interval)
    if a.timeline:
        with open(a.timeline, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["time_s", "rank", "rss_mb"])
            w.writerows(timeline)
    if not ranks:
        print("rss_by_mapping.py: no tribex process was seen", file=sys.stderr)
        return 2
    rows = []
    for r in sorted(ranks.values(), key=lambda r: r["rank"]):
        row = {"rank": r["rank"], "hwm_mb": r["hwm"] / 1000, "sampled_mb": r["max"] / 1000, "peak_at_s": r["at"],
               "shm_mappings_touched": r["touched"]}
        for k in KINDS:
            row[f"{k}_rss_mb"] = r["kinds"][k][0] / 1000
            row[f"{k}_pss_mb"] = r["kinds"][k][1] / 1000
        rows.append(row)
        parts = " ".join(f"{k} {r['kinds'][k][0] / 1000:.0f}/{r['kinds'][k][1] / 1000:.0f}" for k in KINDS)
        big = ", ".join(f"{rss / 1000:.0f} of {size / 1000:.0f} ({kind})" for rss, size, kind in r["big"])
        print(f"rank {r['rank']}: VmHWM {r['hwm'] / 1000:.0f} MB, sampled peak {r['max'] / 1000:.0f} MB at {r['at']:.1f} s; "
              f"RSS/PSS MB: {parts}; shared-memory mappings with resident pages {r['touched']}; "
              f"largest anon/shm mappings RSS of size MB: {big}")
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0]))
            w.writeheader()
            w.writerows(rows)
    return p.returncode


if __name__ == "__main__":
    sys.exit(main())
