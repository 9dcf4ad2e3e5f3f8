"""Progress: on a terminal (a pseudo-terminal here) `run` and `sweep` draw a bar that reaches
100 % and ends with a newline; off a terminal, plain lines as before; -q silences it; from Python
a callback sees the share done."""
import os
import pty
import subprocess

import pytest

import plastica


def stderr_on_a_terminal(command):
    master, slave = pty.openpty()
    process = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=slave)
    os.close(slave)
    out = b""
    while True:
        try:
            chunk = os.read(master, 65536)
        except OSError:  # the terminal's other end has closed
            break
        if not chunk:
            break
        out += chunk
    os.close(master)
    assert process.wait() == 0
    return out.decode()


def test_run_and_sweep_draw_a_bar_on_a_terminal(source, binary, tmp_path):
    scene = str(source / "models/ring_inelastic.toml")
    text = stderr_on_a_terminal([binary, "run", scene, "--no-render", "-o", str(tmp_path / "run")])
    bar = text.split("\r\x1b[K")[-1].split("\r\n")[0]
    assert bar.startswith("solving [########################] 100 %") and "steps/s" in bar
    assert text.split("\r\x1b[K")[-1].split(bar)[1].startswith("\r\n")  # the bar's line is ended
    text = stderr_on_a_terminal([binary, "sweep", scene, "--vary", "analysis.increment=1,2", "--no-charts", "-o", str(tmp_path / "sweep")])
    bar = text.split("\r\x1b[K")[-1]
    assert bar.startswith("running [########################] 100 %  run 2 of 2") and bar.rstrip(" \r\n").endswith("runs/s")
    assert bar.endswith("\r\n")


def test_off_a_terminal_plain_lines_and_quiet_silences(source, binary, tmp_path):
    scene = str(source / "models/ring_inelastic.toml")
    plain = subprocess.run([binary, "run", scene, "--no-render", "-o", str(tmp_path / "a")], capture_output=True, text=True, check=True)
    lines = [l for l in plain.stderr.splitlines() if l.startswith("solving:")]
    # One line every 20 steps, none redrawn: step 0, 20, …, 200.
    assert len(lines) == 11 and "\r" not in plain.stderr and "[#" not in plain.stderr
    assert lines[-1].startswith("solving: 100 %  step 200")
    quiet = subprocess.run([binary, "run", scene, "--no-render", "-q", "-o", str(tmp_path / "b")], capture_output=True, text=True, check=True)
    assert "solving" not in quiet.stderr


def test_a_python_callback_sees_the_share_done(source):
    seen = []
    r = plastica.run(source / "models/ring_inelastic.toml", progress=lambda *a: seen.append(a))
    steps, shares = [s[0] for s in seen], [s[1] for s in seen]
    assert steps[0] == 0 and steps[-1] == r.steps - 1
    assert shares == sorted(shares) and shares[0] == 0.0 and shares[-1] == 1.0
    assert seen[-1][2] == pytest.approx(r.curve["load"][-1], rel=1e-11)
    assert seen[-1][3] == pytest.approx(r.curve["control_displacement"][-1], rel=1e-11)

    class Enough(Exception):
        pass

    def stop(step, share, load, displacement):
        raise Enough(step)

    with pytest.raises(Enough):
        plastica.run(source / "models/ring_inelastic.toml", progress=stop)
