"""stable_solver.py with one fault planted: the release root as printed,
(A.25), which cancels where u >> sqrt(phi) dy. An example of a wrong solver
for check_python.py."""
import math
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).parent))
import stable_solver  # noqa: E402


def solve(u, dy, phi):
    s, which = stable_solver.solve(u, dy, phi)
    if which == 4:
        s = -u / 2 + math.sqrt(u * u + 4 * phi * dy * dy) / 2
    return s, which
