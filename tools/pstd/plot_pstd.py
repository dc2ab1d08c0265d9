#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Plots of a `tribex pstd` run: python3 plot_pstd.py OUTDIR (Debian's /usr/bin/python3 + matplotlib).

normal_force.png   normal force vs position, PSTD events shaded (report Fig. 2.23)
contacts_area.png  contacting asperities and true contact area vs position (Figs. 2.25, 2.26)
area_study.png     normal force vs position for 1..N counterface copies (Fig. 2.24), if area_study.csv exists
"""
import os
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
from history_checks import pyplot  # noqa: E402  (matplotlib, Agg: imported after the inputs are checked)
from cli_errors import InputError, guarded, read_csv_rows, require_folder  # noqa: E402


def read(path, may_be_empty=False):
    """The columns of a CSV of `tribex pstd` as lists of floats (events.csv may have no rows)."""
    fix = "give the -o folder of a finished `tribex pstd` run"
    if may_be_empty and os.path.isfile(path) and os.path.getsize(path) > 0:
        with open(path, newline="") as f:
            if sum(1 for _ in f) == 1:  # the header alone: no events
                return {}
    rows = read_csv_rows(path, "a CSV of tribex pstd", fix)
    try:
        return {k: [float(r[k]) for r in rows] for k in rows[0].keys()}
    except (TypeError, ValueError) as e:
        raise InputError(f"{path}: not a complete CSV of tribex pstd ({e})") from None


def shade_events(ax, events):
    for s, e in zip(events.get("start[nm]", []), events.get("end[nm]", [])):
        ax.axvspan(s / 1e3, e / 1e3, color="tab:orange", alpha=0.25, lw=0)
        ax.axvline(s / 1e3, color="tab:orange", ls="--", lw=0.6)
        ax.axvline(e / 1e3, color="tab:orange", ls="--", lw=0.6)


def main(out):
    require_folder(out, "the -o folder of a tribex pstd run")
    t = read(os.path.join(out, "trajectory.csv"))
    ev = read(os.path.join(out, "events.csv"), may_be_empty=True)
    plt = pyplot()
    x = [p / 1e3 for p in t["position[nm]"]]

    fig, ax = plt.subplots(figsize=(8, 4.5))
    ax.plot(x, t["normal_force[uN]"], lw=1.0, label="normal force")
    shade_events(ax, ev)
    ax.set_xlabel("counterface position [um]")
    ax.set_yscale("log")  # W falls by orders of magnitude along a run
    ax.set_ylabel("normal force [µN]")
    ax.set_title("PSTD model: normal force vs position (%d PSTD events shaded)" % len(ev.get("event", [])))
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "normal_force.png"), dpi=130)
    plt.close(fig)

    fig, ax1 = plt.subplots(figsize=(8, 4.5))
    ax1.plot(x, t["contacts"], color="tab:blue", lw=1.0, drawstyle="steps-post")
    ax1.set_xlabel("counterface position [um]")
    ax1.set_ylabel("contacting asperities", color="tab:blue")
    ax2 = ax1.twinx()
    ax2.plot(x, t["true_area[um^2]"], color="tab:green", lw=1.0)
    ax2.set_yscale("log")
    ax2.set_ylabel("true contact area [um^2]", color="tab:green")
    shade_events(ax1, ev)
    ax1.set_title("contacts (left) and true contact area (right); PSTD events shaded")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "contacts_area.png"), dpi=130)
    plt.close(fig)

    study = os.path.join(out, "area_study.csv")
    if os.path.exists(study):
        s = read(study)
        tr = read(os.path.join(out, "study_trajectories.csv"))
        fig, ax = plt.subplots(figsize=(8, 4.5))
        for n, c0 in zip(s["copies"], s["initial_contacts"]):
            xs = [p / 1e3 for p, k in zip(tr["position[nm]"], tr["copies"]) if k == n]
            fs = [f / n for f, k in zip(tr["normal_force[uN]"], tr["copies"]) if k == n]
            ax.plot(xs, fs, lw=0.9, label="%d copies, %d initial contacts" % (n, c0))
        ax.set_xlabel("counterface position [um]")
        ax.set_yscale("log")
        ax.set_ylabel("normal force per copy [µN]")
        ax.set_title("apparent-area study")
        ax.legend(fontsize=7)
        ax.grid(alpha=0.3)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "area_study.png"), dpi=130)
        plt.close(fig)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print("usage: plot_pstd.py OUTDIR", file=sys.stderr)
        sys.exit(2)
    sys.exit(guarded(lambda: main(sys.argv[1])))
