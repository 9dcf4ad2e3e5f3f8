# `pip install ./python` into an interpreter of one's own: a venv from Debian's Python that sees
# Debian's numpy, offline (--no-index) and with the in-tree build backend (--no-build-isolation
# works, and so would isolation: it needs no package). The build reuses the build tree of the
# tests (PLASTICA_BUILD_DIR), whose extension serves this ABI.
import os
import subprocess
import sys
import venv


def test_pip_installs_the_module_into_a_venv_that_imports_its_own_copy(source, tmp_path):
    home = tmp_path / "venv"
    venv.create(home, system_site_packages=True, with_pip=True)
    python = home / "bin" / "python"
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env.setdefault("PLASTICA_BUILD_DIR", str(source / "build"))
    install = subprocess.run([python, "-m", "pip", "install", "--no-build-isolation", "--no-index", "--no-cache-dir",
                              str(source / "python")], cwd=source, env=env, capture_output=True, text=True)
    assert install.returncode == 0, install.stdout + install.stderr
    check = subprocess.run(
        [python, "-c", "import plastica, sys; r = plastica.run(sys.argv[1]); print(plastica.__file__); "
                       "print(r.status, r.steps, r.curve['load'][-1])", str(source / "models" / "cantilever_tip_load.toml")],
        cwd=tmp_path, env=env, capture_output=True, text=True)
    assert check.returncode == 0, check.stderr
    where, outcome = check.stdout.strip().splitlines()
    assert where.startswith(str(home)), where
    status, steps, load = outcome.split()
    assert status == "completed" and int(steps) > 1 and float(load) > 0.0
    # The program that draws comes with it.
    drawn = subprocess.run([python, "-c", "import plastica._locations as l, os; print(os.access(l.DRAWING_PROGRAM, os.X_OK), l.DRAWING_PROGRAM)"],
                           cwd=tmp_path, env=env, capture_output=True, text=True)
    runnable, program = drawn.stdout.split()
    assert runnable == "True" and program.startswith(str(home))
