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


LONG_SDOF = """
[scene]
name = "sdof"
[[material]]
name = "m"
E = 100.0
[[section]]
name = "s"
material = "m"
A = 1.0
I = 1.0
[[line]]
start = [0.0, 0.0]
end = [1.0, 0.0]
elements = 1
section = "s"
[[support]]
at = [0.0, 0.0]
fix = ["ux", "uy", "rz"]
[[support]]
at = [1.0, 0.0]
fix = ["uy", "rz"]
[[mass]]
at = [1.0, 0.0]
m = 1.0
[[initial_velocity]]
at = [1.0, 0.0]
v = [0.01, 0.0]
[analysis]
scheme = "transient"
time_step = 0.001
duration = 5000.0
control_at = [1.0, 0.0]
control_dof = "ux"
"""


def test_ctrl_c_stops_a_long_run_within_a_second_as_keyboard_interrupt(tmp_path):
    # Five million steps (minutes): SIGINT half a second in must end the run between two
    # iterations and reach Python as KeyboardInterrupt.
    script = tmp_path / "long.py"
    script.write_text(
        "import time, plastica\n"
        f"scene = {LONG_SDOF!r}\n"
        "start = time.monotonic()\n"
        "try:\n"
        "    plastica.run(scene)\n"
        "except KeyboardInterrupt:\n"
        "    print('interrupted after', time.monotonic() - start)\n"
    )
    import signal
    import sys
    import time

    process = subprocess.Popen([sys.executable, str(script)], stdout=subprocess.PIPE, text=True)
    time.sleep(1.5)
    sent = time.monotonic()
    process.send_signal(signal.SIGINT)
    out, _ = process.communicate(timeout=30)
    assert time.monotonic() - sent < 1.0
    assert "interrupted after" in out
