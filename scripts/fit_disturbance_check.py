#!/usr/bin/python3
"""Checks the disturbances planter-fit named on a field log against the columns dropped from it.

Usage: fit_disturbance_check.py FIT_JSON FULL_RECORDING.csv OUTPUT=COLUMN[:SCALE] ...
Each OUTPUT must have its disturbance named and no effect; every other channel must be "no
significant mismatch". The named RMS is compared with the SD of COLUMN (times SCALE, e.g. 100
for a slip fraction shown in %) over the rows the fit calibrated on (t before held_out_from_s):
within 1.96 of its stated SD, or the line says by how many SDs it misses. Prints one line per
channel; exit 0 when every check holds, 1 otherwise.
"""
import csv
import json
import math
import sys


def column_sd(path, column, until_s):
    values = []
    with open(path) as f:
        for row in csv.DictReader(line for line in f if not line.startswith("#")):
            if float(row["t"]) < until_s:
                values.append(float(row[column]))
    mean = sum(values) / len(values)
    return math.sqrt(sum((v - mean) ** 2 for v in values) / len(values))


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    fit = json.load(open(sys.argv[1]))
    expected = {}
    for item in sys.argv[3:]:
        output, column = item.split("=")
        column, _, scale = column.partition(":")
        expected[output] = (column, float(scale or 1.0))
    failed = False
    for c in fit["channels"]:
        output, verdict = c["output"], c["verdict"]
        named = [e["effect"] for e in c["effects"]]
        if output not in expected:
            ok = verdict == "no significant mismatch" and not named
            print("%s %s: %s" % ("PASS" if ok else "FAIL", output, verdict))
            failed |= not ok
            continue
        column, scale = expected.pop(output)
        d = c.get("disturbance")
        if verdict != "disturbance named" or d is None or named:
            print("FAIL %s: %s%s" % (output, verdict, "; named " + ", ".join(named) if named else ""))
            failed = True
            continue
        truth = scale * column_sd(sys.argv[2], column, fit["held_out_from_s"])
        misses = abs(d["rms"] - truth) / d["rms_sd"] if d["rms_sd"] > 0 else float("inf")
        ok = misses <= 1.96
        print("%s %s: %s %.4g +- %.2g %s RMS, dropped %s %.4g (%.1f SD)" % (
            "PASS" if ok else "FAIL", output, d["name"], d["rms"], d["rms_sd"], d["unit"], column,
            truth, misses))
        failed |= not ok
    for output in expected:
        print("FAIL %s: not analysed" % output)
        failed = True
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
