# SPDX-License-Identifier: MIT
"""Running tribex from the Python test scripts (tests/output/check_exodus.py, tests/parallel/parallel_check.py):
one launcher, one `run`, and the uninterrupted-plus-stopped pair that every restart check starts from."""
import os
import shutil
import subprocess
import sys


def launcher(ranks):
    """mpiexec for more than one rank (oversubscribed; as root where the container runs so)."""
    if ranks == 1:
        return []
    cmd = ["mpiexec", "-n", str(ranks), "--oversubscribe"]
    if os.geteuid() == 0:
        cmd.append("--allow-run-as-root")
    return cmd


def run(tribex, deck, out, ranks=1, *extra, check=True, quiet=True, env_extra=None):
    """`tribex run DECK -o OUT` on `ranks` ranks; exits the script with FAIL when `check` and it fails."""
    cmd = launcher(ranks) + [tribex, "run", deck, "-o", out, *(["--quiet"] if quiet else []), *extra]
    env = dict(os.environ, OMPI_MCA_mpi_yield_when_idle="1", OMPI_MCA_hwloc_base_binding_policy="none", **(env_extra or {}))
    p = subprocess.run(cmd, capture_output=True, text=True, env=env)
    if check and p.returncode != 0:
        sys.exit(f"FAIL: {' '.join(cmd)} exited {p.returncode}\n{p.stdout}\n{p.stderr}")
    return p


def full_and_stopped(tribex, deck, out, ranks, stop, stopped_name):
    """OUT/full, run to the end, and OUT/STOPPED_NAME, stopped by --stop-at-step STOP (exit 130 required):
    the pair a restart check resumes and compares. Returns the two folders."""
    full, stopped = os.path.join(out, "full"), os.path.join(out, stopped_name)
    for d in (full, stopped):
        shutil.rmtree(d, ignore_errors=True)
    run(tribex, deck, full, ranks)
    p = run(tribex, deck, stopped, ranks, "--stop-at-step", str(stop), check=False)
    if p.returncode != 130:
        sys.exit(f"FAIL: the stopped run exited {p.returncode}, expected 130\n{p.stderr}")
    return full, stopped
