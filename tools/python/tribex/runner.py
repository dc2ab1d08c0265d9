# SPDX-License-Identifier: MIT
"""Running the tribex binary: `check`, `run`, `run_many` (several runs across the cores, with progress)."""
import concurrent.futures
import os
import pathlib
import subprocess
import sys

from .results import Result

# tools/python/tribex/runner.py -> the repository root, three folders up from this package.
_REPO = pathlib.Path(__file__).resolve().parents[3]


class TribexError(RuntimeError):
    """A tribex command that did not end normally: `exit_code` (2 bad input, 3 numerical failure, 130
    stopped by a signal) and the binary's own message (its last error line) as the text."""

    def __init__(self, message, exit_code, output=""):
        super().__init__(message)
        self.exit_code = exit_code
        self.output = output


def binary(path=None):
    """The tribex executable: `path`, else $TRIBEX, else the repository's build/bin/tribex."""
    found = pathlib.Path(path or os.environ.get("TRIBEX") or _REPO / "build" / "bin" / "tribex")
    if not (found.is_file() and os.access(found, os.X_OK)):
        raise TribexError(f"no tribex binary at {found}; build it (./tribex.sh build) or give binary= / $TRIBEX", 2)
    return str(found)


def _set_args(parameters):
    """`--set NAME=VALUE` for each deck parameter; a value is a number (SI) or a string with its unit."""
    args = []
    for name, value in (parameters or {}).items():
        args += ["--set", f"{name}={value}".replace(" ", "")]
    return args


def _call(command):
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        text = (done.stderr + done.stdout).strip().splitlines()
        errors = [line for line in text if ": error" in line] or text or ["(no output)"]
        raise TribexError(f"{' '.join(command[:3])}: exit {done.returncode}: {errors[0]}", done.returncode,
                          done.stdout + done.stderr)
    return done.stdout


def check(deck, set=None, binary_path=None):  # noqa: A002 (the CLI's name for it)
    """`tribex check DECK --set ...`: the pre-flight report as text; TribexError (exit 2) on a bad deck."""
    return _call([binary(binary_path), "check", str(deck), *_set_args(set)])


def run(deck, out, set=None, ranks=1, binary_path=None, extra=()):  # noqa: A002
    """`tribex run DECK -o OUT --quiet --set ...` (under mpirun with `ranks` > 1); returns the Result."""
    command = [binary(binary_path), "run", str(deck), "-o", str(out), "--quiet", *_set_args(set), *extra]
    if ranks > 1:
        command = ["mpirun", "--oversubscribe", "-np", str(ranks), *command]
    _call(command)
    return Result(out)


def run_many(jobs, workers=None, binary_path=None, progress=True):
    """Runs `jobs`, a list of dicts of run()'s arguments (deck, out, set, ranks), `workers` at a time
    (default: the cores, divided by the ranks a job uses); returns the Results in the jobs' order. A
    failed job raises its TribexError after the others finish."""
    ranks = max((j.get("ranks", 1) for j in jobs), default=1)
    workers = workers or max(1, (os.cpu_count() or 1) // ranks)
    results, errors = [None] * len(jobs), []
    with concurrent.futures.ThreadPoolExecutor(max_workers=workers) as pool:
        futures = {pool.submit(run, binary_path=binary_path, **job): k for k, job in enumerate(jobs)}
        for done, future in enumerate(concurrent.futures.as_completed(futures), 1):
            k = futures[future]
            try:
                results[k] = future.result()
            except TribexError as e:
                errors.append(e)
            if progress:
                print(f"tribex: {done}/{len(jobs)} runs done ({jobs[k]['out']})", file=sys.stderr)
    if errors:
        raise errors[0]
    return results
