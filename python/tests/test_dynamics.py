"""Motion in time from Python: a transient run's time and energy columns, and the modes equal to
`plastica modes`' to the printed digits."""
import subprocess

import numpy as np
import pytest

import plastica


def test_modes_equal_the_command_lines(source, binary, tmp_path):
    scene = source / "models" / "gallery" / "frame_shaken.toml"
    subprocess.run([binary, "modes", str(scene), "-n", "3", "-q", "--no-render", "-o", str(tmp_path)], check=True)
    table = plastica.read_table(tmp_path / "modes.csv")
    found = plastica.modes(scene, count=3)
    assert [m["mode"] for m in found] == [1, 2, 3]
    for k, m in enumerate(found):
        assert m["period"] == pytest.approx(table["period"][k], rel=1e-9)
        assert m["effective_mass_x"] == pytest.approx(table["effective_mass_x"][k], rel=1e-9, abs=1e-12)
    assert found[0]["share_x"] > 0.99
    assert found[0]["shape"].shape == (21, 3)
    # Under gravity (step 4, its last static step) the sway is slower: P-Δ.
    assert plastica.modes(scene, count=1, step=4)[0]["period"] > found[0]["period"]
    with pytest.raises(RuntimeError, match="before step 100000"):
        plastica.modes(scene, count=1, step=100000)


def test_a_run_in_time_reports_time_and_balanced_energy(source):
    result = plastica.run(source / "models" / "gallery" / "pipe_dropped.toml")
    curve = result.curve
    assert curve["time"][-1] == pytest.approx(0.02)
    assert np.all(np.diff(curve["time"]) > 0)
    assert max(curve["energy_error"]) < 1e-4
    assert curve["plastic_dissipation"][-1] > 0.3 * curve["kinetic_energy"][0]
