#!/usr/bin/env python3
"""Check the internal links and section references of the project's documentation.

usage: python3 docs/check_links.py ROOT

For README.md, CONTRIBUTING.md, docs/*.md and the folder READMEs listed in FILES:
  - every relative markdown link [text](target) names a file or folder that exists;
  - every #anchor of such a link (or of a link within the file) is a heading of the
    target file, as GitHub turns headings into anchors;
  - every "section N", "sections N and M" or "§N" names a numbered heading (## N. or
    ### N.M) of the file it refers to: the last .md file named before it in the same
    paragraph, or the file itself when that has numbered headings;
  - every back-quoted path under a top-level folder of the project, or under a folder
    of the file's own folder, exists (with or without its extension).
Prints one line FILE:LINE: reason per problem and exits 1 if there is any.
"""
import glob
import os
import re
import sys

# the files checked, relative to ROOT; docs/*.md is added by glob
FILES = ["README.md", "CONTRIBUTING.md", "report/README.md", "check/README.md",
         "tests/README.md", "solver/README.md", "proofs/README.md"]

LINK = re.compile(r"(?<!!)\[([^\]]*)\]\(([^)\s]+)\)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
NUMBERED = re.compile(r"^(\d+(?:\.\d+)*)\.?\s")
FILE_NAME = re.compile(r"[\w./-]*\w\.md\b")
# "section 4", "sections 3 and 6", "sections 3.4, 5 and 6", "§4", "§§ 3-4" is not used
SECTION = re.compile(r"(?:\bsections?|§)\s*(\d+(?:\.\d+)*(?:(?:\s*,\s*|\s+and\s+|\s*-\s*)\d+(?:\.\d+)*)*)",
                     re.IGNORECASE)
CODE = re.compile(r"`([^`\n]+)`")
SECTION_OF = re.compile(r"\s+of\s+`?([\w./-]*\w\.md)\b")
# written by runs, not committed
GENERATED = ("report/out", "coverage/out")


def slug(title):
    """GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens."""
    title = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", title)
    title = title.strip().lower()
    title = re.sub(r"[^\w\- ]", "", title)
    return title.replace(" ", "-")


def headings(path):
    """(anchors, section numbers) of a markdown file, outside fenced code."""
    anchors, numbers, seen = set(), set(), {}
    fenced = False
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.lstrip().startswith("```"):
                fenced = not fenced
                continue
            match = None if fenced else HEADING.match(line)
            if not match:
                continue
            title = match.group(2)
            anchor = slug(title)
            count = seen.get(anchor, 0)
            seen[anchor] = count + 1
            anchors.add(anchor if count == 0 else f"{anchor}-{count}")
            number = NUMBERED.match(title)
            if number:
                numbers.add(number.group(1))
    return anchors, numbers


def paragraphs(lines):
    """(first line number, text) of each paragraph, fenced code left out."""
    block, start, fenced = [], 0, False
    for number, line in enumerate(lines, 1):
        if line.lstrip().startswith("```"):
            fenced = not fenced
            continue
        if fenced:
            continue
        if line.strip():
            if not block:
                start = number
            block.append(line.rstrip("\n"))
        elif block:
            yield start, block
            block = []
    if block:
        yield start, block


def expand(numbers):
    """'3, 5 and 6' -> ['3', '5', '6']; '3-5' -> ['3', '4', '5']."""
    parts = re.split(r"\s*,\s*|\s+and\s+", numbers)
    result = []
    for part in parts:
        if "-" in part:
            low, high = (p.strip() for p in part.split("-", 1))
            if low.isdigit() and high.isdigit():
                result += [str(n) for n in range(int(low), int(high) + 1)]
                continue
        result.append(part.strip())
    return result


def main(root):
    root = os.path.abspath(root)
    files = [f for f in FILES if os.path.exists(os.path.join(root, f))]
    docs = os.path.join(root, "docs")
    files += sorted("docs/" + f for f in os.listdir(docs) if f.endswith(".md"))
    top_folders = {e for e in os.listdir(root) if os.path.isdir(os.path.join(root, e)) and not e.startswith(".")}
    top_folders |= {".ci", ".github", ".clusterfuzzlite"}
    cache = {}

    def info(path):
        if path not in cache:
            cache[path] = headings(path)
        return cache[path]

    problems = []
    for name in files:
        path = os.path.join(root, name)
        here = os.path.dirname(path)
        with open(path, encoding="utf-8") as f:
            lines = f.readlines()
        for start, block in paragraphs(lines):
            text = "\n".join(block)

            def line_of(offset):
                return start + text.count("\n", 0, offset)

            # links
            for match in LINK.finditer(text):
                target = match.group(2)
                if re.match(r"^[a-z][a-z0-9+.-]*:", target):  # http:, https:, mailto:
                    continue
                file_part, _, anchor = target.partition("#")
                target_path = os.path.normpath(os.path.join(here, file_part)) if file_part else path
                where = f"{name}:{line_of(match.start())}"
                if not target_path.startswith(root):
                    problems.append(f"{where}: link {target} leaves the repository")
                    continue
                if not os.path.exists(target_path):
                    problems.append(f"{where}: link {target}: no such file")
                    continue
                if anchor:
                    if not target_path.endswith(".md"):
                        problems.append(f"{where}: link {target}: anchor into a file that is not markdown")
                    elif anchor not in info(target_path)[0]:
                        problems.append(f"{where}: link {target}: no heading with anchor #{anchor}")
            # section references: to the last .md named before them in the paragraph
            events = [(m.start(), "file", m.group(0)) for m in FILE_NAME.finditer(text)]
            events += [(m.start(), "section", m) for m in SECTION.finditer(text)]
            named = None
            for offset, kind, value in sorted(events, key=lambda e: e[0]):
                if kind == "file":
                    named = value
                    continue
                of = SECTION_OF.match(text, value.end())  # "section 7 of docs/equations.md"
                value, file_named = value.group(1), of.group(1) if of else named
                where = f"{name}:{line_of(offset)}"
                if file_named is None:
                    target_path = path
                else:
                    candidates = [os.path.normpath(os.path.join(here, file_named)), os.path.join(root, file_named),
                                  os.path.join(root, "docs", os.path.basename(file_named))]
                    target_path = next((c for c in candidates if os.path.exists(c)), None)
                    if target_path is None:
                        problems.append(f"{where}: section {value} of {file_named}: no such file")
                        continue
                numbers = info(target_path)[1]
                if not numbers:
                    problems.append(f"{where}: section {value}: {os.path.relpath(target_path, root)} has no "
                                    "numbered sections (name the file the section is in)")
                    continue
                for number in expand(value):
                    if number not in numbers:
                        problems.append(f"{where}: section {number} of {os.path.relpath(target_path, root)}: "
                                        "no such section")
            # back-quoted paths under the project's folders
            for match in CODE.finditer(text):
                code = match.group(1).strip()
                if " " in code or not re.fullmatch(r"[\w./+-]+", code) or "/" not in code:
                    continue
                first = code.split("/", 1)[0]
                local = here != root and os.path.isdir(os.path.join(here, first))
                if (first not in top_folders and not local) or code.startswith(GENERATED):
                    continue
                bases = [root, here] if local else [root]
                # a name without its extension (an obligation, a program) counts too
                if not any(os.path.exists(os.path.join(base, code.rstrip("/"))) or
                           glob.glob(glob.escape(os.path.join(base, code)) + ".*") for base in bases):
                    problems.append(f"{name}:{line_of(match.start())}: path `{code}`: no such file or folder")
    for problem in problems:
        print(problem)
    if problems:
        print(f"{len(problems)} broken link(s) or reference(s)")
        return 1
    print(f"checked {len(files)} files: every link and section reference resolves")
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    sys.exit(main(sys.argv[1]))
