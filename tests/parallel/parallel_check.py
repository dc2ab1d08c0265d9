#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks of parallel runs and restarts (tests/parallel/README.md), run by CTest (label mpi).

  parallel_check.py agree TRIBEX DECK OUT --ranks N --rtol R [--columns c1,c2,...] [--fields]
      runs DECK on 1 and N ranks (--reference DIR: the one-rank run is DIR, run before by the same
      binary, e.g. a verification deck's CTest fixture); every history column (or the listed ones) must agree:
      max |a - b| over the rows <= R * max |a| of the column (of the vector, for a component
      NAME_x/_y/_z; of all energies, for an energy; absolute for energy_error); --fields also compares every
      dataset of results.h5 (gathered fields must land in global order). With --reference, --termination T
      runs the N-rank deck only to T and compares it with the reference's rows up to T (a cheaper check of
      the same code paths where the deck's first part already exercises them).
  parallel_check.py restart TRIBEX DECK OUT --ranks N --stop STEP
      runs DECK uninterrupted, then stopped after STEP (exit 130, restart file) and resumed with
      --restart OUT/restart.h5 into the same folder: history.csv must be byte-identical; where the
      deck writes fields, the resumed results.h5 (continued, not restarted) must hold the same steps
      with bitwise the same times and datasets, and results.xdmf must be byte-identical. The resumed
      summary.json reports its own steps (first_step = STEP, ns/element/step over its steps) and the
      segments' total wall and loop time; log.txt holds both segments. --remapped: the resume goes through
      the move by global numbers of a restart on another rank count (test hook TRIBEX_RESTART_REMAP=1),
      which must then be lossless: the same bitwise checks.
  parallel_check.py remap TRIBEX DECK OUT --from-ranks N --ranks M --stop STEP --rtol R
      runs DECK on N ranks stopped after STEP (restart file), resumed on M ranks from it (the state moved by
      global node and element numbers: solver/restart/restart_remap.hpp; log.txt must say so), and
      uninterrupted on M ranks: the history rows from STEP on and every results.h5 dataset must agree to R
      (relative as in agree). Not bitwise: the two M-rank runs differ at STEP by the N- and M-rank partitions'
      summation order (shared-node sums, lumped masses, energy reductions).
  parallel_check.py sigterm TRIBEX DECK OUT --ranks N --termination T [--signal TERM|INT|USR1] [--sigkill-timeout S]
      DECK with its termination time set to T (written to OUT/deck.i) runs uninterrupted, then again
      with the signal sent to mpiexec alone (as a batch scheduler does at its time limit) once rank 0
      prints "running ..." (the loop has begun). SIGTERM/SIGINT: Open MPI sends the ranks SIGCONT, then
      SIGTERM and SIGKILL S s apart (S = odls_base_sigkill_timeout, default 1); the ranks must stop at the
      SIGCONT (log.txt says so, summary.json written before S s) and mpiexec exits 1 (Open MPI's own code).
      SIGUSR1 is forwarded; mpiexec exits with the ranks' 130. Either way: summary.json status
      "interrupted", exit_code 130, a valid history.csv and results.h5 (every step results.xdmf names),
      and restart.h5, from which the resumed history must equal the uninterrupted one byte for byte.
  parallel_check.py failure TRIBEX DECK OUT --ranks N --expect-code C --expect TEXT
      runs DECK (meant to fail; not quiet, so that rank 0 prints its log); exit code C, TEXT printed
      exactly once on stdout + stderr (not once per rank). --serial-restart-at STEP: resume (on N
      ranks) from a restart file written by a one-rank run stopped after STEP; --strip-global-ids removes its
      global numbers first (a file of an earlier tribex, which another rank count cannot resume).
  parallel_check.py fixture TRIBEX DECK OUT --restart-file F --ranks M [--rtol R]
      DECK resumed on M ranks from F, a restart file an earlier tribex wrote (tests/parallel/restart_v1: format
      version 1), and run uninterrupted on M ranks: each history row of the resumed run must be the
      uninterrupted row of its step, byte for byte when F was written by M ranks, else to R.
  agree ... --decomposition "rcb [SX SY SZ]": both runs of a deck given a `begin decomposition` block (written
      to OUT/deck.i; without SX SY SZ the run chooses the scale); the parallel run's log must name the coordinate
      bisection, and with --expect-partition TEXT its partition line must hold TEXT. --decomposition ptscotch:
      the same, the log naming PT-Scotch; "ptscotch distributed" adds `set-up = distributed`.
"""
import argparse
import csv
import os
import shutil
import subprocess
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from tribex_runs import full_and_stopped, launcher, run  # noqa: E402


def read(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(x) for x in r] for r in rows[1:]]


def with_decomposition(a):
    """--decomposition "METHOD [distributed] [above=N] [SX SY SZ]": DECK with a `begin decomposition` block in its region, written to
    OUT/deck.i (both runs take it; one rank ignores it; no scale: the run's own). DECK must not name files
    relative to itself."""
    if not a.decomposition:
        return a.deck
    method, *scale = a.decomposition.split()
    distributed = "distributed" in scale  # `set-up = distributed` (each rank generates its slab)
    above = [w.split("=")[1] for w in scale if w.startswith("above=")]  # method = auto's `distributed above`
    scale = [w for w in scale if w != "distributed" and not w.startswith("above=")]
    with open(a.deck) as f:
        lines = f.read().split("\n")
    at = next(i for i, line in enumerate(lines) if line.strip().startswith("use finite element model"))
    block = ["      begin decomposition", f"        method = {method}",
             *(["        set-up = distributed"] if distributed else []),
             *([f"        distributed above = {above[0]}"] if above else []),
             *([f"        coordinate scale = {' '.join(scale)}"] if scale else []), "      end decomposition"]
    return deck_copy(a, "\n".join(lines[:at + 1] + block + lines[at + 1:]))


def deck_copy(a, text):
    """`text` (an edited DECK) written to OUT/deck.i, which is returned."""
    os.makedirs(a.out, exist_ok=True)
    deck = os.path.join(a.out, "deck.i")
    with open(deck, "w") as f:
        f.write(text)
    return deck


def same_layout(f1, f2, names):
    """The parallel results.h5 is the serial one's: the same datasets (names, types, shapes), the same
    attributes (but the root's run_id, each run's own), the mesh arrays bitwise (every rank writes its
    own rows of them: a row in the wrong place is not round-off)."""
    import numpy as np
    others = []
    f2.visit(lambda n: others.append(n) if isinstance(f2[n], h5py_dataset()) else None)
    if sorted(others) != sorted(names):
        sys.exit(f"FAIL: results.h5 datasets differ: {sorted(set(names) ^ set(others))[:5]}")
    for n in ["/"] + names:
        x, y = f1[n], f2[n]
        if n != "/" and (x.dtype != y.dtype or x.shape != y.shape):
            sys.exit(f"FAIL: results.h5 {n}: {x.dtype}{x.shape} vs {y.dtype}{y.shape}")
        keys = sorted(k for k in x.attrs if not (n == "/" and k == "run_id"))
        if keys != sorted(k for k in y.attrs if not (n == "/" and k == "run_id")):
            sys.exit(f"FAIL: results.h5 {n}: attributes {keys} vs {sorted(y.attrs)}")
        for k in keys:
            if not np.array_equal(np.asarray(x.attrs[k]), np.asarray(y.attrs[k])):
                sys.exit(f"FAIL: results.h5 {n}: attribute {k} {x.attrs[k]!r} vs {y.attrs[k]!r}")
    for n in ("mesh/coordinates", "mesh/connectivity", "mesh/block_id"):
        if not np.array_equal(np.asarray(f1[n]), np.asarray(f2[n])):
            sys.exit(f"FAIL: results.h5 {n} differs from the one-rank run's")
    print(f"results.h5: the same {len(names)} datasets, types, shapes and attributes; the mesh arrays bitwise equal")


def h5py_dataset():
    import h5py
    return h5py.Dataset

def history_difference(h1, r1, r2, columns):
    """The largest relative difference of `columns` between rows r1 and r2 (header h1) and its column."""
    worst, worst_name = 0.0, ""
    for name in columns:
        j = h1.index(name)
        # A vector component (NAME_x/_y/_z) is measured against the largest component of its
        # vector: a zero-by-symmetry component holds only round-off, relative to itself noise.
        # Energies are measured against the largest energy of the run (a term that is zero up to
        # round-off, like the hourglass energy of a uniaxial wave, has no scale of its own), and
        # energy_error, itself a relative number, absolutely.
        group = [name]
        energy = ("_energy", "_work", "_dissipation")
        if name == "energy_error":
            group = []
        elif name.endswith(energy):
            group = [c for c in h1 if c.endswith(energy)]
        elif name[-2:] in ("_x", "_y", "_z"):
            group = [c for c in h1 if c[:-2] == name[:-2] and c[-2:] in ("_x", "_y", "_z")]
        scale = max((abs(r[h1.index(c)]) for c in group for r in r1), default=1.0)
        if scale == 0.0:
            scale = 1.0
        err = max(abs(x[j] - y[j]) for x, y in zip(r1, r2)) / scale
        if err > worst:
            worst, worst_name = err, name
    return worst, worst_name


def fields_difference(path1, path2):
    """Every dataset of results.h5 `path1` against `path2`: (dataset names, largest relative difference)."""
    import h5py
    import numpy as np
    with h5py.File(path1) as f1, h5py.File(path2) as f2:
        names = []
        f1.visit(lambda n: names.append(n) if isinstance(f1[n], h5py.Dataset) else None)
        fworst = 0.0
        for n in names:
            x, y = np.asarray(f1[n], dtype=float), np.asarray(f2[n], dtype=float)
            if x.shape != y.shape:
                sys.exit(f"FAIL: results.h5 {n}: shape {x.shape} vs {y.shape}")
            # NaN marks "no value" (gap off the slave nodes): at the same places in both files.
            if not np.array_equal(np.isnan(x), np.isnan(y)):
                sys.exit(f"FAIL: results.h5 {n}: NaN at other places than in the one-rank run's")
            x, y = x[~np.isnan(x)], y[~np.isnan(y)]
            scale = np.max(np.abs(x)) if x.size else 0.0
            err = np.max(np.abs(x - y)) / (scale if scale > 0 else 1.0) if x.size else 0.0
            fworst = max(fworst, err)
    return names, fworst


def same_xdmf(serial, parallel, rtol):
    """results.xdmf: the same text but for the output times, which may differ by round-off where the stable
    step is a reduction over the ranks (dmt_coarse: 3e-12 in dt, so the 17th digit of a time); those to rtol."""
    times = re.compile(r'<Time Value="([^"]*)"/>')
    with open(serial) as x1, open(parallel) as x2:
        t1, t2 = x1.read(), x2.read()
    if times.sub("T", t1) != times.sub("T", t2):
        sys.exit("FAIL: results.xdmf differs from the one-rank run's (beyond the output times)")
    v1, v2 = [float(v) for v in times.findall(t1)], [float(v) for v in times.findall(t2)]
    worst = max((abs(x - y) / max(abs(x), abs(y), 1e-300) for x, y in zip(v1, v2)), default=0.0)
    if worst > rtol:
        sys.exit(f"FAIL: results.xdmf's output times differ by {worst:.3e} relative (tolerance {rtol:g})")
    print("results.xdmf: byte-identical to the one-rank run's" if t1 == t2 else
          f"results.xdmf: the one-rank run's text, output times within {worst:.1e} relative")


def agree(a):
    serial, parallel = a.reference or os.path.join(a.out, "np1"), os.path.join(a.out, f"np{a.ranks}")
    for d in ((parallel,) if a.reference else (serial, parallel)):
        shutil.rmtree(d, ignore_errors=True)
    deck = with_decomposition(a)
    if a.termination:  # with --reference only: the N-rank run stops early, compared on the rows it has
        with open(deck) as f:
            text = f.read()
        deck = deck_copy(a, re.sub(r"termination time = [^\n#]*", f"termination time = {a.termination}", text, count=1))
    if not a.reference:
        run(a.tribex, deck, serial, 1)
    run(a.tribex, deck, parallel, a.ranks)
    if a.decomposition:
        with open(os.path.join(parallel, "log.txt")) as f:
            partition = next((line.strip() for line in f if line.startswith("parallel: ")), "")  # the set-up's line
        print(partition)
        if "recursive coordinate bisection" not in partition and a.decomposition.startswith("rcb"):
            sys.exit("FAIL: the run did not partition by coordinate bisection")
        if "PT-Scotch" not in partition and a.decomposition.startswith("ptscotch"):
            sys.exit("FAIL: the run did not partition with PT-Scotch")
        if a.expect_partition not in partition:
            sys.exit(f"FAIL: the partition line does not say '{a.expect_partition}'")
    h1, r1 = read(os.path.join(serial, "history.csv"))
    h2, r2 = read(os.path.join(parallel, "history.csv"))
    if a.termination:
        # The shortened run's rows are the full run's first rows (the same steps: the termination time
        # enters the step only at the last one), except its final row at the new end: dropped.
        r2 = r2[:-1]
        if len(r2) >= len(r1) or any(x[1] != y[1] for x, y in zip(r1, r2)):
            sys.exit("FAIL: the shortened run's rows are not the first rows of the reference (times differ)")
        r1 = r1[:len(r2)]
        print(f"--termination {a.termination}: the first {len(r2)} rows of the reference compared")
    if h1 != h2 or len(r1) != len(r2):
        sys.exit(f"FAIL: histories differ in shape ({len(r1)} vs {len(r2)} rows)")
    columns = a.columns.split(",") if a.columns else h1[1:]
    worst, worst_name = history_difference(h1, r1, r2, columns)
    print(f"{len(columns)} history columns, {len(r1)} rows, 1 vs {a.ranks} ranks: "
          f"largest relative difference {worst:.3e} ({worst_name or 'none'}), tolerance {a.rtol:g}")
    if worst > a.rtol:
        sys.exit("FAIL: history differs beyond the tolerance")
    if a.fields:
        names, fworst = fields_difference(os.path.join(serial, "results.h5"), os.path.join(parallel, "results.h5"))
        print(f"results.h5: {len(names)} datasets, largest relative difference {fworst:.3e}")
        if fworst > a.rtol:
            sys.exit("FAIL: results.h5 differs beyond the tolerance")
        import h5py
        with h5py.File(os.path.join(serial, "results.h5")) as f1, h5py.File(os.path.join(parallel, "results.h5")) as f2:
            same_layout(f1, f2, names)
        same_xdmf(os.path.join(serial, "results.xdmf"), os.path.join(parallel, "results.xdmf"), a.rtol)
    if a.strict_region:
        import json
        with open(os.path.join(serial, "summary.json")) as f:
            whole = json.load(f)["rank_counts"][0]["contact_faces"]
        with open(os.path.join(parallel, "summary.json")) as f:
            faces = [r["contact_faces"] for r in json.load(f)["rank_counts"]]
        print(f"contact region faces per rank {faces} of {whole}")
        if min(faces) >= whole:
            sys.exit("FAIL: every rank's contact region holds the whole surfaces; the test does not exercise the "
                     "distributed contact")
    print("PASS")


def restart(a):
    a.deck = with_decomposition(a)  # --decomposition: both runs with the block (OUT/deck.i)
    full, resumed = full_and_stopped(a.tribex, a.deck, a.out, a.ranks, a.stop, "resumed")
    # --remapped: the resume goes through the move onto a partition by global numbers (restart_remap.hpp)
    # although the rank count is the same (test hook TRIBEX_RESTART_REMAP=1): the move must be lossless.
    run(a.tribex, a.deck, resumed, a.ranks, "--restart", os.path.join(resumed, "restart.h5"),
        env_extra={"TRIBEX_RESTART_REMAP": "1"} if a.remapped else None)
    if a.remapped:
        with open(os.path.join(resumed, "log.txt")) as f:
            if f"moved onto {a.ranks} by global node and element numbers" not in f.read():
                sys.exit("FAIL: --remapped: the resumed run did not go through the move (log.txt)")
        print(f"resumed through the move by global numbers (TRIBEX_RESTART_REMAP=1) on {a.ranks} rank(s)")
    with open(os.path.join(full, "history.csv"), "rb") as f:
        x = f.read()
    with open(os.path.join(resumed, "history.csv"), "rb") as f:
        y = f.read()
    rows = x.count(b"\n") - 1
    print(f"{a.ranks} rank(s): stopped after step {a.stop}, resumed; history.csv {len(y)} bytes vs {len(x)} "
          f"uninterrupted ({rows} rows): {'identical' if x == y else 'DIFFERENT'}")
    if x != y:
        sys.exit("FAIL: the resumed history is not bitwise identical")
    if os.path.exists(os.path.join(full, "results.h5")):
        import h5py
        import numpy as np
        with h5py.File(os.path.join(full, "results.h5")) as f1, h5py.File(os.path.join(resumed, "results.h5")) as f2:
            s1, s2 = sorted(f1["steps"].keys()), sorted(f2["steps"].keys())
            if s1 != s2:
                sys.exit(f"FAIL: results.h5 steps: {len(s2)} resumed vs {len(s1)} uninterrupted")
            names = []
            f1.visit(lambda n: names.append(n) if isinstance(f1[n], h5py.Dataset) else None)
            differ = [n for n in names if n not in f2 or not np.array_equal(f1[n][()], f2[n][()])]
            differ += [k for k in s1 if f1["steps"][k].attrs["time"] != f2["steps"][k].attrs["time"]]
            print(f"results.h5: {len(s1)} steps, {len(names)} datasets; {len(differ)} differ"
                  + (f" (first: {differ[0]})" if differ else " (bitwise identical)"))
            if differ:
                sys.exit("FAIL: the resumed results.h5 differs from the uninterrupted one")
        with open(os.path.join(full, "results.xdmf"), "rb") as f:
            x = f.read()
        with open(os.path.join(resumed, "results.xdmf"), "rb") as f:
            y = f.read()
        print(f"results.xdmf: {'identical' if x == y else 'DIFFERENT'}")
        if x != y:
            sys.exit("FAIL: the resumed results.xdmf differs")
    # The resumed run's cost: its own steps in summary.json, the segments' time added up, both
    # segments in log.txt.
    import json
    with open(os.path.join(full, "summary.json")) as f:
        whole = json.load(f)
    with open(os.path.join(resumed, "summary.json")) as f:
        second = json.load(f)
    with open(os.path.join(resumed, "log.txt")) as f:
        log = f.read()
    own = second["steps"] - second["first_step"]
    ns = 1e9 * second["loop_time_s"] / (second["elements"] * own) if own > 0 else 0.0
    print(f"summary.json: first_step {second['first_step']} (stop {a.stop}), steps {second['steps']} "
          f"(uninterrupted {whole['steps']}), ns/element/step {second['ns_per_element_step']:.4g} "
          f"(loop over own steps {ns:.4g}); total wall {second['total_wall_time_s']:.3g} s >= "
          f"this segment {second['wall_time_s']:.3g} s; log.txt segments {log.count('running ...')}")
    if (second["first_step"] != a.stop or second["steps"] != whole["steps"]
            or abs(second["ns_per_element_step"] - ns) > 1e-9 * ns
            or not second["total_wall_time_s"] > second["wall_time_s"]
            or not second["total_loop_time_s"] > second["loop_time_s"] or log.count("running ...") != 2):
        sys.exit("FAIL: summary.json or log.txt of the resumed run")
    print("PASS")


def valid_outputs(out):
    """history.csv: the header and whole numeric rows; results.h5 opens and holds every step results.xdmf
    names. Returns (history rows, results steps) or exits with FAIL."""
    import h5py
    import re
    rows = list(csv.reader(open(os.path.join(out, "history.csv"))))
    if rows[0][:2] != ["step", "time"] or len(rows) < 2 or any(len(r) != len(rows[0]) for r in rows[1:]):
        sys.exit("FAIL: history.csv is not a header and whole rows")
    [float(v) for r in rows[1:] for v in r]
    with h5py.File(os.path.join(out, "results.h5"), "r") as f:
        steps = set(f["steps"])
    named = set(re.findall(r"(step_\d+)", open(os.path.join(out, "results.xdmf")).read()))
    if not named or not named <= steps:
        sys.exit(f"FAIL: results.xdmf names steps results.h5 lacks: {sorted(named - steps)[:3]}")
    return len(rows) - 1, len(steps)


def sigterm(a):
    """A signal to mpiexec alone (a batch scheduler at its time limit: SIGTERM; Ctrl-C: SIGINT; SIGUSR1),
    with Open MPI's default odls_base_sigkill_timeout or --sigkill-timeout T in its environment."""
    import json
    import re
    import signal
    import time
    with open(a.deck) as f:
        text = f.read()
    deck = deck_copy(a, re.sub(r"termination time = [^\n#]*", f"termination time = {a.termination}", text, count=1))
    full, cut = os.path.join(a.out, "full"), os.path.join(a.out, "cut")
    for d in (full, cut):
        shutil.rmtree(d, ignore_errors=True)
    run(a.tribex, deck, full, a.ranks)
    env = dict(os.environ, OMPI_MCA_mpi_yield_when_idle="1", OMPI_MCA_hwloc_base_binding_policy="none")
    env.pop("OMPI_MCA_odls_base_sigkill_timeout", None)
    if a.sigkill_timeout:
        env["OMPI_MCA_odls_base_sigkill_timeout"] = str(a.sigkill_timeout)
    grace = 2 * (a.sigkill_timeout or 1)  # SIGCONT, SIGTERM after the timeout, SIGKILL after another
    # --via-tribex: `tribex run --ranks N` starts mpirun itself and is the process signalled.
    command = ([a.tribex, "run", "--ranks", str(a.ranks), deck, "-o", cut] if a.via_tribex
               else launcher(a.ranks) + [a.tribex, "run", deck, "-o", cut])
    if a.via_tribex:
        env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    job = subprocess.Popen(command, env=env,
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, bufsize=1)
    # Signal once the ranks are in the time-step loop: rank 0 prints "running ..." as it enters it.
    before = []
    for line in job.stdout:
        before.append(line)
        if line.startswith("running ..."):
            break
    if job.poll() is not None:
        sys.exit(f"FAIL: the run ended (exit {job.returncode}) before its loop began\n{''.join(before)}")
    time.sleep(0.5)  # some steps into the loop
    if job.poll() is not None:
        sys.exit(f"FAIL: the run ended (exit {job.returncode}) before the signal; give it a longer --termination")
    sig = getattr(signal, "SIG" + a.signal)
    sent = time.time()
    job.send_signal(sig)  # to mpiexec only
    output, _ = job.communicate(timeout=120 + 2 * grace)
    ended = time.time() - sent
    with open(os.path.join(cut, "summary.json")) as f:
        summary = json.load(f)
    written = os.path.getmtime(os.path.join(cut, "summary.json")) - sent
    with open(os.path.join(cut, "log.txt")) as f:
        log = f.read()
    reason = next((line for line in log.split("\n") if line.startswith("stopping after step")), "(no stop line)")
    print(f"SIG{a.signal} to mpiexec in the loop ({a.ranks} ranks, odls_base_sigkill_timeout "
          f"{a.sigkill_timeout or 'default 1'}): mpiexec exit {job.returncode} after {ended:.1f} s; summary.json "
          f"status {summary['status']!r}, exit_code {summary['exit_code']}, step {summary['steps']}, written "
          f"{written:.2f} s after the signal; restart.h5 "
          f"{'present' if os.path.exists(os.path.join(cut, 'restart.h5')) else 'MISSING'}; log: {reason}")
    if summary["status"] != "interrupted" or summary["exit_code"] != 130 or not os.path.exists(os.path.join(cut, "restart.h5")):
        sys.exit(f"FAIL: the signalled run did not stop cleanly\n{output}")
    # mpiexec's own code: SIGUSR1 is forwarded and mpiexec ends with the ranks' 130; after SIGTERM or
    # SIGINT Open MPI 4.1 exits 1 whatever the ranks return (its clean_abort sets the status, and the
    # kill sequence cancels the wait for the ranks' codes: docs/architecture.md "Signals").
    # `tribex run --ranks N` forwards any of them as SIGUSR1 and exits with the ranks' 130.
    expected = 130 if a.signal == "USR1" or a.via_tribex else 1
    if job.returncode != expected:
        sys.exit(f"FAIL: {'tribex run --ranks' if a.via_tribex else 'mpiexec'} exited {job.returncode}, "
                 f"expected {expected}\n{output}")
    if a.via_tribex and "SIGUSR1" not in reason:
        sys.exit(f"FAIL: the ranks did not stop at the forwarded SIGUSR1 (log.txt: {reason})")
    # The ranks stop at mpiexec's first signal (SIGCONT for SIGTERM/SIGINT), not at the SIGTERM that comes
    # odls_base_sigkill_timeout later: log.txt names it, and with a timeout set summary.json is written
    # before it (with the default 1 s the margin is too small to time on a loaded machine).
    late = a.sigkill_timeout and written >= a.sigkill_timeout
    if a.signal != "USR1" and not a.via_tribex and ("SIGCONT from mpirun" not in reason or late):
        sys.exit(f"FAIL: the ranks did not stop at mpiexec's SIGCONT (summary.json {written:.2f} s after the signal)")
    rows, steps = valid_outputs(cut)
    print(f"valid outputs: {rows} history rows, {steps} results steps")
    run(a.tribex, deck, cut, a.ranks, "--restart", os.path.join(cut, "restart.h5"))
    with open(os.path.join(full, "history.csv"), "rb") as f:
        x = f.read()
    with open(os.path.join(cut, "history.csv"), "rb") as f:
        y = f.read()
    print(f"resumed from step {summary['steps']}: history.csv {len(y)} bytes vs {len(x)} uninterrupted: "
          f"{'identical' if x == y else 'DIFFERENT'}")
    if x != y:
        sys.exit("FAIL: the resumed history is not bitwise identical")
    print("PASS")


def remap(a):
    """--from-ranks N --ranks M --stop STEP: a run on N ranks stopped after STEP, resumed on M ranks from its
    restart file (moved by global numbers), against an uninterrupted M-rank run."""
    resumed, full = os.path.join(a.out, "resumed"), os.path.join(a.out, "full")
    for d in (resumed, full):
        shutil.rmtree(d, ignore_errors=True)
    p = run(a.tribex, a.deck, resumed, a.from_ranks, "--stop-at-step", str(a.stop), check=False)
    if p.returncode != 130:
        sys.exit(f"FAIL: the stopped run on {a.from_ranks} rank(s) exited {p.returncode}, expected 130\n{p.stderr}")
    run(a.tribex, a.deck, resumed, a.ranks, "--restart", os.path.join(resumed, "restart.h5"))
    run(a.tribex, a.deck, full, a.ranks)
    with open(os.path.join(resumed, "log.txt")) as f:
        moved = f"moved onto {a.ranks} by global node and element numbers" in f.read()
    if not moved:
        sys.exit("FAIL: the resumed run's log.txt does not say the state was moved onto the new rank count")
    h1, r1 = read(os.path.join(full, "history.csv"))
    h2, r2 = read(os.path.join(resumed, "history.csv"))
    if h1 != h2 or len(r1) != len(r2) or any(x[0] != y[0] for x, y in zip(r1, r2)):
        sys.exit(f"FAIL: histories differ in shape or steps ({len(r1)} vs {len(r2)} rows)")
    after = [i for i, r in enumerate(r1) if r[0] >= a.stop]  # the rows the resumed run wrote
    worst, name = history_difference(h1, [r1[i] for i in after], [r2[i] for i in after], h1[1:])
    print(f"{a.from_ranks} -> {a.ranks} ranks, restart after step {a.stop}: {len(after)} history rows from there, "
          f"{len(h1) - 1} columns against an uninterrupted {a.ranks}-rank run: largest relative difference "
          f"{worst:.3e} ({name or 'none'}), tolerance {a.rtol:g}")
    if worst > a.rtol:
        sys.exit("FAIL: the resumed history differs beyond the tolerance")
    if os.path.exists(os.path.join(full, "results.h5")):
        names, fworst = fields_difference(os.path.join(full, "results.h5"), os.path.join(resumed, "results.h5"))
        print(f"results.h5: {len(names)} datasets, largest relative difference {fworst:.3e}")
        if fworst > a.rtol:
            sys.exit("FAIL: the resumed results.h5 differs beyond the tolerance")
    print("PASS")


def fixture(a):
    """--restart-file F --ranks M: DECK resumed on M ranks from F, a restart file an earlier tribex wrote (format
    version 1: tests/parallel/restart_v1), into an empty folder, against an uninterrupted M-rank run: every
    history row the resumed run writes must be the uninterrupted row of its step, byte for byte when F was
    written by M ranks, else to --rtol (the move onto another rank count)."""
    resumed, full = os.path.join(a.out, "resumed"), os.path.join(a.out, "full")
    for d in (resumed, full):
        shutil.rmtree(d, ignore_errors=True)
    run(a.tribex, a.deck, full, a.ranks)
    run(a.tribex, a.deck, resumed, a.ranks, "--restart", a.restart_file)
    with open(os.path.join(full, "history.csv")) as f:
        lines = f.read().splitlines()
    by_step = {line.split(",")[0]: line for line in lines[1:]}
    with open(os.path.join(resumed, "history.csv")) as f:
        mine = f.read().splitlines()
    rows = [line for line in mine[1:] if line]
    if mine[0] != lines[0] or not rows or any(line.split(",")[0] not in by_step for line in rows):
        sys.exit(f"FAIL: the resumed history's header or steps are not the uninterrupted run's ({len(rows)} rows)")
    import h5py
    with h5py.File(a.restart_file) as f:
        writers, version = int(f.attrs["ranks"]), int(f.attrs["format_version"])
    if writers == a.ranks:
        same = sum(by_step[line.split(",")[0]] == line for line in rows)
        print(f"format version {version} file of {writers} rank(s) resumed on {a.ranks}: {len(rows)} history rows from "
              f"step {rows[0].split(',')[0]}, {same} byte-identical to the uninterrupted run's")
        if same != len(rows):
            sys.exit("FAIL: the resumed history is not bitwise the uninterrupted one")
    else:
        h1, r1 = read(os.path.join(full, "history.csv"))
        _, r2 = read(os.path.join(resumed, "history.csv"))
        first = {r[0]: r for r in r1}
        worst, name = history_difference(h1, [first[r[0]] for r in r2], r2, h1[1:])
        print(f"format version {version} file of {writers} rank(s) resumed on {a.ranks}: {len(r2)} history rows, "
              f"largest relative difference {worst:.3e} ({name or 'none'}), tolerance {a.rtol:g}")
        if worst > a.rtol:
            sys.exit("FAIL: the resumed history differs beyond the tolerance")
    print("PASS")


def strip_global_ids(path):
    """A restart file as an earlier tribex wrote it: without the global numbers of each rank group."""
    import h5py
    with h5py.File(path, "r+") as f:
        for group in f.values():
            for name in ("global_node", "global_element", "block_ranges"):
                if name in group:
                    del group[name]


def failure(a):
    shutil.rmtree(a.out, ignore_errors=True)
    extra = []
    if a.serial_restart_at >= 0:  # a restart file written by one rank, resumed on a.ranks
        first = os.path.join(a.out, "serial")
        run(a.tribex, a.deck, first, 1, "--stop-at-step", str(a.serial_restart_at), check=False)
        if a.strip_global_ids:
            strip_global_ids(os.path.join(first, "restart.h5"))
        extra = ["--restart", os.path.join(first, "restart.h5")]
    p = run(a.tribex, a.deck, a.out, a.ranks, *extra, check=False, quiet=False)
    text = p.stdout + p.stderr
    count = text.count(a.expect)
    print(f"{a.ranks} ranks: exit code {p.returncode} (expected {a.expect_code}); '{a.expect}' printed {count} time(s)")
    if p.returncode != a.expect_code or count != 1:
        sys.exit(f"FAIL\n{text}")
    print("PASS")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("mode", choices=["agree", "restart", "remap", "sigterm", "failure", "fixture"])
    ap.add_argument("tribex")
    ap.add_argument("deck")
    ap.add_argument("out")
    ap.add_argument("--ranks", type=int, default=2)
    ap.add_argument("--rtol", type=float, default=1e-10)
    ap.add_argument("--columns", default="")
    ap.add_argument("--fields", action="store_true")
    ap.add_argument("--reference", default="",
                    help="agree: the one-rank run's output folder, already run (a verification run's fixture)")
    ap.add_argument("--stop", type=int, default=100)
    ap.add_argument("--expect-code", type=int, default=3)
    ap.add_argument("--expect", default="")
    ap.add_argument("--serial-restart-at", type=int, default=-1)
    ap.add_argument("--strip-global-ids", action="store_true",
                    help="failure with --serial-restart-at: remove the global numbers from the restart file (an earlier "
                         "tribex's file)")
    ap.add_argument("--from-ranks", type=int, default=1, help="remap: the rank count that writes the restart file")
    ap.add_argument("--remapped", action="store_true",
                    help="restart: resume through the move by global numbers at the same rank count (bitwise)")
    ap.add_argument("--restart-file", default="", help="fixture: the restart file an earlier tribex wrote")
    ap.add_argument("--termination", default="")
    ap.add_argument("--via-tribex", action="store_true",
                    help="sigterm: start the run with `tribex run --ranks N` and signal that process, not mpiexec")
    ap.add_argument("--signal", default="TERM", choices=["TERM", "INT", "USR1"], help="sigterm: the signal for mpiexec")
    ap.add_argument("--sigkill-timeout", type=int, default=0,
                    help="sigterm: OMPI_MCA_odls_base_sigkill_timeout for mpiexec (0: Open MPI's default, 1 s)")
    ap.add_argument("--decomposition", default="",
                    help='agree: "METHOD SX SY SZ", both runs with this `begin decomposition` (OUT/deck.i)')
    ap.add_argument("--expect-partition", default="",
                    help="agree with --decomposition: text the parallel run's partition line must hold")
    ap.add_argument("--strict-region", action="store_true",
                    help="agree: also require that some rank's contact region holds fewer faces than the whole "
                         "surfaces (summary.json rank_counts contact_faces), so the distributed contact is exercised")
    a = ap.parse_args()
    {"agree": agree, "restart": restart, "remap": remap, "sigterm": sigterm, "failure": failure,
     "fixture": fixture}[a.mode](a)


if __name__ == "__main__":
    main()
