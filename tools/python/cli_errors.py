# SPDX-License-Identifier: MIT
"""Bad input of the repository's scripts (issue 54, item 17): one line to stderr, exit 2, nothing
left behind, as the tribex binary does (README.md, exit codes).

    from cli_errors import InputError, guarded, require_file
    ...
    if __name__ == "__main__":
        sys.exit(guarded(main))

`guarded(main, made=...)` runs main(); an InputError or an OSError about a file (missing, a folder,
unreadable) becomes `error: ...` on one line and exit 2, and every folder in `made` (a list main fills
with the output folders it created) is removed again. Other exceptions (bugs) keep their traceback.
"""
import csv
import os
import shutil
import sys


class InputError(Exception):
    """A missing, empty or malformed input: the message is the one line the user sees."""


def fail(message):
    """One line to stderr and exit 2 (argument errors found before anything is written)."""
    print(f"error: {message}", file=sys.stderr)
    sys.exit(2)


def require_file(path, what, fix=""):
    """`path` must be a regular, non-empty file; `what` names it ("the run's history.csv")."""
    hint = f"; {fix}" if fix else ""
    if os.path.isdir(path):
        raise InputError(f"{path}: is a folder, not {what}{hint}")
    if not os.path.exists(path):
        raise InputError(f"{path}: no such file ({what}){hint}")
    if not os.path.isfile(path):
        raise InputError(f"{path}: not a regular file ({what}){hint}")
    if os.path.getsize(path) == 0:
        raise InputError(f"{path}: is empty ({what}){hint}")
    return path


def require_folder(path, what, fix=""):
    """`path` must be an existing folder; `what` names it ("the run's output folder")."""
    hint = f"; {fix}" if fix else ""
    if not os.path.exists(path):
        raise InputError(f"{path}: no such folder ({what}){hint}")
    if not os.path.isdir(path):
        raise InputError(f"{path}: not a folder ({what}){hint}")
    return path


def require_executable(path, what, fix=""):
    """`path` must be an executable file (the tribex binary given by --tribex)."""
    hint = f"; {fix}" if fix else ""
    if not os.path.isfile(path) or not os.access(path, os.X_OK):
        raise InputError(f"{path}: no such executable ({what}){hint}")
    return path


def make_folder(path, made):
    """os.makedirs(path); a folder that did not exist is appended to `made` (removed again on bad input)."""
    if not os.path.isdir(path):
        made.append(path)
    os.makedirs(path, exist_ok=True)


def read_csv_rows(path, what, fix=""):
    """The rows of a CSV file with a header as dicts of strings; a header without rows is an InputError."""
    require_file(path, what, fix)
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise InputError(f"{path}: has no data rows ({what}){'; ' + fix if fix else ''}")
    return rows


def guarded(main, made=None):
    """main(*args)'s exit status; bad input -> one line, exit 2, and the folders listed in `made` removed."""
    try:
        return main()
    except (InputError, OSError) as e:
        if isinstance(e, OSError) and e.filename is not None:
            message = f"{e.filename}: {e.strerror or e}"
        else:
            message = str(e)
        for folder in made or []:
            shutil.rmtree(folder, ignore_errors=True)
        print(f"error: {message.splitlines()[0] if message else type(e).__name__}", file=sys.stderr)
        return 2
