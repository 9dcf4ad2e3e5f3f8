"""The command line's other commands from Python: section, study, sweep and compare. Each runs
`plastica-draw` (which has every command) into a folder and reads what it wrote back as numpy
tables; a sweep's runs open as Results. Bad input raises SceneError with the command's message."""

import os
import subprocess
import tempfile

from . import _plastica
from ._locations import DRAWING_PROGRAM

SceneError = _plastica.SceneError


def _scene_file(scene, folder):
    """A path for the command line: the scene's own file, or the TOML of text or a dict written into folder."""
    from . import _scene_source
    source, is_text, _ = _scene_source(scene)
    if not is_text:
        return source
    path = os.path.join(folder, "scene.toml")
    with open(path, "w", encoding="utf-8") as f:
        f.write(source)
    return path


def _command(words, failure):
    done = subprocess.run([DRAWING_PROGRAM, *words], capture_output=True, text=True)
    if done.returncode == 2:
        message = done.stderr.strip()
        raise SceneError(message[len("plastica: "):] if message.startswith("plastica: ") else message)
    if done.returncode not in (0,) + failure:
        raise RuntimeError(f"plastica {words[0]} failed ({done.returncode}): {done.stderr.strip()}")
    return done


def _folder(folder, kind):
    return os.fspath(folder) if folder is not None else tempfile.mkdtemp(prefix=f"plastica_{kind}_")


def _value(value):
    text = repr(float(value)) if isinstance(value, float) else str(value).lower() if isinstance(value, bool) else str(value)
    if "," in text or any(ord(c) < 32 for c in text):
        raise SceneError(f"a varied value may not hold a comma or a control character: {text!r}")
    return text


class Section:
    """A section's capacity and moment–curvature tables (`plastica section`), as dicts of numpy
    arrays: `capacity` (axial_force, moment_positive, moment_negative, first_yield_moment,
    hinge_moment_positive, hinge_moment_negative, first_yield_moment_negative; signed edges of the
    domain) and `moment_curvature` (axial_ratio, axial_force,
    curvature, moment)."""

    def __init__(self, name, capacity, moment_curvature):
        self.name, self.capacity, self.moment_curvature = name, capacity, moment_curvature

    def __repr__(self):
        return f"<plastica.Section {self.name}: {len(self.capacity.get('axial_force', []))} capacity points>"


def section(scene, name=None, points=101, folder=None):
    """The N–M capacity and M–κ curves of a scene's section `name` (every inelastic one when None):
    a Section, or a dict {name: Section} when name is None."""
    from . import read_table
    out = _folder(folder, "section")
    words = ["section", _scene_file(scene, out), "-o", out, "--points", str(int(points)), "--no-charts", "-q"]
    if name is not None:
        words += ["--section", str(name)]
    _command(words, ())
    found = {}
    for file in sorted(os.listdir(out)):
        if file.endswith("_capacity.csv"):
            stem = file[: -len("_capacity.csv")]
            found[stem] = Section(stem, read_table(os.path.join(out, file)),
                                  read_table(os.path.join(out, stem + "_moment_curvature.csv")))
    if name is not None:
        if len(found) != 1:
            raise SceneError(f"section {name!r}: the command wrote {len(found)} tables")
        return next(iter(found.values()))
    return found


class Table:
    """A study's or a sweep's table (study.csv, sweep.csv) as a dict of numpy arrays, with the folder it came from."""

    def __init__(self, folder, table):
        self.folder, self.table = folder, table

    def __getitem__(self, column):
        return self.table[column]

    def run(self, run_id):
        """A sweep's run by its id ("r0001") as a Result (plastica.open of its folder)."""
        from . import open as open_result
        return open_result(os.path.join(self.folder, "runs", run_id))

    def __repr__(self):
        rows = len(next(iter(self.table.values()))) if self.table else 0
        return f"<plastica table of {rows} rows in {self.folder}>"


def study(scene, vary, reference=None, at=None, folder=None):
    """`plastica study`: vary maps a ladder's name (elements, fibres, integration_points,
    segments, increment, plasticity) to its levels. Returns the table of study.csv."""
    from . import read_table
    out = _folder(folder, "study")
    words = ["study", _scene_file(scene, out), "-o", out]
    for key, values in vary.items():
        words += ["--vary", f"{key}=" + ",".join(_value(v) for v in values)]
    if reference is not None:
        words += ["--reference", str(reference)]
    if at is not None:
        words += ["--at", ",".join(_value(v) for v in at)]
    _command(words, ())
    return Table(out, read_table(os.path.join(out, "study.csv")))


def sweep(scene, vary=None, zip=False, sample=None, samples=100, seed=1, jobs=None, at=None, folder=None, run_output="curves"):  # noqa: A002
    """`plastica sweep`: vary maps key paths (as `--set`) to lists of values, a grid (or side by
    side with zip=True); or sample maps them to laws ("uniform:a:b", "normal:μ:σ",
    "lognormal:μ:σ") for `samples` runs. Every value is checked before a run starts. Returns the
    table of sweep.csv; `.run(id)` opens a run."""
    from . import read_table
    out = _folder(folder, "sweep")
    words = ["sweep", _scene_file(scene, out), "-o", os.path.join(out), "--no-charts", "--run-output", run_output]
    for key, values in (vary or {}).items():
        words += ["--vary", f"{key}=" + ",".join(_value(v) for v in values)]
    for key, law in (sample or {}).items():
        words += ["--sample", f"{key}={_value(law)}"]
    if sample:
        words += ["--samples", str(int(samples)), "--seed", str(int(seed))]
    if zip:
        words.append("--zip")
    if jobs is not None:
        words += ["-j", str(int(jobs))]
    if at is not None:
        words += ["--at", ",".join(_value(v) for v in at)]
    _command(words, (1, 3))
    return Table(out, read_table(os.path.join(out, "sweep.csv")))


def compare(actual, reference, threshold=16, max_fraction=0.001, region=None):
    """`plastica compare`: pictures (a PNG or a folder of them) against references. A dict:
    passed (bool) and pictures (name → passed, differing_fraction, rms, vtk_error, problem)."""
    from . import read_table
    with tempfile.TemporaryDirectory(prefix="plastica_compare_") as out:
        table = os.path.join(out, "compare.csv")
        words = ["compare", os.fspath(actual), os.fspath(reference), "--threshold", str(int(threshold)),
                 "--max-fraction", repr(float(max_fraction)), "--table", table, "-q"]
        if region is not None:
            words += ["--region", ",".join(repr(float(v)) for v in region)]
        done = _command(words, (1,))
        rows = read_table(table)
    pictures = {}
    for i, name in enumerate(rows.get("name", [])):
        pictures[str(name)] = {"passed": bool(rows["passed"][i]), "differing_fraction": float(rows["differing_fraction"][i]),
                               "rms": float(rows["rms"][i]), "vtk_error": float(rows["vtk_error"][i]),
                               "problem": rows["problem"][i] if rows["problem"].dtype.kind == "U" else ""}
    return {"passed": done.returncode == 0, "pictures": pictures}
