"""What a run costs from Python against the command line's whole process, for the rings:
medians of 15 runs each, alternating. Usage: python3 bench/python_overhead.py [BUILD]"""
import statistics
import subprocess
import sys
import time

import plastica

build = sys.argv[1] if len(sys.argv) > 1 else "build"
for scene in ("ring_elastic", "ring_inelastic"):
    path = f"models/{scene}.toml"
    in_python, process = [], []
    for _ in range(15):
        t = time.perf_counter()
        r = plastica.run(path)
        in_python.append(time.perf_counter() - t)
        t = time.perf_counter()
        subprocess.run([f"{build}/cli/plastica", "run", path, "--curves-only", "-q", "--force", "-o", "/tmp/plastica_overhead"], check=True)
        process.append(time.perf_counter() - t)
    analysis = r.report["seconds"]["analysis"]
    print(f"{scene}: plastica.run {1e3 * statistics.median(in_python):.1f} ms (analysis {1e3 * analysis:.1f} ms), "
          f"`plastica run --curves-only` whole process {1e3 * statistics.median(process):.1f} ms")
