"""Linear buckling and critical points from Python, against the command line."""
import subprocess

import numpy as np
import pytest

import plastica


def test_buckling_equals_the_command_lines(source, binary, tmp_path):
    scene = source / "models" / "gallery" / "roorda_frame.toml"
    subprocess.run([binary, "buckling", str(scene), "-n", "2", "-q", "--no-render", "-o", str(tmp_path)], check=True)
    table = plastica.read_table(tmp_path / "buckling.csv")
    found = plastica.buckling(scene, count=2)
    assert [m["mode"] for m in found] == [1, 2]
    for k, m in enumerate(found):
        assert m["load_factor"] == pytest.approx(table["load_factor"][k], rel=1e-9)
    # Roorda's 13.8859 EI/L² (20 elements a member).
    assert found[0]["load_factor"] == pytest.approx(13.8859, rel=3e-3)
    assert np.max(np.hypot(found[0]["shape"][:, 0], found[0]["shape"][:, 1])) == pytest.approx(1.0)


def test_a_bifurcation_is_in_the_curve_and_followed(source):
    result = plastica.run(source / "models" / "gallery" / "roorda_frame.toml")
    kinds = result.curve["critical_point"]
    steps = [k for k, kind in enumerate(kinds) if kind == "bifurcation"]
    assert steps == [1]
    assert result.curve["critical_load_factor"][1] == pytest.approx(13.9186, rel=1e-4)
    assert np.isnan(result.curve["critical_load_factor"][2])
