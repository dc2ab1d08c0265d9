#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The repository stands on its own: nothing it holds reads or cites a file outside it.

Checks, over every tracked file (git ls-files; every file under the root when there is no .git):
  1. no file names the team's old side folder (the parent directory's `shared`), the compile
     definition that pointed tests at it, or the design notes kept there (cited by bare file name);
  2. every `docs/<name>.md` a file cites exists, and every section number cited after
     `docs/theory.md` (`docs/theory.md 6.3`, `... section 2.1`, `... 7.1-7.2`, `... 6, 7`) is a heading
     of docs/theory.md; `docs/dependencies.md section N` likewise;
  3. every repository path a README, deck or source comment names (`solver/run/run.cpp`,
     `verification/hertz/README.md`, ...) exists, except a command's output argument (-o, --csv, ...);
  4. the AFM sample files match the SHA-256 sums listed in inputs/data/afm/README.md.
Prints one line per problem as FILE:LINE: message, then a summary; exit 1 when anything fails.

usage: check_repo.py [REPO_ROOT]   (default: two folders up from this script)
"""
import hashlib
import os
import re
import subprocess
import sys

ROOT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", ".."))
OUTSIDE = ".." + "/shared"                 # spelt in two pieces so this file does not match itself
OLD_DEFINE = "TRIBEX_" + "SHARED_DIR"
# The design notes that lived outside the repository, cited by bare name (their text is in docs/ now).
OLD_NOTES = re.compile(r"(?<![\w/])(%s)\.md" % "|".join(["phys" + "ics", "CONVEN" + "TIONS", "ARCHI" + "TECTURE",
                                                          "DEPEN" + "DENCIES", "seed" + "-report"]))
TOP = ("inputs", "mesh", "materials", "contact", "solver", "verification", "tests", "tools", "docs")
PATH_RE = re.compile(r"(?<![\w./-])((?:%s)/[\w./-]*\w\.(?:md|cpp|hpp|h|py|i|csv|txt|cmake|sh|json|di|gsf))(?![\w/])"
                     % "|".join(TOP))
DOC_RE = re.compile(r"docs/(\w+)\.md")
SECTION_RE = re.compile(r"docs/(theory|dependencies)\.md,?\s+(?:sections?\s+)?(\d+(?:\.\d+)?(?:[a-z])?(?:\s*(?:-|,|and)\s*\d+(?:\.\d+)?[a-z]?)*)")
OUTPUT_ARG = re.compile(r"(?:^|\s)(?:-o|--out|--csv|--plot|--summits|>)\s*$")
TEXT_EXT = (".md", ".cpp", ".hpp", ".h", ".py", ".i", ".txt", ".cmake", ".sh", ".csv", ".json", "")
problems = []


def tracked_files():
    try:
        out = subprocess.run(["git", "-C", ROOT, "ls-files", "-z"], check=True, capture_output=True).stdout
        return [f for f in out.decode().split("\0") if f]
    except (OSError, subprocess.CalledProcessError):
        files = []
        for d, dirs, names in os.walk(ROOT):
            dirs[:] = [x for x in dirs if not (x.startswith(".") or x.startswith("build"))]
            files += [os.path.relpath(os.path.join(d, n), ROOT) for n in names]
        return files


def headings(doc):
    """Section numbers of a markdown file's headings: '## 6. The Adhesion Model' -> '6', '### 6.3 Cutoff' -> '6.3'."""
    found = set()
    with open(os.path.join(ROOT, doc), encoding="utf-8") as f:
        for line in f:
            m = re.match(r"#+\s+(\d+(?:\.\d+)*)\.?\s", line)
            if m:
                found.add(m.group(1))
    return found


def cited_numbers(text):
    """'7.1-7.2' -> ['7.1', '7.2'], '6, 7' -> ['6', '7'], '11.2b' -> ['11.2']."""
    return [re.sub(r"[a-z]$", "", n) for n in re.findall(r"\d+(?:\.\d+)?[a-z]?", text)]


def main():
    files = tracked_files()
    present = set(files)
    sections = {}
    for f in files:
        if not f.endswith(TEXT_EXT) or f.startswith("inputs/data/"):
            continue
        try:
            with open(os.path.join(ROOT, f), encoding="utf-8") as fh:
                lines = fh.read().splitlines()
        except (UnicodeDecodeError, FileNotFoundError):
            continue
        for no, line in enumerate(lines, 1):
            where = f"{f}:{no}"
            if OUTSIDE in line or OLD_DEFINE in line:
                problems.append(f"{where}: names a folder outside the repository ({line.strip()[:80]})")
            for name in OLD_NOTES.findall(line):
                problems.append(f"{where}: cites the old outside note {name}.md; cite docs/ instead")
            for name in DOC_RE.findall(line):
                if f"docs/{name}.md" not in present:
                    problems.append(f"{where}: cites docs/{name}.md, which does not exist")
            for doc, nums in SECTION_RE.findall(line):
                path = f"docs/{doc}.md"
                if path not in present:
                    continue
                if path not in sections:
                    sections[path] = headings(path)
                for n in cited_numbers(nums):
                    if n not in sections[path]:
                        problems.append(f"{where}: cites {path} section {n}, which has no such heading")
            for m in PATH_RE.finditer(line):
                p = m.group(1)
                if OUTPUT_ARG.search(line[:m.start()]):
                    continue  # a file a command writes, not one the repository holds
                if p not in present and not os.path.exists(os.path.join(ROOT, p)):
                    problems.append(f"{where}: names {p}, which is not in the repository")
    readme = os.path.join(ROOT, "inputs/data/afm/README.md")
    with open(readme, encoding="utf-8") as fh:
        sums = re.findall(r"^([0-9a-f]{64})  (\S+)$", fh.read(), re.M)
    if len(sums) < 6:
        problems.append(f"inputs/data/afm/README.md: expected the SHA-256 of 6 sample files, found {len(sums)}")
    for digest, name in sums:
        path = os.path.join(ROOT, "inputs/data/afm", name)
        if not os.path.isfile(path):
            problems.append(f"inputs/data/afm/{name}: listed in the README but missing")
            continue
        with open(path, "rb") as fh:
            if hashlib.sha256(fh.read()).hexdigest() != digest:
                problems.append(f"inputs/data/afm/{name}: SHA-256 differs from the README's")
    return report(problems, f"{len(files)} files checked, {len(sums)} sample sums")


def report(problems, what):
    """One line per problem, then `WHAT, N problems`; the exit status (1 when any)."""
    for p in problems:
        print(p)
    print(f"{what}, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
