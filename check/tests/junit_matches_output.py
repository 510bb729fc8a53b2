#!/usr/bin/env python3
"""junit_matches_output.py JUNIT -- COMMAND...: runs contact-check, then checks that
the JUnit file is well-formed XML with one testcase per property the command
printed, failed exactly where the command printed FAIL."""
import subprocess
import sys
import xml.etree.ElementTree as ET

junit, command = sys.argv[1], sys.argv[sys.argv.index("--") + 1:]
run = subprocess.run(command, capture_output=True, text=True)
print(run.stdout, run.stderr)
printed = {}
for line in run.stdout.splitlines():
    fields = line.split()
    if len(fields) > 1 and fields[0] in ("ok", "FAIL") and "trials" in line:
        printed[fields[1]] = fields[0] == "FAIL"
cases = ET.parse(junit).getroot().findall("./testsuite/testcase")
written = {case.get("name"): case.find("failure") is not None for case in cases}
assert len(cases) == len(written), "a property has two testcases"
assert printed, "contact-check printed no property"
assert written == printed, f"JUnit {written} differs from the output {printed}"
print(f"{len(cases)} testcases, {sum(written.values())} failed, as printed")
