#!/usr/bin/env python3
"""gaphys's rows of two compare_engines runs side by side: the double
engine's results.csv and the float engine's (compare_engines_float), as a
Markdown table with the float value's relative difference.

    beside.py DOUBLE/results.csv FLOAT/results.csv [--metrics m1,m2,...]
"""
import argparse
import csv
import sys


def gaphys_rows(path):
    rows = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            if row["engine"] == "gaphys":
                rows[(row["metric"], row["scenario"], row["parameter"], row["quantity"])] = row["value"]
    return rows


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def shown(text):
    x = number(text)
    return text if x is None else f"{x:.6g}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("double_csv")
    parser.add_argument("float_csv")
    parser.add_argument("--metrics", default="", help="comma-separated, e.g. m1,m2 (default: all)")
    args = parser.parse_args()
    wanted = {m.strip().upper() for m in args.metrics.split(",") if m.strip()}
    in_double = gaphys_rows(args.double_csv)
    in_float = gaphys_rows(args.float_csv)
    if not in_double or not in_float:
        sys.exit("beside.py: a file has no gaphys rows (run compare_engines with --engines gaphys)")
    print("| metric | scenario | quantity | double | float | float / double - 1 |")
    print("|---|---|---|---:|---:|---:|")
    for key, value in in_double.items():
        metric, scenario, parameter, quantity = key
        if wanted and metric not in wanted:
            continue
        other = in_float.get(key, "")
        a, b = number(value), number(other)
        ratio = f"{b / a - 1:+.2g}" if a not in (None, 0.0) and b is not None else ""
        label = f"{scenario} ({parameter})" if parameter else scenario
        print(f"| {metric} | {label} | {quantity} | {shown(value)} | {shown(other)} | {ratio} |")


if __name__ == "__main__":
    main()
