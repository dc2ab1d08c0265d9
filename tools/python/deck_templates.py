# SPDX-License-Identifier: MIT
"""Pieces shared by the deck generators (make_decks.py): drive functions written as piecewise-linear
tables, and the deck blocks every generated deck spells the same way.

Drive functions. A cycloidal speed ramp v = V (1 - cos(pi s / T)) / 2 over T has no acceleration jump
at either end; its travel after s seconds is V/2 (s - T/pi sin(pi s / T)) (`cycloid_travel`).
`ramped_travel` is a move at constant speed started (and optionally stopped) with such ramps;
`table_times` (on `sample_times`), `function_table` and `values_lines` turn a function of time into
the `begin values` lines of a `type = piecewise linear` function (`piecewise_linear_function`),
times in ps.

Deck blocks (`elastic_material`, HEX8_FULLY_INTEGRATED, `block_parameters`, `fixed_displacement`,
`prescribed`, `contact_definition`, `history_output`, `results_output`) are the text of the inputs/
deck language at the indentation the generators use (two spaces a level, inside `begin sierra`).
A change here changes every generated deck: rerun the three make_decks.py and check the diff.
"""
import math
import os

PS = 1e-12  # s
NM = 1e-9   # m


def cycloid_travel(s, speed, ramp):
    """Travel after s (0 <= s <= ramp) of a cycloidal speed ramp from 0 to `speed` over `ramp`:
    speed/2 (s - ramp/pi sin(pi s/ramp)). Any consistent units (m, s or nm, ps)."""
    return speed / 2 * (s - ramp / math.pi * math.sin(math.pi * s / ramp))


def ramped_travel(t, speed, t_start, t_end=None, ramp=40 * PS):
    """Displacement (m) of a move at `speed` (m/s) from t_start (cycloidal ramp up over `ramp`) to
    t_end (cycloidal ramp down over `ramp`, ending at t_end; None: no stop), zero before t_start."""
    s = t - t_start
    if s <= 0:
        return 0.0
    if t_end is None or t <= t_end - ramp:
        return cycloid_travel(s, speed, ramp) if s <= ramp else speed * ramp / 2 + speed * (s - ramp)
    total = speed * (t_end - t_start - ramp)
    return total - cycloid_travel(min(t_end - t, ramp), speed, ramp) if t < t_end else total


def sample_times(t_start, t_stop, step=5 * PS):
    """t_start, t_start + step, ... up to t_stop (t_stop included when it is on the grid, to 1e-9
    of a step)."""
    return [t_start + i * step for i in range(int((t_stop - t_start) / step + 1e-9) + 1)]


def table_times(t_end, t_start=0.0, t_stop=None, step=5 * PS):
    """Times (s) of a drive table: 0 (when t_start > 0: the function is flat before it), then every
    `step` from t_start to t_stop (default t_end), then t_end. A table sampled only over a ramp
    (t_stop = the ramp's end) is exact where the function is constant or linear."""
    times = ([0.0] if t_start > 0 else []) + sample_times(t_start, t_end if t_stop is None else t_stop, step)
    if t_end - times[-1] > 1e-15:
        times.append(t_end)
    return times


def values_lines(points, time_format):
    """The `begin values` lines of a piecewise-linear function: (time in ps, value) pairs, values to
    5 decimals, times in `time_format` (e.g. "7.1f")."""
    return "\n".join(f"      {t:{time_format}}  {x:.5f}" for t, x in points)


def function_table(func, times, time_format, scale=1e9):
    """values_lines of func(t) * scale at `times` (s): scale 1e9 writes a displacement in nm."""
    return values_lines([(t / PS, func(t) * scale) for t in times], time_format)


def piecewise_linear_function(name, values, ordinate_unit="nm"):
    """A `begin function` block, abscissa in ps (ordinate_unit None: a plain factor)."""
    unit = f"    ordinate unit = {ordinate_unit}\n" if ordinate_unit else ""
    return (f"  begin function {name}\n    type = piecewise linear\n    abscissa unit = ps\n{unit}"
            f"    begin values\n{values}\n    end values\n  end function {name}")


