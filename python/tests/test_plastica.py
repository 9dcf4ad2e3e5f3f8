"""The Python module against the command line: the same curves to the bit, the same overrides,
the VTU's arrays, located errors, runs on threads, pictures; and a cantilever from a dict against
its closed form."""
import concurrent.futures
import subprocess
import threading
import tomllib

import numpy as np
import pytest

import plastica


def cli_curve(binary, scene, folder, sets=()):
    command = [binary, "run", str(scene), "--curves-only", "-q", "--force", "-o", str(folder)]
    for s in sets:
        command += ["--set", s]
    subprocess.run(command, check=True)
    return plastica.read_table(folder / "curve.csv")


def assert_same_columns(a, b):
    assert list(a) == list(b)
    for name in a:
        assert a[name].dtype == b[name].dtype, name
        # A column empty away from a critical point holds NaN there, in both.
        equal_nan = a[name].dtype.kind == "f"
        assert np.array_equal(a[name], b[name], equal_nan=equal_nan), name


@pytest.mark.parametrize("scene", ["models/ring_inelastic.toml", "models/ring_elastic.toml", "models/gallery/portal_frame.toml"])
def test_curve_equals_the_command_lines_to_the_bit(source, binary, tmp_path, scene):
    r = plastica.run(source / scene)
    assert r.status == "completed"
    assert_same_columns(r.curve, cli_curve(binary, source / scene, tmp_path))


def test_overrides_equal_set(source, binary, tmp_path):
    scene = source / "models/ring_inelastic.toml"
    r = plastica.run(scene, overrides={"material[steel].fy": 20000.0, "analysis.increment": 1.0})
    assert_same_columns(r.curve, cli_curve(binary, scene, tmp_path, ["material[steel].fy=20000.0", "analysis.increment=1.0"]))
    # The override changed the run: a weaker ring carries less.
    assert r.curve["load"].max() < plastica.run(scene).curve["load"].max()


def test_text_and_dict_scenes_run_as_the_file(source):
    path = source / "models/gallery/portal_frame.toml"
    from_file = plastica.run(path)
    from_text = plastica.run(path.read_text())
    from_dict = plastica.run(tomllib.loads(path.read_text()))
    assert_same_columns(from_file.curve, from_text.curve)
    assert_same_columns(from_file.curve, from_dict.curve)


def test_step_arrays_match_the_vtu(source, tmp_path):
    vtk = pytest.importorskip("vtkmodules.vtkIOXML")
    from vtkmodules.util.numpy_support import vtk_to_numpy
    r = plastica.run(source / "models/ring_inelastic.toml")
    r.write(tmp_path)
    assert (tmp_path / "ring_inelastic.pvd").exists() and (tmp_path / "run.json").exists()
    for k in (0, 104, r.steps - 1):
        step = r.step(k)
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName(str(tmp_path / "vtu" / f"step_{k:06d}.vtu"))
        reader.Update()
        grid = reader.GetOutput()
        assert np.array_equal(vtk_to_numpy(grid.GetPoints().GetData()), step.points)
        for name, values in step.point.items():
            assert np.array_equal(vtk_to_numpy(grid.GetPointData().GetArray(name)).reshape(values.shape), values), name
        for name, values in step.cell.items():
            assert np.array_equal(vtk_to_numpy(grid.GetCellData().GetArray(name)).reshape(values.shape), values), name
    assert plastica.read_table(tmp_path / "curve.csv")["load"].tolist() == r.curve["load"].tolist()


def test_a_stop_is_a_status(source):
    r = plastica.run(source / "models/ring_inelastic.toml", overrides={"analysis.max_steps": 5})
    assert r.status == "step_limit"
    assert "step limit" in r.reason
    assert r.steps == 6
    assert r.report["status"] == "step_limit"


def test_scene_errors_are_located(source):
    scene = tomllib.loads((source / "models/gallery/portal_frame.toml").read_text())
    scene["section"][0]["depth"] = -0.3
    with pytest.raises(plastica.SceneError, match=r"^section\[HEB300\]\.depth: expected a positive number"):
        plastica.run(scene)
    del scene["section"][0]["name"]  # no name: the index
    with pytest.raises(plastica.SceneError, match=r"^section\[1\]"):
        plastica.run(scene)
    with pytest.raises(ValueError, match=r"scene.toml:3: 'scene.bogus': unknown key"):
        plastica.run('[scene]\nname = "x"\nbogus = 1\n')
    with pytest.raises(plastica.SceneError, match=r"--set material\[steel\]\.fy: expected a positive number"):
        plastica.run(source / "models/ring_inelastic.toml", overrides={"material[steel].fy": -1.0})
    # From a dict too, an override's error names the override.
    ring = tomllib.loads((source / "models/ring_inelastic.toml").read_text())
    with pytest.raises(plastica.SceneError, match=r"^--set material\[steel\]\.fy: expected a positive number"):
        plastica.run(ring, overrides={"material[steel].fy": -1.0})


