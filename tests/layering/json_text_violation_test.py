#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Proves scripts/check_json_text.py fails on each kind of in-process JSON text it
refuses (a parse of a dump, a re-parsed body, Json::parse in server/, JSON text
to Python) and passes the same tree without them."""
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(sys.argv[1])
CHECK = ROOT / "scripts" / "check_json_text.py"
CASES = {
    "src/hula/server/routes/x.cpp": 'Json out = Json::parse(outcome_response(o, 201).body);\n',
    "src/hula/oli/y.cpp": 'const auto d = io::parse_study_json(resolved.dump(), kind);\n',
    "src/hula/server/z.cpp": 'return Json::parse(text.str());\n',
    "python/src/w.cpp": 'return out.dump();\n',
    "python/hulahoops/v.py": 'return json.loads(self._doc.show(label))\n',
}


def run(root):
    return subprocess.run([sys.executable, str(CHECK), "--root", str(root)], capture_output=True, text=True)


def main():
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        for rel in CASES:
            (root / rel).parent.mkdir(parents=True, exist_ok=True)
        for rel, line in CASES.items():
            for other in CASES:
                (root / other).write_text("// clean\n")
            (root / rel).write_text(line)
            r = run(root)
            if r.returncode != 1 or rel not in r.stdout:
                failures.append(f"{rel}: not refused ({r.returncode}): {r.stdout}")
        for other in CASES:
            (root / other).write_text("// clean: Json value, no text\n")
        r = run(root)
        if r.returncode != 0:
            failures.append(f"clean tree refused: {r.stdout}")
    for f in failures:
        print(f)
    print(f"json_text_violation_test: {len(CASES)} cases, {len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
