#!/usr/bin/python3
"""Checks the disturbances planter-fit named on a field log against the columns dropped from it.

Usage: fit_disturbance_check.py FIT_JSON FULL_RECORDING.csv OUTPUT=COLUMN[:SCALE] ...
Each OUTPUT must have its disturbance named and no effect; every other channel must be "no
significant mismatch". The named RMS is compared with the SD of COLUMN (times SCALE, e.g. 100
for a slip fraction shown in %) along the row (each row weighted by its travel, true_x_m) over
the rows the fit calibrated on (t before held_out_from_s): within 1.96 of its stated SD, or the
line says by how many SDs it misses. Prints one line per channel; exit 0 when every check holds,
1 otherwise.
"""
import csv
import json
import math
import sys


def column_sd(path, column, until_s):
    """The column's SD along the row over the rows before until_s: each row weighted by the
    distance travelled to the next (true_x_m), as the process is one of distance (analysis/
    disturbance.h), its RMS what the row shows and not what a stop lingers over. A recording
    without true_x_m weighs each row alike."""
    values, x = [], []
    with open(path) as f:
        for row in csv.DictReader(line for line in f if not line.startswith("#")):
            if float(row["t"]) < until_s:
                values.append(float(row[column]))
                x.append(float(row["true_x_m"]) if "true_x_m" in row else float(len(x)))
    x.append(x[-1] + (x[-1] - x[-2] if len(x) > 1 else 1.0))
    weights = [max(b - a, 0.0) for a, b in zip(x, x[1:])]
    if sum(weights) <= 0:
        weights = [1.0] * len(values)
    total = sum(weights)
    mean = sum(w * v for w, v in zip(weights, values)) / total
    return math.sqrt(sum(w * (v - mean) ** 2 for w, v in zip(weights, values)) / total)


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
