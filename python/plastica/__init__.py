"""Plastica from Python: run a scene, read its curve and steps as numpy arrays, write and draw.

    import plastica
    r = plastica.run("models/ring_inelastic.toml", overrides={"material[1].fy": 20000.0})
    r.status, r.reason          # as run.json: "completed", "limit_load", ... (a stop is no exception)
    r.curve["load"]             # numpy arrays, one per column of curve.csv
    r.step(-1).cell["axial_force"]
    r.write("out/ring")         # the files of `plastica run --no-render`
    plastica.render(r, "out/ring/frames")

A scene is a path to a TOML file, TOML text, or a dict with the file's structure. Overrides take
the keys and paths of `plastica run --set`. Errors in a scene raise SceneError (a ValueError),
located as the command line locates them (file and line, or the key path for a dict).
docs/python.md has the whole interface.
"""

import builtins
import csv
import io
import json
import math
import os
import re
import subprocess

import numpy as np

from . import _plastica
from ._locations import DRAWING_PROGRAM

SceneError = _plastica.SceneError
__version__ = _plastica.version

__all__ = ["run", "open", "render", "section", "study", "sweep", "compare", "read_table", "Result", "Step", "SceneError", "to_toml", "modes", "buckling"]


def _toml_key(key):
    key = str(key)
    bare = key and all(c.isalnum() or c in "-_" for c in key)
    return key if bare else json.dumps(key)


def _toml_value(value, where):
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        value = float(value)
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, str):
        return json.dumps(value)  # a JSON string is a TOML basic string
    if isinstance(value, dict):
        return "{" + ", ".join(f"{_toml_key(k)} = {_toml_value(v, f'{where}.{k}')}" for k, v in value.items()) + "}"
    if isinstance(value, (list, tuple, np.ndarray)):
        return "[" + ", ".join(_toml_value(v, f"{where}[{i}]") for i, v in enumerate(value)) + "]"
    raise SceneError(f"{where}: cannot be written in a scene: {type(value).__name__}")


def to_toml(scene):
    """The TOML text of a scene given as a dict: tables for dicts, arrays of tables for lists of dicts."""
    if not isinstance(scene, dict):
        raise SceneError(f"scene: expected a dict, got {type(scene).__name__}")
    lines = []
    for key, value in scene.items():
        if not isinstance(value, dict) and not (isinstance(value, list) and value and all(isinstance(v, dict) for v in value)):
            lines.append(f"{_toml_key(key)} = {_toml_value(value, key)}")
    for key, value in scene.items():
        if isinstance(value, dict):
            lines.append(f"\n[{_toml_key(key)}]")
            lines += [f"{_toml_key(k)} = {_toml_value(v, f'{key}.{k}')}" for k, v in value.items()]
        elif isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
            for i, table in enumerate(value):
                lines.append(f"\n[[{_toml_key(key)}]]")
                lines += [f"{_toml_key(k)} = {_toml_value(v, f'{key}[{i + 1}].{k}')}" for k, v in table.items()]
    return "\n".join(lines) + "\n"


def _columns(rows):
    """Columns of CSV rows (the first is the header) as numpy arrays: float where every value is
    a number or empty (NaN: critical_load_factor away from a critical point), else str."""
    header, body = rows[0], rows[1:]
    columns = {}
    for j, name in enumerate(header):
        values = [row[j] if j < len(row) else "" for row in body]
        try:
            columns[name] = np.array([float(v) if v != "" else np.nan for v in values], dtype=float)
        except ValueError:
            columns[name] = np.array(values, dtype=str)
    return columns


def read_table(path):
    """A CSV that Plastica writes (curve.csv, sweep.csv, a study's table) as a dict of numpy
    arrays, one per column: numbers as float, other columns as str. pandas.DataFrame(...) takes it."""
    with builtins.open(path, encoding="utf-8", newline="") as f:
        return _columns([row for row in csv.reader(f) if row])


class Step:
    """One converged step: `points` (n × 3, deformed), `lines` (the elements' node pairs), and the
    result schema's arrays by name: `point[...]` per node, `cell[...]` per element, `field[...]`."""

    def __init__(self, arrays):
        self.points = arrays["points"]
        self.lines = arrays["lines"]
        self.point = arrays["point"]
        self.cell = arrays["cell"]
        self.field = {k: (v[0] if len(v) == 1 else v) for k, v in arrays["field"].items()}

    def __repr__(self):
        return f"<plastica.Step {int(self.field.get('step', -1))}: {len(self.points)} nodes, {len(self.lines)} elements>"


