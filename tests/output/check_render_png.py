# SPDX-License-Identifier: MIT
"""Check that a PNG from tools/plot/render_xdmf.py (contact view) is a picture, not noise (issue 27).

Usage: /usr/bin/python3 check_render_png.py OUT.png
The render frames the contact region at the image centre on a white background. In the central
window (the middle half of the width and height, clear of the colour bar) the check asks for
  - body: at least 40 % of the pixels are not background (the section fills the view);
  - colours: at least 12 distinct colours (RGB quantised to 1/32) among the body pixels (a colour
    field, not a flat fill);
  - not black and white: at most 10 % of the body pixels are grey (max - min channel < 0.08) -- the
    Viridis map has no grey;
  - smooth: at most 3 % of horizontally or vertically neighbouring body pixel pairs differ by more
    than 0.25 in any channel (the section's boundary and a few element faces), and the median
    difference is under 0.02.
The old picture of the demo (SI coordinates, ParaView's depth range collapsed) fails every line
but the first. Prints the figures and PASS or FAIL; exit status 1 on failure.
"""
import sys

import numpy as np
from matplotlib import image


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: check_render_png.py OUT.png")
    rgb = image.imread(sys.argv[1])[..., :3].astype(float)  # PNG: floats in 0..1
    h, w, _ = rgb.shape
    win = rgb[h // 4: 3 * h // 4, w // 4: 3 * w // 4]
    body = np.min(win, axis=2) < 0.97  # background is white
    body_fraction = float(body.mean())
    px = win[body]
    colours = len({tuple(c) for c in np.floor(px * 32).astype(int)}) if len(px) else 0
    grey = float(np.mean(np.ptp(px, axis=1) < 0.08)) if len(px) else 1.0
    diffs = []
    for a, b, both in ((win[:, 1:], win[:, :-1], body[:, 1:] & body[:, :-1]),
                       (win[1:, :], win[:-1, :], body[1:, :] & body[:-1, :])):
        diffs.append(np.max(np.abs(a - b), axis=2)[both])
    d = np.concatenate(diffs) if diffs else np.array([1.0])
    jumps = float(np.mean(d > 0.25)) if len(d) else 1.0
    median = float(np.median(d)) if len(d) else 1.0
    failures = []
    if body_fraction < 0.40:
        failures.append(f"body covers {body_fraction:.1%} of the central window (< 40 %)")
    if colours < 12:
        failures.append(f"{colours} distinct colours in the body (< 12)")
    if grey > 0.10:
        failures.append(f"{grey:.1%} of the body pixels are grey (> 10 %): black-and-white, not a colour map")
    if jumps > 0.03:
        failures.append(f"{jumps:.1%} of neighbouring pixel pairs jump by > 0.25 (> 3 %): noise")
    if median > 0.02:
        failures.append(f"median neighbour difference {median:.3f} (> 0.02)")
    print(f"{sys.argv[1]}: {w}x{h}; central window: body {body_fraction:.1%}, {colours} colours, grey {grey:.1%}, "
          f"jumps {jumps:.2%}, median neighbour difference {median:.4f}")
    for f in failures:
        print("FAIL: " + f)
    print("PASS" if not failures else "FAIL")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
