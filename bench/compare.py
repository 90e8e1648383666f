#!/usr/bin/python3
"""Compares Google Benchmark JSON results against a committed baseline.

For every benchmark: the median time per iteration over the repetitions now
and in the baseline (CPU time by default, --metric real_time for wall time),
their ratio (now / baseline), and a verdict:

  SLOWER   ratio > 1 + threshold
  faster   ratio < 1 / (1 + threshold)
  ok       in between
  MISSING  in the baseline, not in the new results
  new      in the new results, not in the baseline
  ERROR    the new run ended in an error (SkipWithError)

It prints a table per benchmark binary, writes the same as Markdown
(--markdown), and warns when the run's context (machine, build type,
revision, benchmark library build, engine versions) differs from the
baseline's, or when the machine was busy. Exit 0 unless --strict and
something is SLOWER, MISSING or ERROR (exit 1); unreadable input exits 2.
Standard library only.

  compare.py [--threshold 0.15] [--metric cpu_time|real_time] [--strict]
             [--markdown OUT.md] --pair BASELINE.json NEW.json [--pair ...]
"""

import argparse
import json
import os
import re
import statistics
import sys

# seconds per Google Benchmark time unit
UNIT_S = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}

# context keys whose change makes a comparison doubtful: the machine, the
# build, the benchmark library; every "engine.<name>" key is compared too
CONTEXT_KEYS = [
    "host_name", "num_cpus", "machine_cpu_model", "machine_os",
    "planarbench_build_type", "planarbench_revision", "planarbench_compiler",
    "planarbench_flags", "planarbench_sanitize",
    "library_build_type", "benchmark_library_build_type",
]


class InputError(Exception):
    """An input file that cannot be read as Google Benchmark JSON."""


def load(path):
    """The parsed JSON of a Google Benchmark output file."""
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
    except (OSError, ValueError) as e:
        raise InputError(f"{path}: {e}") from e
    if not isinstance(data, dict) or not isinstance(data.get("benchmarks"), list):
        raise InputError(f"{path}: not Google Benchmark JSON (no 'benchmarks' list)")
    return data


def summarise(data, metric="cpu_time"):
    """run_name -> {median_s, reps, spread, error} from the iteration runs.

    The median is over the repetitions' time per iteration, `metric` being
    "real_time" (wall) or "cpu_time". spread = (max - min) / median. When the
    file holds aggregates only, the "median" aggregate is used.
    """
    runs = {}
    medians = {}
    errors = {}
    for b in data["benchmarks"]:
        name = b.get("run_name", b.get("name"))
        if b.get("error_occurred"):
            errors[name] = b.get("error_message", "error")
            continue
        scale = UNIT_S.get(b.get("time_unit", "ns"))
        if scale is None or metric not in b:
            continue
        t_s = float(b[metric]) * scale
        run_type = b.get("run_type", "iteration")
        if run_type == "iteration":
            runs.setdefault(name, []).append(t_s)
        elif run_type == "aggregate" and b.get("aggregate_name") == "median":
            medians[name] = (t_s, int(b.get("repetitions", 0)))
    out = {}
    for name, times in runs.items():
        m = statistics.median(times)
        spread = (max(times) - min(times)) / m if m > 0 and len(times) > 1 else None
        out[name] = {"median_s": m, "reps": len(times), "spread": spread, "error": None}
    for name, (m, reps) in medians.items():
        if name not in out:
            out[name] = {"median_s": m, "reps": reps, "spread": None, "error": None}
    for name, message in errors.items():
        out[name] = {"median_s": None, "reps": 0, "spread": None, "error": message}
    return out


def verdict(ratio, threshold):
    if ratio > 1.0 + threshold:
        return "SLOWER"
    if ratio < 1.0 / (1.0 + threshold):
        return "faster"
    return "ok"


def natural_key(name):
    """Sort key that orders numbers by value: N:45 before N:180 before N:1440."""
    return [(0, int(part), "") if part.isdigit() else (1, 0, part)
            for part in re.split(r"(\d+)", name)]


