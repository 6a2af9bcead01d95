"""Shared by the dtoadq plot scripts: reading the CSV files the C++ side writes, colours, saving.
The scripts only draw; every number comes from dtoadq."""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")  # headless: never open a window
import matplotlib.pyplot as plt  # noqa: E402


def argument_parser():
    """The arguments every script takes: the data table the C++ side wrote, and the PNG to write."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--data", required=True)
    parser.add_argument("--out", required=True)
    return parser


def read_rows(path):
    """Rows of a CSV file with a header, as dicts of strings."""
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def material_colours(count):
    """Distinct colours, one per material: tab10, then tab20 for more than ten."""
    cmap = plt.get_cmap("tab10" if count <= 10 else "tab20")
    return [cmap(i % cmap.N) for i in range(count)]


def save(fig, path, dpi):
    fig.savefig(path, dpi=dpi, facecolor="white")
    plt.close(fig)
