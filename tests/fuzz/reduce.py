#!/usr/bin/env python3
"""Cuts a pivot-fuzz journal down to a short one that still fails its replay the same way.

    reduce.py PIVOT_FUZZ JOURNAL [OUT]

Delta debugging (ddmin) over the journal's lines, keeping the first (the world) line: a
candidate is kept when `PIVOT_FUZZ --replay candidate` still exits as the journal does: 3 for
a world turned non-finite, 4 for a body's state beyond the input limits. Then each step line
is tried with fewer iterations, and every line with rounder numbers, so the result is short
and readable. Writes OUT (default: JOURNAL with .min appended) and prints it.
"""
import os
import subprocess
import sys
import tempfile


FAILURE = 3  # the replay's exit status being reduced (main sets it from the journal's)


def replay_status(fuzz, lines):
    with tempfile.NamedTemporaryFile("w", suffix=".journal", delete=False) as f:
        f.write("\n".join(lines) + "\n")
        path = f.name
    try:
        result = subprocess.run([fuzz, "--replay", path], stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL)
        return result.returncode
    finally:
        os.unlink(path)


def still_fails(fuzz, lines):
    return replay_status(fuzz, lines) == FAILURE


def round_field(text, digits):
    """A number rounded to `digits` decimals; names (b3, s7, ...) unchanged."""
    try:
        value = float(text)
    except ValueError:
        return text
    if text.lstrip("-").isdigit():
        return text
    rounded = round(value, digits)
    return str(int(rounded)) if digits == 0 else repr(rounded)


def ddmin(fuzz, head, body):
    n = 2
    while len(body) >= 2:
        chunk = max(1, len(body) // n)
        reduced = False
        for start in range(0, len(body), chunk):
            candidate = body[:start] + body[start + chunk:]
            if still_fails(fuzz, head + candidate):
                body = candidate
                n = max(n - 1, 2)
                reduced = True
                break
        if not reduced:
            if n >= len(body):
                break
            n = min(len(body), 2 * n)
    return body


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    fuzz, journal = sys.argv[1], sys.argv[2]
    out = sys.argv[3] if len(sys.argv) > 3 else journal + ".min"
    lines = [l for l in open(journal).read().splitlines() if l and not l.startswith("#")]
    global FAILURE
    FAILURE = replay_status(fuzz, lines)
    if FAILURE not in (3, 4):
        print("the journal's replay does not fail (exit status %d)" % FAILURE)
        return 1
    head, body = lines[:1], lines[1:]
    body = ddmin(fuzz, head, body)
    # Fewer iterations per step, where that keeps the failure.
    for i, line in enumerate(body):
        fields = line.split()
        if fields[0] != "step":
            continue
        for iterations in ([fields[2], "1"], ["1", fields[3]], ["1", "1"]):
            candidate = body[:i] + [" ".join(fields[:2] + iterations)] + body[i + 1:]
            if still_fails(fuzz, head + candidate):
                body = candidate
                fields = body[i].split()
    # Rounder numbers, line by line, where that keeps the failure: easier to read and retype.
    for i, line in enumerate(body):
        fields = line.split()
        for digits in (0, 1, 2):
            rounded = [fields[0]] + [round_field(x, digits) for x in fields[1:]]
            candidate = body[:i] + [" ".join(rounded)] + body[i + 1:]
            if rounded != fields and still_fails(fuzz, head + candidate):
                body = candidate
                break
    with open(out, "w") as f:
        f.write("\n".join(head + body) + "\n")
    print("\n".join(head + body))
    return 0


if __name__ == "__main__":
    sys.exit(main())
