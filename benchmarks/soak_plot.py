#!/usr/bin/env python3
"""Draws the resident memory of a soak run (benchmarks/soak --csv) against the plans made, and
prints the growth per 1,000 plans after the first 1,000 (the least-squares slope of the reports
from then on). Needs matplotlib (Debian's python3-matplotlib).

Example:
  benchmarks/soak_plot.py out/soak/soak.csv --out docs/images/soak_memory.png
"""
import argparse
import csv
import sys


def growth_per_thousand(plans, resident):
    """Least-squares slope of resident MB against plans, per 1,000 plans, from the 1,000th plan on."""
    points = [(p, r) for p, r in zip(plans, resident) if p >= 1000]
    if len(points) < 2:
        return None
    mean_p = sum(p for p, _ in points) / len(points)
    mean_r = sum(r for _, r in points) / len(points)
    slope = sum((p - mean_p) * (r - mean_r) for p, r in points) / sum((p - mean_p) ** 2 for p, _ in points)
    return 1000.0 * slope


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("csv", help="the soak's CSV file")
    parser.add_argument("--out", required=True, help="PNG file to write")
    args = parser.parse_args(argv)
    try:
        with open(args.csv, newline="") as f:
            rows = list(csv.DictReader(f))
        plans = [int(row["plans"]) for row in rows]
        resident = [float(row["resident_mb"]) for row in rows]
    except (OSError, KeyError, ValueError) as e:
        print(f"soak_plot.py: {args.csv}: {e}", file=sys.stderr)
        return 2
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    growth = growth_per_thousand(plans, resident)
    figure, axes = plt.subplots(figsize=(7, 3.5))
    axes.plot(plans, resident, marker="o")
    axes.set_xlabel("plans made in the process")
    axes.set_ylabel("resident memory (MB)")
    axes.set_ylim(0, max(resident) * 1.2)
    axes.grid(True, alpha=0.3)
    title = "soak: resident memory"
    if growth is not None:
        title += f" (after 1,000 plans: {growth:+.2f} MB per 1,000 plans)"
    axes.set_title(title, fontsize=10)
    figure.tight_layout()
    figure.savefig(args.out, dpi=100)
    print(f"{args.out}: growth after the first 1,000 plans: "
          + ("n/a" if growth is None else f"{growth:+.3f} MB per 1,000 plans"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
