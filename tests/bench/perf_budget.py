#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The performance budget the project keeps (tests/bench/perf_budget.json).

Every figure is "lower is better": a figure slid when today's value is above
the kept one by more than its noise (the spread between runs of one build on
the two-core machine), and misses its target when it is above the target.

  perf_budget.py compare BUDGET KEY=VALUE...   today's figures beside the kept ones
  perf_budget.py keep BUDGET README KEY=VALUE... [--seconds S --load L --commit C --date D]
                                               the same, then today's figures become the
                                               kept ones, the kept ones the run before,
                                               and README's table shows both
  perf_budget.py readme BUDGET README          README's table from the kept figures

A value that is not a number (a benchmark that printed nothing) is shown as
"?" and never kept. compare and keep exit with 0; the table says what slid.
"""
import json
import sys

README_BEGIN = "<!-- perf-table: generated from tests/bench/perf_budget.json by tests/bench/perf_table.sh --keep -->"
README_END = "<!-- perf-table end -->"


def load(path):
    with open(path, encoding="utf-8") as f:
        budget = json.load(f)
    for figure in budget["figures"]:
        for field in ("key", "name", "unit", "noise"):
            if field not in figure:
                raise ValueError(f"{path}: a figure has no {field!r}: {figure}")
    return budget


def parse_today(pairs):
    today = {}
    for pair in pairs:
        key, sep, value = pair.partition("=")
        if not sep:
            raise ValueError(f"not KEY=VALUE: {pair!r}")
        try:
            today[key] = float(value)
        except ValueError:
            today[key] = None  # the benchmark printed nothing usable
    return today


def number(value, unit):
    if value is None:
        return "?"
    return f"{value:g} {unit}"


def verdict(figure, value):
    """What today's value says beside the kept one and the target."""
    if value is None:
        return "no figure today"
    words = []
    kept = figure.get("kept")
    if kept is not None:
        if value > kept + figure["noise"]:
            words.append(f"SLID by {value - kept:.3g} {figure['unit']} (noise {figure['noise']:g})")
        elif value < kept - figure["noise"]:
            words.append("better")
    target = figure.get("target")
    if target is not None and value > target:
        words.append("MISSES TARGET")
    return ", ".join(words) if words else "ok"


def target_text(figure):
    target = figure.get("target")
    return "-" if target is None else f"<= {target:g} {figure['unit']}"


def compare(budget, today):
    """Prints the table; returns (slid, missed) lists of figure names."""
    kept_run = budget.get("kept_run", {})
    row = "| {:<58} | {:<12} | {:<12} | {:<12} | {}"
    print(row.format("figure", "today", "kept", "target", "verdict"))
    print(row.format("----", "----", "----", "----", "----"))
    slid, missed = [], []
    for figure in budget["figures"]:
        value = today.get(figure["key"])
        said = verdict(figure, value)
        if "SLID" in said:
            slid.append(figure["name"])
        if "MISSES" in said:
            missed.append(figure["name"])
        print(row.format(figure["name"], number(value, figure["unit"]), number(figure.get("kept"), figure["unit"]),
                         target_text(figure), said))
    print()
    if kept_run:
        print(f"kept: {kept_run.get('date', '?')}, commit {kept_run.get('commit', '?')}, "
              f"{kept_run.get('seconds', '?')} s runs, load average {kept_run.get('load', '?')}")
    print("slid beyond their noise: " + (", ".join(slid) if slid else "none"))
    print("missing their target: " + (", ".join(missed) if missed else "none"))
    return slid, missed


def keep(budget, today, run):
    """Today's figures become the kept ones; the kept ones, the run before."""
    budget["run_before"] = budget.get("kept_run", {})
    for figure in budget["figures"]:
        if figure.get("kept") is not None:
            figure["before"] = figure["kept"]
        value = today.get(figure["key"])
        if value is not None:
            figure["kept"] = value
    budget["kept_run"] = run


def run_text(run):
    return (f"{run.get('date', '?')}, commit {run.get('commit', '?')}, "
            f"{run.get('seconds', '?')} s runs under Xvfb 1600x1000, load average {run.get('load', '?')}")


def readme_table(budget):
    before = budget.get("run_before")
    lines = [README_BEGIN, "", f"Last kept run: {run_text(budget.get('kept_run', {}))}."]
    if before:
        lines.append(f"The run before: {run_text(before)}.")
    lines.append("")
    if before:
        lines += ["| figure | kept | the run before | target |", "|---|---|---|---|"]
    else:
        lines += ["| figure | kept | target |", "|---|---|---|"]
    for figure in budget["figures"]:
        cells = [figure["name"], number(figure.get("kept"), figure["unit"])]
        if before:
            cells.append(number(figure.get("before"), figure["unit"]))
        cells.append(target_text(figure))
        lines.append("| " + " | ".join(cells) + " |")
    lines += ["", README_END]
    return "\n".join(lines)


def write_readme(budget, path):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    begin, end = text.find(README_BEGIN), text.find(README_END)
    if begin < 0 or end < begin:
        raise ValueError(f"{path} has no performance table between {README_BEGIN!r} and {README_END!r}")
    text = text[:begin] + readme_table(budget) + text[end + len(README_END):]
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def main(argv):
    if len(argv) < 3 or argv[1] not in ("compare", "keep", "readme"):
        print(__doc__, file=sys.stderr)
        return 2
    command, budget_path = argv[1], argv[2]
    try:
        budget = load(budget_path)
        if command == "readme":
            if len(argv) != 4:
                print(__doc__, file=sys.stderr)
                return 2
            write_readme(budget, argv[3])
            return 0
        args = argv[3:]
        readme = None
        if command == "keep":
            if not args:
                print(__doc__, file=sys.stderr)
                return 2
            readme, args = args[0], args[1:]
        run, pairs = {}, []
        i = 0
        while i < len(args):
            if args[i].startswith("--") and i + 1 < len(args):
                run[args[i][2:]] = args[i + 1]
                i += 2
            else:
                pairs.append(args[i])
                i += 1
        today = parse_today(pairs)
        compare(budget, today)
        if command == "keep":
            keep(budget, today, run)
            with open(budget_path, "w", encoding="utf-8") as f:
                json.dump(budget, f, indent=2, ensure_ascii=False)
                f.write("\n")
            write_readme(budget, readme)
            print(f"kept today's figures in {budget_path} and {readme}")
    except (OSError, ValueError, KeyError) as error:
        print(f"perf_budget.py: {error}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
