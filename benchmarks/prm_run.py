"""Runs rollnip on a benchmark's parameter file: the one piece the
benchmark scripts share.

run_prm(binary, directory, text) appends an Output subsection for
directory/out (emptied first; no VTU, no timing tables) to the .prm text,
writes it to directory/run.prm, runs the binary on it and returns the wall
time [s], the CPU time of the run [s] and the finished process (its
stdout, stderr and returncode).
"""

import os
import resource
import shutil
import subprocess
import time

OUTPUT = """subsection Output
  set Directory = {directory}/out
  set Write VTU = false
  set Print timing = false
end
"""


def run_prm(binary, directory, text):
    shutil.rmtree(os.path.join(directory, "out"), ignore_errors=True)
    prm = os.path.join(directory, "run.prm")
    with open(prm, "w") as f:
        f.write(text + OUTPUT.format(directory=directory))
    t0 = time.perf_counter()
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    p = subprocess.run([binary, prm], capture_output=True, text=True)
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    wall = time.perf_counter() - t0
    cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    return wall, cpu, p