def elastic_material(name, density, youngs_gpa, poisson):
    """A linear elastic material block: density in kg/m^3, Young's modulus in GPa."""
    return (f"  begin property specification for material {name}\n"
            f"    density = {density:g} kg/m^3\n"
            f"    begin parameters for model elastic\n"
            f"      youngs modulus = {youngs_gpa:g} GPa\n"
            f"      poissons ratio = {poisson:g}\n"
            f"    end parameters for model elastic\n"
            f"  end property specification for material {name}")


HEX8_FULLY_INTEGRATED = """\
  begin solid section hex8
    formulation = fully_integrated
  end solid section hex8"""


def block_parameters(block, material, section="hex8"):
    """A `begin parameters for block` block (inside `begin finite element model`)."""
    return (f"    begin parameters for block {block}\n      material = {material}\n"
            f"      section = {section}\n    end parameters for block {block}")


def write_deck(folder, name, text):
    """Writes folder/name.i (the folder is created if missing); returns its path."""
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, name + ".i")
    with open(path, "w") as f:
        f.write(text)
    return path


def fixed_displacement(node_set, components):
    """A `begin fixed displacement` block (inside `begin presto region`); components e.g. "x y z"."""
    return (f"      begin fixed displacement\n        node set = {node_set}\n        components = {components}\n"
            f"      end fixed displacement")


def prescribed(kind, node_set, component, function, scale_factor=None, target="node set"):
    """A `begin prescribed displacement` (kind "displacement") or `begin prescribed force` block
    driven by `function`, optionally scaled (scale_factor as written, e.g. "-1", "-500 nN"); target
    "rigid body" names a rigid body instead of a node set."""
    scale = f"        scale factor = {scale_factor}\n" if scale_factor is not None else ""
    return (f"      begin prescribed {kind}\n        {target} = {node_set}\n        component = {component}\n"
            f"        function = {function}\n{scale}      end prescribed {kind}")


def rigid_body(name, node_set):
    """A `begin rigid body` block: the nodes of `node_set` move as one translating body."""
    return f"      begin rigid body {name}\n        node set = {node_set}\n      end rigid body {name}"


def history_output(increment_ps, reactions, displacements):
    """The `hist` history output: reaction forces of the node sets `reactions` and mean
    displacements of `displacements` (space-separated names) every increment_ps ps."""
    return (f"      begin history output hist\n        time increment = {increment_ps} ps\n"
            f"        reaction force = {reactions}\n        mean displacement = {displacements}\n"
            f"      end history output hist")


def results_output(increment_ps, element_variables=None, nodal_variables="displacement contact_traction contact_status"):
    """The `fields` results output every increment_ps ps: by default the displacement and contact fields."""
    element = f"        element variables = {element_variables}\n" if element_variables else ""
    return (f"      begin results output fields\n        time increment = {increment_ps} ps\n"
            f"        nodal variables = {nodal_variables}\n{element}"
            f"      end results output fields")


def contact_definition(name, surfaces, axis, interaction, body):
    """A `begin contact definition` with one interaction between all its surfaces: surfaces = [(surface,
    side or node set), ...]; axis = the contact axis (point and direction, nm) as written; body = the
    interaction's model lines (10 spaces of indentation, each ending in a newline; "" for plain
    penalty contact)."""
    lines = [f"      begin contact definition {name}"]
    lines += [f"        contact surface {surface} contains {where}" for surface, where in surfaces]
    lines += [f"        contact axis = {axis} nm", f"        begin interaction {interaction}",
              f"          surfaces = {' '.join(surface for surface, _ in surfaces)}"]
    return "\n".join(lines) + f"\n{body}        end interaction {interaction}\n      end contact definition {name}"