def compare(baseline, now, threshold):
    """Rows (name, baseline entry, new entry, ratio, verdict), sorted by name.

    (Random interleaving shuffles the order in which benchmarks finish.)
    """
    rows = []
    for name in sorted(set(baseline) | set(now), key=natural_key):
        b = baseline.get(name)
        n = now.get(name)
        if b is None:
            rows.append((name, None, n, None, "ERROR" if n["error"] is not None else "new"))
            continue
        if n is None:
            rows.append((name, b, None, None, "MISSING"))
        elif n["error"] is not None:
            rows.append((name, b, n, None, "ERROR"))
        elif b["median_s"] is None or b["median_s"] <= 0:
            rows.append((name, b, n, None, "new"))
        else:
            ratio = n["median_s"] / b["median_s"]
            rows.append((name, b, n, ratio, verdict(ratio, threshold)))
    return rows


def context_differences(baseline_data, new_data):
    """[(key, baseline value, new value)] for the context keys that differ."""
    b = baseline_data.get("context", {})
    n = new_data.get("context", {})
    keys = list(CONTEXT_KEYS)
    keys += sorted(k for k in set(b) | set(n) if k.startswith("engine.") and k not in keys)
    return [(k, b.get(k, "(absent)"), n.get(k, "(absent)"))
            for k in keys if str(b.get(k, "(absent)")) != str(n.get(k, "(absent)"))]


def busy_warning(label, data):
    """A warning when the machine was busy as the run started, else None.

    Google Benchmark records the 1-minute load average at the start; a load
    at or above the CPU count means other work competed for the CPUs, which
    inflates wall (and manual) times.
    """
    ctx = data.get("context", {})
    load = ctx.get("load_avg") or []
    cpus = ctx.get("num_cpus")
    if load and cpus and float(load[0]) >= float(cpus):
        return (f"warning: {label}: the machine was busy (1-minute load {float(load[0]):.2f} "
                f"on {cpus} CPUs): wall times are inflated, CPU times less so")
    return None


def fmt_time(t_s):
    if t_s is None:
        return "-"
    for unit, scale in (("s", 1.0), ("ms", 1e-3), ("us", 1e-6)):
        if t_s >= scale:
            return f"{t_s / scale:.4g} {unit}"
    return f"{t_s / 1e-9:.4g} ns"


def fmt_spread(entry):
    if entry is None or entry["spread"] is None:
        return "-"
    return f"{100.0 * entry['spread']:.1f} %"


def table_rows(rows):
    """The table as lists of strings, header first."""
    out = [["benchmark", "baseline", "now", "ratio", "reps", "spread now", "verdict"]]
    for name, b, n, ratio, v in rows:
        if v == "ERROR":
            v = f"ERROR: {n['error']}"
        out.append([
            name,
            fmt_time(b["median_s"] if b else None),
            fmt_time(n["median_s"] if n else None),
            f"{ratio:.3f}" if ratio is not None else "-",
            str(n["reps"]) if n else "-",
            fmt_spread(n),
            v,
        ])
    return out


def text_table(cells):
    widths = [max(len(r[i]) for r in cells) for i in range(len(cells[0]))]
    lines = []
    for k, r in enumerate(cells):
        lines.append("  ".join(c.ljust(w) if i in (0, len(r) - 1) else c.rjust(w)
                               for i, (c, w) in enumerate(zip(r, widths))).rstrip())
        if k == 0:
            lines.append("  ".join("-" * w for w in widths))
    return "\n".join(lines)


def markdown_table(cells):
    lines = ["| " + " | ".join(cells[0]) + " |",
             "|" + "|".join(["---"] + ["---:"] * (len(cells[0]) - 2) + ["---"]) + "|"]
    for r in cells[1:]:
        lines.append("| " + " | ".join(c.replace("|", "\\|") for c in r) + " |")
    return "\n".join(lines)


# Issue 12's detection targets, measured within one run (ratios of the new
# results only, so that machine speed cancels): the engine's default search
# warm against the brute force at N = 180, and its growth from N = 45 to 1440.
DETECTION_TARGETS = {"near_contact": 100.0, "in_contact": 60.0}
DETECTION_GROWTH_LIMIT = 2.0


