#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Values, not text (DESIGN.md "One engine, one answer"): no door serialises a
JSON value to parse it again inside the process. Codecs take and return JSON
values (io::Json); text is written once, at a boundary (an HTTP body, a file,
stdout, a child process, an MPI message), and parsed once where it comes in.

Refused, line by line (comments are skipped):
  - a parser applied to a dump:            parse_*json(x.dump()), Json::parse(x.dump())
  - a re-parsed response body:             Json::parse(r.body), parse_json_text(r.body, ...)
  - Json::parse in server/, oli/ (but the store's persisted blobs and the
    exchange helper's files) and python/src: they take values
  - JSON text between C++ and Python:      json.dumps / json.loads in the binding and the
    package, .dump() handed to Python by python/src
Usage: check_json_text.py [--root DIR]; exit 0 when clean, 1 with one line per finding.
"""
import argparse
import pathlib
import re
import sys

EVERYWHERE = [
    (re.compile(r"parse_\w*json\w*\([^;]*\.dump\("), "parses a value it just dumped"),
    (re.compile(r"Json::parse\([^;]*\.dump\("), "parses a value it just dumped"),
    (re.compile(r"(Json::parse|parse_json_text)\(\s*[\w.>-]*\.body\b"), "re-parses a response body it built"),
]
NO_PARSE = (re.compile(r"\bJson::parse\("), "parses JSON text inside the process (take the value)")
PYTHON_TEXT = (re.compile(r"\bjson\.(dumps|loads)\(|attr\(\"(dumps|loads)\"\)"),
               "passes JSON text between C++ and Python (pass values)")
DUMP_TO_PYTHON = (re.compile(r"\.dump\(\)"), "hands JSON text to Python (convert with to_python)")

# Where a parse is a boundary: persisted blobs, the exchange helper's request and answer files.
BOUNDARIES = ("src/hula/oli/store/", "src/hula/oli/exchange/", "src/hula/oli/detail/entity_codec.cpp")


def rules_for(rel: str):
    rules = list(EVERYWHERE)
    if rel.startswith(("src/hula/server/", "src/hula/oli/", "python/src/")) and not rel.startswith(BOUNDARIES):
        rules.append(NO_PARSE)
    if rel.startswith("python/src/"):
        rules.append(DUMP_TO_PYTHON)
    if rel.startswith(("python/src/", "python/hulahoops/")):
        rules.append(PYTHON_TEXT)
    return rules


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", default=pathlib.Path(__file__).resolve().parent.parent, type=pathlib.Path)
    root = parser.parse_args().root.resolve()
    findings = []
    scanned = 0
    for base in ("src/hula", "apps", "python/src", "python/hulahoops"):
        for path in sorted((root / base).rglob("*")):
            if path.suffix not in {".cpp", ".hpp", ".py"} or not path.is_file():
                continue
            rel = path.relative_to(root).as_posix()
            scanned += 1
            rules = rules_for(rel)
            for n, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
                code = line.split("//")[0] if path.suffix != ".py" else line.split("#")[0]
                for pattern, why in rules:
                    if pattern.search(code):
                        findings.append(f"json text: {rel}:{n}: {why}: {line.strip()}")
    for f in findings:
        print(f)
    print(f"check_json_text: {scanned} files, {len(findings)} finding(s)")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