def test_runs_release_the_gil_and_run_on_threads(source):
    scene = source / "models/ring_distributed.toml"
    alone = plastica.run(scene)
    # While a run goes on in another thread, this one keeps running Python.
    ticks = 0
    worker = threading.Thread(target=plastica.run, args=(scene,))
    worker.start()
    while worker.is_alive():
        ticks += 1
    worker.join()
    assert ticks > 100
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        results = list(pool.map(lambda fy: plastica.run(scene, overrides={"material[1].fy": fy}), [20000.0, 30000.0, 20000.0]))
    assert_same_columns(results[0].curve, results[2].curve)
    assert results[1].curve["load"].max() > results[0].curve["load"].max()
    assert alone.status == "completed"


def test_cantilever_from_a_dict_meets_its_closed_form():
    # A tip load of a hundredth of EI/L², elastic: δ = PL³/3EI within the co-rotational beam's
    # geometric stiffening (a rotation of 1/200 rad: 1e-5 of δ) and the 1e-6 residual tolerance.
    E, b, h, L, P = 2.1e8, 0.1, 0.2, 3.0, 1.0
    EI = E * b * h**3 / 12
    load = 0.01 * EI / L**2
    scene = {
        "scene": {"name": "cantilever", "title": "Cantilever from Python"},
        "material": [{"name": "steel", "E": E, "fy": 2.35e5}],
        "section": [{"name": "s", "material": "steel", "shape": "rectangle", "b": b, "h": h, "plasticity": "none"}],
        "line": [{"name": "beam", "start": [0.0, 0.0], "end": [L, 0.0], "elements": 10, "section": "s"}],
        "support": [{"at": [0.0, 0.0], "fix": ["ux", "uy", "rz"]}],
        "load": [{"at": [L, 0.0], "fy": -load}],
        "analysis": {"scheme": "load_control", "increment": 0.5, "target_load_factor": P},
    }
    r = plastica.run(scene)
    assert r.status == "completed", r.reason
    tip = r.step(-1).point["displacement"][-1]
    assert tip[1] == pytest.approx(-load * L**3 / (3 * EI), rel=1e-4)
    # The shear is (moment_j − moment_i)/L of the reported end moments, and equals the tip load
    # in every element; the moment grows linearly from the tip to P·L at the clamp (a hogging
    # moment, negative in the reported convention).
    cells = r.step(-1).cell
    element = L / 10
    assert cells["shear"] == pytest.approx((cells["moment_j"] - cells["moment_i"]) / element, rel=1e-4)
    assert np.abs(cells["shear"]) == pytest.approx(load, rel=1e-4)
    assert abs(cells["moment_i"][0]) == pytest.approx(load * L, rel=1e-4)


def test_chart_and_pictures(source, tmp_path):
    import matplotlib.image
    r = plastica.run(source / "models/ring_elastic.toml", overrides={"analysis.target_displacement": 20.0})
    png = r._repr_png_()
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    (tmp_path / "chart.png").write_bytes(png)
    chart = matplotlib.image.imread(tmp_path / "chart.png")
    assert chart.std() > 0.05  # a curve and axes, not a blank page
    plastica.render(r, tmp_path / "pictures", size=(320, 180), options=["--no-animation"])
    frames = sorted((tmp_path / "pictures" / "frames").glob("frame_*.png"))
    assert len(frames) == r.steps
    last = matplotlib.image.imread(frames[-1])
    assert last.shape[:2] == (180, 320) and last.std() > 0.05


def test_a_sweeps_table_reads_as_numpy(source, binary, tmp_path):
    subprocess.run([binary, "sweep", str(source / "models/ring_elastic.toml"), "--vary", "analysis.target_displacement=10,20",
                    "--no-charts", "-o", str(tmp_path)], check=True, capture_output=True)
    table = plastica.read_table(tmp_path / "sweep.csv")
    assert table["peak_load"].dtype == float and len(table["peak_load"]) == 2
    assert table["peak_load"][1] > table["peak_load"][0]


def test_curve_as_a_dataframe(source):
    pandas = pytest.importorskip("pandas")
    r = plastica.run(source / "models/ring_elastic.toml", overrides={"analysis.target_displacement": 10.0})
    frame = r.dataframe()
    assert isinstance(frame, pandas.DataFrame)
    assert frame["load"].tolist() == r.curve["load"].tolist()


def test_eight_threads_writing_one_folder_leave_one_runs_files(source, tmp_path):
    # The folder is one writer's own while it writes: the others are refused, naming the holder,
    # and what is there afterwards is one run's series, whole.
    result = plastica.run(str(source / "models" / "ring_elastic.toml"))
    folder = tmp_path / "out"
    start = threading.Barrier(8)

    def write(_):
        start.wait()
        try:
            result.write(str(folder))
            return "written"
        except RuntimeError as e:
            return str(e)

    with concurrent.futures.ThreadPoolExecutor(8) as pool:
        outcomes = list(pool.map(write, range(8)))
    assert outcomes.count("written") >= 1
    for refused in (o for o in outcomes if o != "written"):
        assert "is in use by process" in refused and "a Python Result.write" in refused
    rows = (folder / "curve.csv").read_text().splitlines()
    assert len(rows) == len(result.curve["load"]) + 1
    assert len(list((folder / "vtu").glob("step_*.vtu"))) == len(result.curve["load"])
