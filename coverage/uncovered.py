#!/usr/bin/env python3
"""Lists what llvm-cov's report counts as missed, as file:line.

Reads `llvm-cov show -format=text -show-branches=count -show-instantiations=true`
on stdin. llvm-cov's report counts a function template's lines and branches in
its best instantiation only (the one covering most of them), not the union of
all instantiations: a template is 100% covered only when one instantiation runs
every line and takes every branch both ways. So, per template, this lists the
misses of its best instantiation (and says when another instantiation covers
them); for ordinary code, the lines not run and the branch directions not taken.

Usage: uncovered.py ROOT < show.txt > uncovered.txt
"""
import re
import subprocess
import sys

LINE = re.compile(r"^(?P<bars>(?:  \|)*)\s*(?P<line>\d+)\|\s*(?P<count>[0-9.]+[kMGTPEZY]?)?\|(?P<text>.*)$")
BRANCH = re.compile(r"Branch \((?P<line>\d+):(?P<col>\d+)\): \[True: (?P<t>[^,]+), False: (?P<f>[^\]]+)\]")
SUBVIEW = re.compile(r"^  \| (?P<name>\S+):$")


def nonzero(count):
    return count is not None and count.strip() not in ("", "0")


class View:
    def __init__(self, name=None):
        self.name = name
        self.lines = {}  # line -> count string (code lines only)
        self.branches = []  # (line, col, taken_true, taken_false)

    def missed_lines(self):
        return sorted(l for l, c in self.lines.items() if not nonzero(c))

    def covered_lines(self):
        return sum(1 for c in self.lines.values() if nonzero(c))

    def covered_directions(self):
        return sum(int(t) + int(f) for _, _, t, f in self.branches)


def parse(stream, root):
    files = {}  # file -> (main view, [subviews])
    current = None
    for raw in stream:
        raw = raw.rstrip("\n")
        if raw.startswith("/") and raw.endswith(":"):
            name = raw[:-1]
            if name.startswith(root):
                name = name[len(root):]
            current = files.setdefault(name, (View(), []))
            continue
        if current is None:  # a single file is shown without a header
            current = files.setdefault("(the only file)", (View(), []))
        main, subviews = current
        m = SUBVIEW.match(raw)
        if m:
            subviews.append(View(m.group("name")))
            continue
        m = LINE.match(raw)
        if m:
            depth = len(m.group("bars")) // 3
            view = main if depth == 0 else (subviews[-1] if subviews else main)
            if m.group("count") is not None:
                view.lines[int(m.group("line"))] = m.group("count")
            continue
        m = BRANCH.search(raw)
        if m:
            depth = raw.split("Branch")[0].count("|")
            view = main if depth <= 1 else (subviews[-1] if subviews else main)
            view.branches.append((int(m.group("line")), int(m.group("col")), nonzero(m.group("t")), nonzero(m.group("f"))))
    return files


def demangle(names):
    names = list(names)
    if not names:
        return {}
    for tool in ("llvm-cxxfilt-14", "llvm-cxxfilt", "c++filt"):
        try:
            out = subprocess.run([tool], input="\n".join(names), capture_output=True, text=True, check=True).stdout
            return dict(zip(names, out.splitlines()))
        except (OSError, subprocess.CalledProcessError):
            continue
    return {n: n for n in names}


def main():
    root = sys.argv[1].rstrip("/") + "/" if len(sys.argv) > 1 else ""
    files = parse(sys.stdin, root)
    readable = demangle({v.name for _, subs in files.values() for v in subs})
    out = []
    for name in sorted(files):
        main_view, subviews = files[name]
        # instantiations of one template: subviews starting on the same line
        groups = {}
        for v in subviews:
            if v.lines:
                groups.setdefault(min(v.lines), []).append(v)
        template_lines = {l for v in subviews for l in v.lines}
        for line in main_view.missed_lines():
            if line not in template_lines:
                out.append((name, line, 0, "line not run"))
        seen = set()
        for line, col, t, f in main_view.branches:
            if line in template_lines or (line, col) in seen:
                continue
            seen.add((line, col))
            if not t and not f:
                out.append((name, line, col, "branch never reached"))
            elif not t:
                out.append((name, line, col, "branch never true"))
            elif not f:
                out.append((name, line, col, "branch never false"))
        for start, views in groups.items():
            union_lines = {l for v in views for l, c in v.lines.items() if nonzero(c)}
            union_true = {(l, c) for v in views for l, c, t, _ in v.branches if t}
            union_false = {(l, c) for v in views for l, c, _, f in v.branches if f}
            best = max(views, key=lambda v: v.covered_lines())
            who = readable.get(best.name, best.name)
            tag = f"in {who}, the best of {len(views)} instantiation{'s' if len(views) > 1 else ''}"
            for line in best.missed_lines():
                note = "; another instantiation runs it" if line in union_lines else ""
                out.append((name, line, 0, f"line not run ({tag}{note})"))
            best = max(views, key=lambda v: v.covered_directions())
            who = readable.get(best.name, best.name)
            tag = f"in {who}, the best of {len(views)} instantiation{'s' if len(views) > 1 else ''}"
            for line, col, t, f in best.branches:
                for taken, direction, union in ((t, "true", union_true), (f, "false", union_false)):
                    if not taken:
                        note = "; another instantiation takes it" if (line, col) in union else ""
                        out.append((name, line, col, f"branch never {direction} ({tag}{note})"))
    for name, line, col, what in sorted(set(out), key=lambda x: (x[0], x[1], x[2], x[3])):
        print(f"{name}:{line}:{col}: {what}" if col else f"{name}:{line}: {what}")


if __name__ == "__main__":
    main()
