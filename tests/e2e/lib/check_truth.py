#!/usr/bin/env python3
"""Checks a calibration file against field_gen.py's truth: every fitted parameter within K sigma
of the truth (K = 4 by default), held angles named when --held says so.

  check_truth.py CAL.json TRUTH.json [--k 4] [--mcounts] [--held a_yz,a_zy,a_zx]

--mcounts: the readings were a logger's m/s^2 read with --unit m/s^2 (1 count = 0.001 m/s^2):
compare with the truth's bias_mcounts and scale_mcounts. Prints one line per parameter.
"""
import argparse
import json
import math
import sys


def main():
    p = argparse.ArgumentParser()
    p.add_argument("cal")
    p.add_argument("truth")
    p.add_argument("--k", type=float, default=4.0)
    p.add_argument("--mcounts", action="store_true")
    p.add_argument("--held", default="")
    a = p.parse_args()
    cal = json.load(open(a.cal))
    truth = json.load(open(a.truth))
    unc = cal["uncertainty"]
    tb = truth["bias_mcounts"] if a.mcounts else truth["bias_counts"]
    tk = truth["scale_mcounts"] if a.mcounts else truth["scale_counts_per_mps2"]
    rows = []
    for i, ax in enumerate("xyz"):
        rows.append(("bias_" + ax, cal["bias_counts"][i], unc["bias_counts"][i], tb[i]))
        rows.append(("scale_" + ax, cal["scale_counts_per_mps2"][i], unc["scale_counts_per_mps2"][i], tk[i]))
    held = {h["name"] for h in cal.get("held", [])}
    want_held = set(x for x in a.held.split(",") if x)
    if want_held and held != want_held:
        print("held %s, expected %s" % (sorted(held), sorted(want_held)))
        return 1
    for key in ("yz", "zy", "zx"):
        name = "a_" + key
        if name in held:
            print("%s held at %g" % (name, cal["misalignment_rad"][key]))
            continue
        rows.append((name, cal["misalignment_rad"][key], unc["misalignment_rad"][key],
                     truth["misalignment_rad"][key]))
    bad = 0
    for name, est, sigma, true in rows:
        z = (est - true) / sigma if sigma else math.inf
        ok = abs(z) <= a.k
        bad += not ok
        print("%-8s %14.6g +- %-10.3g truth %14.6g  %+.2f sigma %s" % (name, est, sigma, true, z, "" if ok else "FAIL"))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
