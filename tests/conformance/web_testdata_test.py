# SPDX-License-Identifier: MIT
# The web tests' kernel reference values (web/src/geometry/testdata/) are what the current `hula` writes:
# generate.sh runs into a scratch folder and every file there must equal the committed one, value for value
# (the committed ones are prettier-formatted, so they are compared parsed: same members, same array lengths,
# equal strings and booleans, numbers within 1e-12 relative (absolute below 1: a torsion of 1e-14 is rounding
# noise whose sign may flip), as rounding of one build against another). A
# kernel change that moves a value makes this fail until generate.sh is run and the new values committed.
# Usage: web_testdata_test.py HULA
import json
import math
import pathlib
import subprocess
import sys
import tempfile

TESTDATA = pathlib.Path(__file__).resolve().parents[2] / "web" / "src" / "geometry" / "testdata"


def differences(a, b, where="$"):
    """Where the parsed JSON values a (written now) and b (committed) differ."""
    if isinstance(a, bool) or isinstance(b, bool) or a is None or b is None or isinstance(a, str):
        return [] if a == b and type(a) is type(b) else [f"{where}: {a!r} now, {b!r} committed"]
    if isinstance(a, (int, float)) and isinstance(b, (int, float)):
        if a == b or (math.isfinite(a) and math.isfinite(b) and abs(a - b) <= 1e-12 * max(abs(a), abs(b), 1.0)):
            return []
        return [f"{where}: {a!r} now, {b!r} committed"]
    if isinstance(a, dict) and isinstance(b, dict):
        if a.keys() != b.keys():
            return [f"{where}: members {sorted(a.keys() ^ b.keys())} only on one side"]
        return [d for k in a for d in differences(a[k], b[k], f"{where}.{k}")]
    if isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            return [f"{where}: {len(a)} elements now, {len(b)} committed"]
        return [d for i, (x, y) in enumerate(zip(a, b)) for d in differences(x, y, f"{where}[{i}]")]
    return [f"{where}: {type(a).__name__} now, {type(b).__name__} committed"]


def main():
    hula = str(pathlib.Path(sys.argv[1]).resolve())
    with tempfile.TemporaryDirectory() as scratch:
        subprocess.run([str(TESTDATA / "generate.sh"), hula, scratch], check=True, timeout=300)
        written = sorted(p.relative_to(scratch) for p in pathlib.Path(scratch).rglob("*.json"))
        # Every committed output (NAME.KIND.json); the curve files generate.sh reads (NAME.json) are inputs.
        committed = sorted(p.relative_to(TESTDATA) for p in TESTDATA.rglob("*.json") if "." in p.stem)
        problems = [f"{p}: committed but not written by generate.sh" for p in committed if p not in written]
        for rel in written:
            if not (TESTDATA / rel).exists():
                problems.append(f"{rel}: written by generate.sh but not committed")
                continue
            now = json.loads((pathlib.Path(scratch) / rel).read_text())
            before = json.loads((TESTDATA / rel).read_text())
            problems += [f"{rel} {d}" for d in differences(now, before)[:5]]
        assert len(written) >= 36, f"generate.sh wrote only {len(written)} files"
    if problems:
        print("web/src/geometry/testdata/ is not what the current hula writes (run generate.sh and commit):")
        print("\n".join(problems[:40]))
        sys.exit(1)
    print(f"{len(written)} reference files equal the current hula's output")


if __name__ == "__main__":
    main()