class Result:
    """A finished run (completed or stopped: see `status` and `reason`): one run in memory
    (plastica.run), or an output folder read back (plastica.open). Pickling keeps its curve, report
    and every step's arrays, so a process pool may return it."""

    def __init__(self, source):
        self._source = source
        self._report = None
        if hasattr(source, "status"):
            self.status, self.reason, self._scene_name = source.status, source.reason, source.scene_name
        else:
            self.status = self.report.get("status", "")
            self.reason = self.report.get("reason", "")
            self._scene_name = self.report.get("scene", "")
        self.curve = _columns([row for row in csv.reader(io.StringIO(source.curve_csv)) if row])

    @property
    def report(self):
        """What run.json holds, as a dict."""
        if self._report is None:
            self._report = json.loads(self._source.report_json)
        return self._report

    @property
    def steps(self):
        """How many steps the run kept (the unloaded state, step 0, included)."""
        return self._source.step_count

    def step(self, k):
        """Step k of those kept (negative k counts from the last)."""
        return Step(self._source.step_arrays(k))

    def write(self, folder):
        """Writes the VTU/PVD series, curve.csv and run.json into folder, as `plastica run --no-render`."""
        if not hasattr(self._source, "write"):
            raise RuntimeError("this Result holds a run's arrays, not the run: write it before pickling it, "
                               "or pickle plastica.open(folder) of the folder it was written to")
        os.makedirs(folder, exist_ok=True)
        self._source.write(os.fspath(folder))
        return folder

    def dataframe(self):
        """The curve as a pandas DataFrame (pandas is needed for this alone)."""
        import pandas
        return pandas.DataFrame(self.curve)

    def __reduce__(self):
        if isinstance(self._source, _plastica.ResultFolder):
            return (open, (self._source.folder,))
        steps = [self._source.step_arrays(k) for k in range(self.steps)]
        return (_stored_result, (self.status, self.reason, self._scene_name, self._source.curve_csv,
                                 self._source.report_json, steps))

    def _repr_png_(self):
        """The load–displacement chart, as Jupyter shows a Result (matplotlib, no pyplot state)."""
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure
        first = self.step(0).field
        fig = Figure(figsize=(6, 4), dpi=100)
        FigureCanvasAgg(fig)
        ax = fig.add_subplot()
        ax.plot(self.curve["control_displacement"], self.curve["load"], color="#1f4e99")
        def label(name, unit):
            text, unit = str(first.get(name, name.replace("_label", ""))), str(first.get(unit, ""))
            return f"{text} ({unit})" if unit else text
        ax.set_xlabel(label("displacement_label", "displacement_unit"))
        ax.set_ylabel(label("load_label", "load_unit"))
        ax.set_title(f"{first.get('title', self._scene_name)}: {self.status}")
        ax.grid(True, alpha=0.3)
        fig.tight_layout()
        out = io.BytesIO()
        fig.savefig(out, format="png")
        return out.getvalue()

    def __repr__(self):
        return f"<plastica.Result {self._scene_name}: {self.status}, {self.steps} steps>"


class _StoredRun:
    """What a pickled Result carries: its texts and every step's arrays."""

    def __init__(self, status, reason, scene_name, curve_csv, report_json, steps):
        self.status, self.reason, self.scene_name = status, reason, scene_name
        self.curve_csv, self.report_json, self._steps = curve_csv, report_json, steps

    @property
    def step_count(self):
        return len(self._steps)

    def step_arrays(self, k):
        return self._steps[k]


def _stored_result(status, reason, scene_name, curve_csv, report_json, steps):
    return Result(_StoredRun(status, reason, scene_name, curve_csv, report_json, steps))


def open(folder):  # noqa: A001 (plastica.open, as the command line's output folders are opened)
    """An output folder that `plastica run` or Result.write wrote (run.json, curve.csv and the VTU
    series, each step read when asked for) as a Result, equal to the one the run returned."""
    try:
        return Result(_plastica.ResultFolder(os.fspath(folder)))
    except ValueError as error:
        raise ValueError(f"plastica.open: {error}") from None


def _scene_source(scene):
    if isinstance(scene, dict):
        return to_toml(scene), True, ""
    if isinstance(scene, os.PathLike):
        return os.fspath(scene), False, ""
    if isinstance(scene, str):
        if "\n" in scene or "=" in scene:
            return scene, True, "scene.toml"
        return scene, False, ""
    raise SceneError(f"scene: expected a path, TOML text or a dict, got {type(scene).__name__}")


