#!/usr/bin/env python3
"""contact-solve's line protocol for a Python solver of (A.2):

    python3 examples/adapters/check_python.py PATH/TO/mysolver.py

mysolver.py defines solve(u, dy, phi) -> (s, which), which: 1 free, 2 impact,
3 contact, 4 release, 0 invalid input with s = NaN. Standard input holds lines
"u dy phi" (C99 hex floats, as contact-check writes them, or decimals); each
answer is a line "s which" in hex, every bit kept. A line that is not three
numbers stops the adapter with the line's number."""
import importlib.util
import math
import pathlib
import sys


def number(text):
    try:
        return float.fromhex(text) if "0x" in text.lower() else float(text)
    except ValueError:
        return None


def exact(s):
    return s.hex() if math.isfinite(s) else repr(s)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: check_python.py PATH/TO/solver.py")
    path = pathlib.Path(sys.argv[1])
    spec = importlib.util.spec_from_file_location(path.stem, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    out = []
    for number_of_line, line in enumerate(sys.stdin, 1):
        fields = line.split()
        if not fields:
            continue
        values = [number(f) for f in fields]
        if len(values) != 3 or None in values:
            sys.stdout.write("".join(out))
            sys.exit(f"stdin:{number_of_line}: expected \"u dy phi\", got {line.rstrip()!r}")
        s, which = module.solve(*values)
        out.append(f"{exact(float(s))} {int(which)}\n")
    sys.stdout.write("".join(out))


if __name__ == "__main__":
    main()
