#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Proves scripts/check_tautologies.py fails on each kind of test that cannot
fail (an always-true lambda, `else True`, `assert True`, EXPECT_TRUE(true), a
skip or DISABLED_ test without an issue named) and passes the same tree with
those lines fixed or their skips explained."""
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(sys.argv[1])
CHECK = ROOT / "scripts" / "check_tautologies.py"
# (file, refused line, accepted line)
CASES = [
    ("tests/server/a_test.py", "    assert wait_until(lambda: True, 0)\n", "    assert wait_until(lambda: done(), 5)\n"),
    ("python/tests/b_test.py", '    assert x < 1 if "rms" in after else True\n', '    assert "rms" in after and x < 1\n'),
    ("python/tests/c_test.py", "    assert True\n", "    assert value is True\n"),
    ("tests/d/d_test.cpp", "  EXPECT_TRUE(true);\n", "  EXPECT_TRUE(ok);\n"),
    ("tests/e/e_test.cpp", "TEST(A, DISABLED_B) {}\n", "// By hand (issue 14): prints a table.\nTEST(A, DISABLED_B) {}\n"),
    ("web/e2e/f.spec.ts", "  test.skip(env === '0', 'no routes yet');\n",
     "  test.skip(env === '0', 'no routes yet (issue 12)');\n"),
    ("web/src/g/g.test.ts", "it.skip('draws', () => {});\n", "it('draws', () => { expect(x).toBe(1); });\n"),
    ("python/tests/h_test.py", "@pytest.mark.skip\n", "@pytest.mark.skipif(not HAVE_MPI, reason='needs MPI (issue 9)')\n"),
]


def run(root):
    return subprocess.run([sys.executable, str(CHECK), "--root", str(root)], capture_output=True, text=True)


def main():
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        for rel, _, _ in CASES:
            (root / rel).parent.mkdir(parents=True, exist_ok=True)
        for rel, bad, _ in CASES:
            for other, _, good in CASES:
                (root / other).write_text(good)
            (root / rel).write_text(bad)
            r = run(root)
            if r.returncode != 1 or rel not in r.stdout:
                failures.append(f"{rel}: not refused ({r.returncode}): {r.stdout}")
        for rel, _, good in CASES:
            (root / rel).write_text(good)
        r = run(root)
        if r.returncode != 0:
            failures.append(f"clean tree refused: {r.stdout}")
    for f in failures:
        print(f)
    print(f"tautology_violation_test: {len(CASES)} cases, {len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