def detection_ratios(summary):
    """Rows (config, N, brute / default_warm, target) and (config, growth, limit)."""
    def median(method, config, n):
        entry = summary.get(f"detection/{method}/{config}/N:{n}")
        return entry["median_s"] if entry and entry.get("median_s") else None

    rows = []
    for config, target in DETECTION_TARGETS.items():
        for n in (45, 180, 1440):
            brute, fast = median("brute", config, n), median("default_warm", config, n)
            if brute and fast:
                rows.append([f"{config} N={n}", "brute / default_warm", f"{brute / fast:.1f}",
                             f">= {target:g}" if n == 180 else "-"])
        small, large = median("default_warm", config, 45), median("default_warm", config, 1440)
        if small and large:
            rows.append([f"{config}", "default_warm N=1440 / N=45", f"{large / small:.2f}",
                         f"<= {DETECTION_GROWTH_LIMIT:g}" if config == "in_contact" else "-"])
    return rows


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--pair", nargs=2, action="append", required=True,
                   metavar=("BASELINE", "NEW"), help="baseline JSON and new JSON")
    p.add_argument("--threshold", type=float, default=0.15,
                   help="flag SLOWER when now / baseline > 1 + threshold (default 0.15)")
    p.add_argument("--metric", choices=("cpu_time", "real_time"), default="cpu_time",
                   help="the time compared (default cpu_time: see bench/README.md)")
    p.add_argument("--strict", action="store_true",
                   help="exit 1 when a benchmark is SLOWER, MISSING or ERROR")
    p.add_argument("--markdown", help="also write the comparison as Markdown to this file")
    args = p.parse_args(argv)
    if args.threshold <= 0.0:
        p.error("--threshold must be > 0")

    text = []
    md = ["# Benchmark comparison", "",
          f"Median {args.metric} per iteration over the repetitions, now vs baseline; "
          f"SLOWER when now / baseline > {1.0 + args.threshold:.2f}, faster when "
          f"< {1.0 / (1.0 + args.threshold):.3f}. spread = (max - min) / median "
          f"over the repetitions.", ""]
    counts = {}
    try:
        for baseline_path, new_path in args.pair:
            title = os.path.basename(new_path)
            new_data = load(new_path)
            if not os.path.exists(baseline_path):
                note = f"no baseline {baseline_path}: nothing to compare (bless one with --bless)"
                text += [f"== {title}", note, ""]
                md += [f"## {title}", "", note, ""]
                rows = compare({}, summarise(new_data, args.metric), args.threshold)
            else:
                baseline_data = load(baseline_path)
                rows = compare(summarise(baseline_data, args.metric),
                               summarise(new_data, args.metric), args.threshold)
                text.append(f"== {title} (baseline {baseline_path})")
                md += [f"## {title}", "", f"Baseline: `{baseline_path}`", ""]
                diffs = context_differences(baseline_data, new_data)
                for key, b, n in diffs:
                    text.append(f"warning: context differs: {key}: baseline '{b}', now '{n}'")
                for label, data in (("baseline", baseline_data), ("now", new_data)):
                    busy = busy_warning(label, data)
                    if busy:
                        text.append(busy)
                        md += [f"**{busy}**", ""]
                if diffs:
                    md.append("**Warning: the context differs from the baseline's; "
                              "the ratios may reflect that, not the code.**")
                    md.append("")
                    md += [f"- `{k}`: baseline `{b}`, now `{n}`" for k, b, n in diffs]
                    md.append("")
            cells = table_rows(rows)
            text += [text_table(cells), ""]
            md += [markdown_table(cells), ""]
            ratio_rows = detection_ratios(summarise(new_data, args.metric))
            if ratio_rows:
                ratio_cells = [["detection now", "ratio", "value", "target"]] + ratio_rows
                text += ["speed-ups within this run:", text_table(ratio_cells), ""]
                md += ["Speed-ups within this run:", "", markdown_table(ratio_cells), ""]
            for row in rows:
                counts[row[4]] = counts.get(row[4], 0) + 1
    except InputError as e:
        print(f"compare.py: {e}", file=sys.stderr)
        return 2

    summary = ", ".join(f"{counts.get(k, 0)} {k}"
                        for k in ("SLOWER", "faster", "ok", "MISSING", "new", "ERROR"))
    text.append(f"summary: {summary} (median {args.metric}, threshold {args.threshold:.2f})")
    md += [f"Summary: {summary} (median {args.metric}, threshold {args.threshold:.2f})", ""]
    print("\n".join(text))
    if args.markdown:
        os.makedirs(os.path.dirname(os.path.abspath(args.markdown)), exist_ok=True)
        with open(args.markdown, "w", encoding="utf-8") as f:
            f.write("\n".join(md))
    failed = sum(counts.get(k, 0) for k in ("SLOWER", "MISSING", "ERROR"))
    return 1 if args.strict and failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
