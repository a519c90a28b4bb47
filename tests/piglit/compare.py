#!/usr/bin/env python3
"""piglit's results against tests/piglit/expectations.txt (scripts/piglit.sh).

    compare.py RESULTS.json.bz2 EXPECTATIONS     exit 1 on anything unexpected
    compare.py --summary RESULTS.json.bz2        counts only
    compare.py --write RESULTS.json.bz2          the expectation lines of this run (each
                                                 with the test's own message, to edit)

A test not listed must pass. A listed test must have its listed result (skip, fail,
warn); one that now passes is unexpected too, so the file stays true. A crash, a
timeout or an incomplete test is never expected.
"""
import bz2
import collections
import json
import sys


def load(path):
    return {name: t for name, t in json.load(bz2.open(path))["tests"].items()}


def message(t):
    lines = [l.strip() for l in (t.get("out", "") + "\n" + t.get("err", "")).splitlines()]
    lines = [l for l in lines if l and not l.startswith("PIGLIT:") and "Falling back" not in l]
    return (lines[-1] if t["result"] == "skip" and lines else " / ".join(lines[:2]))[:160]


def summary(tests):
    counts = collections.Counter(t["result"] for t in tests.values())
    applicable = sum(n for r, n in counts.items() if r != "skip")
    print(f"piglit: {counts['pass']} pass of {applicable} that ran (not skipped), of {len(tests)}: {dict(counts)}")


def main():
    if sys.argv[1] == "--summary":
        summary(load(sys.argv[2]))
        return 0
    if sys.argv[1] == "--write":
        for name, t in sorted(load(sys.argv[2]).items()):
            if t["result"] != "pass":
                print(f"{t['result']} {name}  # {message(t)}")
        return 0
    tests = load(sys.argv[1])
    expected = {}
    for number, line in enumerate(open(sys.argv[2]), 1):
        line = line.split("#", 1)[0].strip() if not line.lstrip().startswith("#") else ""
        if not line:
            continue
        result, _, name = line.partition(" ")
        if result not in ("skip", "fail", "warn", "excluded"):
            print(f"{sys.argv[2]}:{number}: expected skip, fail, warn or excluded, not '{result}'")
            return 1
        expected[name.strip()] = result
    summary(tests)
    bad = []
    for name, t in sorted(tests.items()):
        want = expected.get(name, "pass")
        if t["result"] in ("crash", "timeout", "incomplete") or t["result"] != want:
            bad.append(f"  {name}: {t['result']}, expected {want}  ({message(t)})")
    missing = [n for n, r in expected.items() if r != "excluded" and n not in tests]
    bad += [f"  {n}: listed in the expectations but not run" for n in missing]
    if bad:
        print(f"piglit: {len(bad)} unexpected results:")
        print("\n".join(bad))
        return 1
    print("piglit: every result as expected")
    return 0


if __name__ == "__main__":
    sys.exit(main())
