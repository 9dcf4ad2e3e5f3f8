"""Every command from Python on the same Result API: plastica.open of a folder equals the run it
came from, arrays to the bit; a Result pickles; section, study, sweep and compare return their
tables, and a sweep's bad plan is refused before any run."""
import concurrent.futures
import os
import pickle

import numpy as np
import pytest

import plastica


def assert_same_steps(a, b):
    assert a.steps == b.steps
    for k in range(a.steps):
        x, y = a.step(k), b.step(k)
        assert np.array_equal(x.points, y.points) and np.array_equal(x.lines, y.lines)
        for group in ("point", "cell"):
            p, q = getattr(x, group), getattr(y, group)
            assert list(p) == list(q)
            for name in p:
                assert p[name].dtype == q[name].dtype and np.array_equal(p[name], q[name]), name
        assert list(x.field) == list(y.field)
        for name in x.field:
            assert np.array_equal(np.asarray(x.field[name]), np.asarray(y.field[name])), name


def assert_same_curve(a, b):
    assert list(a.curve) == list(b.curve)
    for name in a.curve:
        assert np.array_equal(a.curve[name], b.curve[name], equal_nan=a.curve[name].dtype.kind == "f"), name


@pytest.mark.parametrize("compression", ["none", "lz4", "zlib"])
def test_an_opened_folder_equals_the_run_to_the_bit(source, binary, tmp_path, compression):
    import subprocess
    scene = source / "models/ring_inelastic.toml"
    subprocess.run([binary, "run", str(scene), "--no-render", "-q", "--compression", compression, "-o", str(tmp_path)], check=True)
    opened, run = plastica.open(tmp_path), plastica.run(scene)
    assert (opened.status, opened.reason) == (run.status, run.reason)
    assert_same_curve(opened, run)
    assert_same_steps(opened, run)
    assert opened.report["steps"] == run.report["steps"]


def test_a_written_result_opens_as_itself(source, tmp_path):
    run = plastica.run(source / "models/ring_elastic.toml")
    opened = plastica.open(run.write(tmp_path / "ring"))
    assert_same_curve(opened, run)
    assert_same_steps(opened, run)


def test_results_pickle_and_cross_a_process_pool(source, tmp_path):
    run = plastica.run(source / "models/cantilever_tip_load.toml")
    copy = pickle.loads(pickle.dumps(run))
    assert_same_curve(copy, run)
    assert_same_steps(copy, run)
    # An opened folder pickles as its folder.
    opened = plastica.open(run.write(tmp_path / "c"))
    assert_same_steps(pickle.loads(pickle.dumps(opened)), run)
    with concurrent.futures.ProcessPoolExecutor(max_workers=2) as pool:
        results = list(pool.map(plastica.run, [source / "models/cantilever_tip_load.toml"] * 2))
    for r in results:
        assert_same_curve(r, run)


def test_open_refuses_a_folder_that_reaches_outside(source, tmp_path):
    run = plastica.run(source / "models/cantilever_tip_load.toml")
    folder = run.write(tmp_path / "crafted")
    os.remove(folder / "run.json")
    os.symlink("/etc/passwd", folder / "run.json")
    with pytest.raises(ValueError, match="run.json"):
        plastica.open(folder)
    os.remove(folder / "run.json")
    run.write(tmp_path / "crafted")
    pvd = next(folder.glob("*.pvd"))
    pvd.write_text(pvd.read_text().replace('file="vtu/step_000000.vtu"', 'file="../../../etc/passwd"'))
    with pytest.raises(ValueError, match="not a file inside the folder"):
        plastica.open(folder)
    # A step file that is not what its tags say is refused with the reason, not read past its end.
    run.write(tmp_path / "cut")
    step = tmp_path / "cut" / "vtu" / "step_000001.vtu"
    step.write_bytes(step.read_bytes()[:-200])
    with pytest.raises(ValueError, match="step_000001.vtu"):
        plastica.open(tmp_path / "cut").step(1)


