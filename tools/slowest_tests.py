#!/usr/bin/env python3
"""Prints the slowest tests of one or more ctest runs, from the JUnit files that
`ctest --output-junit FILE` writes, with each run's total: where the test command's time goes."""
import argparse
import sys
import xml.etree.ElementTree as ElementTree


def read_run(path):
    """(name, seconds) of every test case in a ctest JUnit file."""
    try:
        root = ElementTree.parse(path).getroot()
    except (OSError, ElementTree.ParseError) as error:
        sys.exit(f"slowest_tests: {path}: {error}")
    return [(case.get("name", "?"), float(case.get("time", "0"))) for case in root.iter("testcase")]


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("junit", nargs="+", help="JUnit files written by ctest --output-junit")
    parser.add_argument("-n", type=int, default=10, help="how many tests to print (10)")
    args = parser.parse_args()
    everything = []
    for path in args.junit:
        run = read_run(path)
        print(f"{path}: {len(run)} tests, {sum(seconds for _, seconds in run):.1f} s of test time")
        everything += [(seconds, name, path) for name, seconds in run]
    print(f"The {args.n} slowest tests:")
    for seconds, name, path in sorted(everything, reverse=True)[: args.n]:
        print(f"  {seconds:7.2f} s  {name}  ({path})")


if __name__ == "__main__":
    main()
