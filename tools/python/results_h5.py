# SPDX-License-Identifier: MIT
"""Reading tribex's results.h5 in SI units.

results.h5 writes the coordinates and the length fields (displacement) in its length unit (nm for a
model under 1 um, solver/output/README.md "Units"): every dataset carries a `units` attribute and
the file a `length_unit` one. Files written before the units have neither and are SI throughout.
"""
import numpy as np

METRES_PER = {"m": 1.0, "um": 1e-6, "nm": 1e-9}


def units(dataset):
    """The dataset's `units` attribute as text ("" when it has none)."""
    u = dataset.attrs.get("units", b"")
    return u.decode() if isinstance(u, (bytes, np.bytes_)) else str(u)


def si(dataset):
    """The dataset's values in SI: lengths in um or nm converted to metres, everything else as stored."""
    values = dataset[()]
    scale = METRES_PER.get(units(dataset), 1.0)
    return values * scale if scale != 1.0 else values
