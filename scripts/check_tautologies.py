#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Tests that cannot fail (STYLE.md, BRIEF "What done means"): no test file
holds an assertion that is true whatever the code does, nor a skip that can
hide a failure without saying why.

Refused, line by line in the test files (tests/, python/tests/, web/e2e/ and
web/src/**/*.test.ts; comments are skipped):
  - `lambda: True` (a wait or a check that holds at once)
  - `else True` (an assertion that holds whenever its condition is false)
  - `assert True`, `EXPECT_TRUE(true)`, `ASSERT_TRUE(true)`, `expect(true)`
  - a skipped test — `test.skip`, `it.skip`, `describe.skip`, `test.fixme`,
    `pytest.mark.skip`, `pytest.skip(`, a gtest `DISABLED_` — without a reason
    naming an issue ("issue N") on its line, the 3 lines before it or the 3
    after it (a skip that stays must say which issue keeps it)
Usage: check_tautologies.py [--root DIR]; exit 0 when clean, 1 with one line per finding.
"""
import argparse
import pathlib
import re
import sys

ALWAYS = [
    (re.compile(r"\blambda\s*:\s*True\b"), "a lambda that is always True"),
    (re.compile(r"\belse\s+True\b"), "`else True`: holds whenever the condition is false"),
    (re.compile(r"^\s*assert\s+True\b"), "`assert True`"),
    (re.compile(r"\b(EXPECT|ASSERT)_TRUE\(\s*true\s*\)"), "EXPECT_TRUE(true)"),
    (re.compile(r"\bexpect\(\s*true\s*\)"), "expect(true)"),
]
SKIP = re.compile(r"\b(test|it|describe)\.(skip|fixme)\b|\bpytest\.mark\.skip\b|\bpytest\.skip\(|\bDISABLED_\w+")
ISSUE = re.compile(r"\bissues?\s+#?\d+", re.IGNORECASE)
CONTEXT = 3


def test_files(root: pathlib.Path):
    for base in ("tests", "python/tests", "web/e2e"):
        d = root / base
        if d.is_dir():
            for p in sorted(d.rglob("*")):
                if p.suffix in (".py", ".cpp", ".hpp", ".ts") and p.is_file() and "node_modules" not in p.parts:
                    yield p
    src = root / "web" / "src"
    if src.is_dir():
        yield from sorted(p for p in src.rglob("*.test.ts") if "node_modules" not in p.parts)


def is_comment(line: str, suffix: str) -> bool:
    s = line.lstrip()
    return s.startswith("#") if suffix == ".py" else s.startswith(("//", "*", "/*"))


def findings(root: pathlib.Path):
    for path in test_files(root):
        rel = path.relative_to(root).as_posix()
        if rel == "tests/layering/tautology_violation_test.py":
            continue  # holds the refused lines as data
        lines = path.read_text(errors="replace").splitlines()
        for i, line in enumerate(lines):
            if is_comment(line, path.suffix):
                continue
            for pattern, why in ALWAYS:
                if pattern.search(line):
                    yield f"{rel}:{i + 1}: {why}: {line.strip()}"
            if SKIP.search(line):
                around = "\n".join(lines[max(0, i - CONTEXT):i + CONTEXT + 1])
                if not ISSUE.search(around):
                    yield f"{rel}:{i + 1}: a skipped test without a reason naming an issue: {line.strip()}"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", default=pathlib.Path(__file__).resolve().parent.parent, type=pathlib.Path)
    root = parser.parse_args().root
    found = list(findings(root))
    for f in found:
        print(f)
    print(f"check_tautologies: {len(found)} finding(s)")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