def _named_path(message, scene):
    """A dict's error names a table by its name where it has one: section[HEB200].depth, not section[1].depth."""
    match = re.match(r"^([A-Za-z_]+)\[(\d+)\](.*)$", message, re.S)
    if not match:
        return message
    table, index, rest = match.group(1), int(match.group(2)), match.group(3)
    entries = scene.get(table)
    if isinstance(entries, list) and 1 <= index <= len(entries) and isinstance(entries[index - 1], dict):
        name = entries[index - 1].get("name")
        if isinstance(name, str) and name:
            return f"{table}[{name}]{rest}"
    return message


def _progress_callback(progress):
    """The callback run() hands the engine: the user's own, or with progress=True a tqdm bar where
    tqdm is installed, else a line on stderr redrawn in place."""
    if progress is None or progress is False:
        return None, None
    if callable(progress):
        return progress, None
    try:
        from tqdm import tqdm
        bar = tqdm(total=100, unit="%", bar_format="{l_bar}{bar}| {n:.0f}/100 % [{elapsed}<{remaining}]")

        def show(step, share, load, displacement):
            bar.set_postfix_str(f"step {step}  load {load:.4g}")
            if share >= 0.0:
                bar.update(100.0 * share - bar.n)
        return show, bar.close
    except ImportError:
        import sys

        def show(step, share, load, displacement):
            done = f"{100.0 * share:3.0f} %  " if share >= 0.0 else ""
            sys.stderr.write(f"\rsolving {done}step {step}  load {load:.6g}  control displacement {displacement:.6g}")
            sys.stderr.flush()
        return show, lambda: sys.stderr.write("\n")


def run(scene, overrides=None, progress=None):
    """Runs a scene (a path, TOML text or a dict) with overrides {key path: value}, as
    `plastica run SCENE --set KEY=VALUE ...`. Returns a Result; the GIL is released while it runs.
    progress: a callable (step, share done in [0, 1] or −1 when unknown, load, control
    displacement), called at most ten times a second and at the last step; or True for a tqdm bar
    (a line on stderr without tqdm). What the callable raises stops the run and is raised."""
    source, is_text, name = _scene_source(scene)
    pairs = [(str(k), _toml_value(v, str(k))) for k, v in (overrides or {}).items()]
    callback, close = _progress_callback(progress)
    try:
        return Result(_plastica.run_scene(source, is_text, name, pairs, callback))
    except SceneError as error:
        if isinstance(scene, dict):
            raise SceneError(_named_path(str(error), scene)) from None
        raise
    finally:
        if close:
            close()


def modes(scene, count=6, step=0, overrides=None):
    """The natural modes of a scene (a path, TOML text or a dict), as `plastica modes`: at the
    unloaded structure, or at step `step` of its run. A list of dicts, one per mode: mode, period,
    frequency, omega, effective_mass_x/y, share_x/y, and shape (an n_nodes × 3 array: ux, uy, θ
    for unit modal mass)."""
    return _at_step(_plastica.modes_of_scene, scene, count, step, overrides)


def _at_step(find, scene, count, step, overrides):
    """find(source, is_text, name, overrides, count, step), with a dict scene's errors named by its keys."""
    source, is_text, name = _scene_source(scene)
    pairs = [(str(k), _toml_value(v, str(k))) for k, v in (overrides or {}).items()]
    try:
        return find(source, is_text, name, pairs, int(count), int(step))
    except SceneError as error:
        if isinstance(scene, dict):
            raise SceneError(_named_path(str(error), scene)) from None
        raise


def buckling(scene, count=6, step=0, overrides=None):
    """The critical load factors and buckling modes of a scene's loads (a path, TOML text or a
    dict), as `plastica buckling`: at the unloaded structure, or about step `step` of its run. A
    list of dicts, one per mode: mode, load_factor, above_state (the factor above the state's),
    and shape (an n_nodes × 3 array: ux, uy, θ, its largest translation 1)."""
    return _at_step(_plastica.buckling_of_scene, scene, count, step, overrides)


def render(result, folder, size=(1280, 720), options=()):
    """Draws a run's pictures into folder as the render stage draws them (frames, chart.png,
    contact sheet, animation): the series is written beside them (folder/series) and drawn by
    `plastica render`. Extra command-line options go in `options`."""
    folder = os.fspath(folder)
    series = os.path.join(folder, "series")
    result.write(series)
    command = [DRAWING_PROGRAM, "render", series, "-o", folder, "--size", f"{int(size[0])}x{int(size[1])}", "-q", *options]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"plastica render failed ({done.returncode}): {done.stderr.strip()}")
    return folder


from .commands import compare, section, study, sweep  # noqa: E402 (they use the helpers above)