def test_section_gives_its_capacity_and_moment_curvature(source):
    s = plastica.section(source / "models/ring_inelastic.toml", "ring")
    # The ring's rectangle in 10 layers: squash load fy·b·h, and at N = 0 the full plastic moment
    # fy·b·h²/4, exact for an even number of layers.
    fy, b, h = 36518.0, 9.128709291752768, 0.010954451150103323
    n = s.capacity["axial_force"]
    assert n[0] == pytest.approx(-fy * b * h, rel=1e-12) and n[-1] == pytest.approx(fy * b * h, rel=1e-12)
    mid = len(n) // 2
    assert n[mid] == pytest.approx(0.0, abs=1e-9 * abs(n[0]))
    assert s.capacity["moment_positive"][mid] == pytest.approx(fy * b * h * h / 4.0, rel=1e-9)
    assert s.moment_curvature["moment"].max() <= s.capacity["moment_positive"].max() * (1 + 1e-9)


def test_study_and_sweep_return_their_tables_and_runs(source, tmp_path):
    study = plastica.study(source / "models/cantilever_tip_load.toml", {"elements": [4, 8]}, folder=tmp_path / "study")
    assert list(study["level"]) == [4.0, 8.0]
    # The error falls with the mesh.
    assert study["max_error"][1] < study["max_error"][0]
    sweep = plastica.sweep(source / "models/cantilever_tip_load.toml", {"analysis.increment": [0.1, 0.2]}, folder=tmp_path / "sweep",
                           run_output="series")
    assert list(sweep["id"]) == ["r0001", "r0002"]
    assert list(sweep["status"]) == ["completed", "completed"]
    run = sweep.run("r0002")
    assert run.status == "completed" and run.steps > 1
    assert run.curve["load"].max() == sweep["peak_load"][1]


def test_a_bad_plan_is_refused_before_any_run(source, tmp_path):
    with pytest.raises(plastica.SceneError, match=r"analysis.scheme = bogus in runs r0003, r0004"):
        plastica.sweep(source / "models/cantilever_tip_load.toml",
                       {"analysis.scheme": ["load_control", "bogus"], "analysis.increment": [0.1, 0.2]}, folder=tmp_path / "bad")
    assert not (tmp_path / "bad" / "runs").exists()
    with pytest.raises(plastica.SceneError, match="comma"):
        plastica.sweep(source / "models/cantilever_tip_load.toml", {"scene.title": ["a,b"]}, folder=tmp_path / "comma")


def test_compare_gives_each_pictures_verdict(source, tmp_path):
    reference = source / "tests/snapshots/ring_elastic/chart.png"
    same = plastica.compare(reference, reference)
    assert same["passed"] and same["pictures"]["chart.png"]["differing_fraction"] == 0.0
    differ = plastica.compare(source / "tests/snapshots/ring_inelastic/chart.png", reference)
    assert not differ["passed"]
    assert differ["pictures"]["chart.png"]["differing_fraction"] > 0.001
    with pytest.raises(plastica.SceneError, match="size mismatch"):
        plastica.compare(source / "tests/snapshots/ring_inelastic/contact_sheet.png", source / "tests/snapshots/ring_elastic/contact_sheet.png")


def test_messages_name_the_key_and_suggest_the_nearest(source):
    # An override's error begins with the override, as on the command line, and suggests a name.
    with pytest.raises(plastica.SceneError, match=r"^--set material\[stel\]\.fy: no \[\[material\]\] named 'stel'; did you mean 'steel'\?"):
        plastica.run(source / "models/ring_inelastic.toml", overrides={"material[stel].fy": 1.0})
    # A misspelt key is named beside the missing one it stands for.
    scene = {"scene": {"name": "typo"}, "material": [{"name": "s", "E": 2.1e8, "fy": 3.55e5}],
             "section": [{"name": "I", "material": "s", "shape": "i", "depth": 0.3, "flange_widht": 0.15,
                          "flange_thickness": 0.01, "web_thickness": 0.007}]}
    with pytest.raises(plastica.SceneError, match=r"section\[I\]\.flange_widht: unknown key; did you mean 'flange_width'\? \(missing required key 'flange_width'"):
        plastica.run(scene)
