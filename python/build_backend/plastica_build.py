"""The build backend of `pip install ./python` (PEP 517), written out in full so that building
needs nothing beyond the Python that runs pip, CMake and a compiler: no setuptools, no download.

It builds the extension `_plastica` for the running interpreter with the repository's CMake and
packs it into a wheel with the package's Python files and the `plastica-draw` program (every
command, pictures included), which the module runs for `render`, `section`, `study`, `sweep` and
`compare`.

Where it builds: PLASTICA_BUILD_DIR (or `--config-settings build-dir=…`) if set; else `build/` of
the repository, the one `make` configures, where it holds an extension of this interpreter's ABI
(a venv of Debian's Python); else `build-python-<cache tag>/` beside it, configured for this
interpreter, so that `build/` stays make's.
"""

import base64
import hashlib
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import zipfile
from pathlib import Path

_PYTHON_DIR = Path(__file__).resolve().parent.parent
_REPOSITORY = _PYTHON_DIR.parent
_NAME = "plastica"


def _version():
    text = (_REPOSITORY / "CMakeLists.txt").read_text(encoding="utf-8")
    match = re.search(r"project\(plastica VERSION ([0-9.]+)", text)
    return match.group(1) if match else "0"


def _metadata():
    return (
        "Metadata-Version: 2.1\n"
        f"Name: {_NAME}\n"
        f"Version: {_version()}\n"
        "Summary: Co-rotational beam-columns with plastic hinges, fibre members and unilateral contact\n"
        "Requires-Python: >=3.8\n"
        "Requires-Dist: numpy\n"
    )


def _tag():
    """The wheel's tag for this interpreter: cp311-cp311-linux_x86_64 and the like."""
    if sys.implementation.name != "cpython":
        raise RuntimeError(f"plastica builds for CPython; this is {sys.implementation.name}")
    version = f"cp{sys.version_info[0]}{sys.version_info[1]}"
    abi = version + (sys.abiflags if hasattr(sys, "abiflags") else "")
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"{version}-{abi}-{platform}"


def _run(command):
    print("plastica build:", " ".join(str(c) for c in command), file=sys.stderr, flush=True)
    subprocess.run([str(c) for c in command], check=True, stdout=sys.stderr)


def _configure(build, python, tests):
    generator = ["-G", "Ninja"] if shutil.which("ninja") and not (build / "CMakeCache.txt").exists() else []
    options = [] if tests else ["-DPLASTICA_TESTS=OFF"]
    _run(["cmake", "-S", _REPOSITORY, "-B", build, *generator, "-DCMAKE_BUILD_TYPE=Release", f"-DPython_EXECUTABLE={python}", *options])


def _built_module(build):
    return build / "python" / _NAME / f"_plastica{sysconfig.get_config_var('EXT_SUFFIX')}"


def _build(config_settings):
    """Builds the extension for this interpreter and plastica-draw; returns the build folder."""
    if not (_REPOSITORY / "CMakeLists.txt").exists():
        raise RuntimeError("pip install ./python builds from the repository: run it from the repository root")
    settings = config_settings or {}
    chosen = settings.get("build-dir") or os.environ.get("PLASTICA_BUILD_DIR")
    targets = ["--target", "_plastica", "plastica-draw"]
    jobs = ["-j", str(os.cpu_count() or 1)]
    if chosen:
        build = Path(chosen).resolve()
        if not (build / "CMakeCache.txt").exists():
            _configure(build, sys.executable, tests=False)
        _run(["cmake", "--build", build, *targets, *jobs])
        if _built_module(build).exists():
            return build
    # make's build/ where it serves this interpreter's ABI (a venv of Debian's Python), else a
    # build of this interpreter's own beside it: build/ stays make's.
    main = _REPOSITORY / "build"
    if not chosen and (main / "CMakeCache.txt").exists():
        _run(["cmake", "--build", main, *targets, *jobs])
        if _built_module(main).exists():
            return main
    build = _REPOSITORY / f"build-python-{sys.implementation.cache_tag}"
    _configure(build, sys.executable, tests=False)
    _run(["cmake", "--build", build, *targets, *jobs])
    if not _built_module(build).exists():
        raise RuntimeError(f"the build in {build} made no {_built_module(build).name}")
    return build


def _record_line(name, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{name},sha256={digest},{len(data)}"


def _write_dist_info(directory):
    info = Path(directory) / f"{_NAME}-{_version()}.dist-info"
    info.mkdir(parents=True, exist_ok=True)
    (info / "METADATA").write_text(_metadata(), encoding="utf-8")
    return info.name


# PEP 517 hooks.

def get_requires_for_build_wheel(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    return _write_dist_info(metadata_directory)


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    build = _build(config_settings)
    package = build / "python" / _NAME
    locations = 'import os\n# The program that draws, shipped in the wheel beside the module.\n' \
                'DRAWING_PROGRAM = os.path.join(os.path.dirname(__file__), "bin", "plastica-draw")\n'
    files = [(f"{_NAME}/{source.name}", source.read_bytes(), 0o644) for source in sorted(package.glob("*.py"))
             if source.name != "_locations.py"]
    files += [
        (f"{_NAME}/_locations.py", locations.encode(), 0o644),
        (f"{_NAME}/{_built_module(build).name}", _built_module(build).read_bytes(), 0o755),
        (f"{_NAME}/bin/plastica-draw", (build / "cli" / "plastica-draw").read_bytes(), 0o755),
    ]
    info = f"{_NAME}-{_version()}.dist-info"
    tag = _tag()
    wheel_text = f"Wheel-Version: 1.0\nGenerator: plastica_build\nRoot-Is-Purelib: false\nTag: {tag}\n"
    files += [(f"{info}/METADATA", _metadata().encode(), 0o644), (f"{info}/WHEEL", wheel_text.encode(), 0o644)]
    record = "\n".join(_record_line(name, data) for name, data, _ in files) + f"\n{info}/RECORD,,\n"
    files.append((f"{info}/RECORD", record.encode(), 0o644))
    wheel_name = f"{_NAME}-{_version()}-{tag}.whl"
    with zipfile.ZipFile(Path(wheel_directory) / wheel_name, "w", zipfile.ZIP_DEFLATED) as wheel:
        for name, data, mode in files:
            entry = zipfile.ZipInfo(name, date_time=(2020, 1, 1, 0, 0, 0))
            entry.external_attr = (0o100000 | mode) << 16
            entry.compress_type = zipfile.ZIP_DEFLATED
            wheel.writestr(entry, data)
    return wheel_name
