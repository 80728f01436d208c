#!/usr/bin/python3
"""Draws the CSV that `delaunay_benchmark --csv FILE` writes (scripts/benchmark.sh --plot does both).

usage: /usr/bin/python3 scripts/plot_benchmark.py RESULTS.csv FIGURE.png|FIGURE.svg

One row of panels per point distribution: seconds against n (log-log), Mtets/s against n (log n), and, when the run
had several thread counts, the speed-up of each parallel engine against its thread count, over its sequential
counterpart (fast-par over fast, cgal-par over cgal; over its own smallest thread count when that did not run).
Each engine keeps one colour in every panel; a parallel engine's thread counts differ by line style. The title
carries the machine and the date from the CSV's '#' lines.
"""

import csv
import os
import sys

from figure_files import import_pyplot, save_figure  # beside this script

# One colour per engine, the same in every figure; engines not listed take the remaining colours in order.
ENGINE_COLOURS = {
    "fast": "tab:blue",
    "fast-par": "tab:green",
    "cgal": "tab:orange",
    "cgal-par": "tab:red",
    "fast-remove": "tab:purple",
    "cgal-remove": "tab:brown",
    "fast-move": "tab:pink",
    "cgal-move": "tab:gray",
    "fast-epec": "tab:olive",
    "cgal-epec": "tab:cyan",
    "hxt": "black",
}
LINE_STYLES = ["-", "--", ":", "-."]
MARKERS = ["o", "s", "^", "D", "v", "P"]


def read_results(path):
    """The data rows (dicts) and the '#' comment lines, without the '# ' prefix."""
    comments, lines = [], []
    with open(path, newline="") as f:
        for line in f:
            if line.startswith("#"):
                comments.append(line[1:].strip())
            elif line.strip():
                lines.append(line)
    rows = []
    for row in csv.DictReader(lines):
        # The extra runs (fast+phases: phase clocks on; fast-par+log: forced partitions) are not comparable rows.
        if "+" in row["engine"]:
            continue
        rows.append({
            "n": int(row["n"]),
            "distribution": row["distribution"],
            "engine": row["engine"],
            "threads": int(row["threads"]),
            "seconds": float(row["median_seconds"]),
            "mtets": float(row["mtets_per_second"]),
            "load": float(row["load_average"]),
        })
    if not rows:
        sys.exit("plot_benchmark: %s has no result rows" % path)
    return rows, comments


def title_of(comments, rows):
    """'Fast_Delaunay_triangulation_3 benchmark, DATE', the machine line as the benchmark printed them, and the load
    average the measurements started at (other work on the machine slows the engines, the parallel ones most)."""
    heading = next((c for c in comments if "benchmark," in c), "delaunay_benchmark")
    machine = next((c[len("machine:"):].strip() for c in comments if c.startswith("machine:")), "")
    loads = sorted({r["load"] for r in rows})
    load = "load average %.2f" % loads[0] if len(loads) == 1 else "load average %.2f to %.2f" % (loads[0], loads[-1])
    warnings = [c for c in comments if c.startswith("WARNING")]
    title = heading + "\n" + (machine + "; " if machine else "") + load
    if warnings:
        title += "\n" + "; ".join(warnings)
    return title


def colours_for(engines):
    """{engine: colour}: the fixed colour of a known engine, the remaining tab10 colours in turn for the others."""
    spare = [c for c in ("tab:%s" % name for name in ("blue", "orange", "green", "red", "purple", "brown", "pink",
                                                      "gray", "olive", "cyan"))
             if c not in [ENGINE_COLOURS.get(e) for e in engines]] or ["black"]
    unknown = [e for e in engines if e not in ENGINE_COLOURS]
    return {e: ENGINE_COLOURS.get(e) or spare[unknown.index(e) % len(spare)] for e in engines}


def series_of(rows):
    """{(engine, threads): [(n, seconds, mtets)] sorted by n}, engines in the order of the CSV."""
    series = {}
    for r in rows:
        series.setdefault((r["engine"], r["threads"]), []).append((r["n"], r["seconds"], r["mtets"]))
    for points in series.values():
        points.sort()
    return series


def sequential_counterpart(engine):
    return engine[:-len("-par")] if engine.endswith("-par") else None


def speedups(rows):
    """{(engine, n): [(threads, speed-up)]} for the engines that ran at several thread counts."""
    seconds = {(r["engine"], r["threads"], r["n"]): r["seconds"] for r in rows}
    thread_counts = {}
    for r in rows:
        thread_counts.setdefault((r["engine"], r["n"]), set()).add(r["threads"])
    result = {}
    for (engine, n), counts in thread_counts.items():
        if len(counts) < 2:
            continue
        reference = seconds.get((sequential_counterpart(engine), 1, n)) if sequential_counterpart(engine) else None
        if reference is None:
            reference = seconds[(engine, min(counts), n)]
        result[(engine, n)] = sorted((t, reference / seconds[(engine, t, n)]) for t in counts)
    return result


def draw(rows, comments, figure_path):
    pyplot = import_pyplot("plot_benchmark")
    from matplotlib import ticker
    distributions = list(dict.fromkeys(r["distribution"] for r in rows))
    engines = list(dict.fromkeys(r["engine"] for r in rows))
    colours = colours_for(engines)
    has_speedup = any(speedups([r for r in rows if r["distribution"] == d]) for d in distributions)
    columns = 3 if has_speedup else 2
    figure, axes = pyplot.subplots(len(distributions), columns, figsize=(5.0 * columns, 4.2 * len(distributions)),
                                   squeeze=False, layout="constrained")
    for row_axes, distribution in zip(axes, distributions):
        subset = [r for r in rows if r["distribution"] == distribution]
        threads_of = {}
        for r in subset:
            threads_of.setdefault(r["engine"], set()).add(r["threads"])
        time_axis, rate_axis = row_axes[0], row_axes[1]
        for (engine, threads), points in series_of(subset).items():
            counts = sorted(threads_of[engine], reverse=True)
            style = LINE_STYLES[counts.index(threads) % len(LINE_STYLES)]
            label = engine if len(counts) == 1 and threads == 1 else "%s, %d thread%s" % (
                engine, threads, "" if threads == 1 else "s")
            n = [p[0] for p in points]
            common = dict(color=colours[engine], linestyle=style, marker="o", markersize=4, label=label)
            time_axis.plot(n, [p[1] for p in points], **common)
            rate_axis.plot(n, [p[2] for p in points], **common)
        time_axis.set_xscale("log")
        time_axis.set_yscale("log")
        # Labels at 1, 2 and 5 of every decade: a run spans one or two decades, too few for powers of ten alone.
        time_axis.yaxis.set_major_locator(ticker.LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
        time_axis.yaxis.set_major_formatter(ticker.FuncFormatter(lambda value, _: "%g" % value))
        time_axis.yaxis.set_minor_formatter(ticker.NullFormatter())
        time_axis.set_ylabel("seconds (median)")
        time_axis.set_title("%s points: time" % distribution)
        rate_axis.set_xscale("log")
        rate_axis.set_ylim(bottom=0)
        rate_axis.set_ylabel("million tetrahedra per second")
        rate_axis.set_title("%s points: throughput" % distribution)
        sizes = sorted({r["n"] for r in subset})
        for axis in (time_axis, rate_axis):
            # Ticks at the sizes measured: a run spans a decade or two, where log ticks crowd or are missing.
            axis.set_xticks(sizes)
            axis.set_xticklabels([format_n(n) for n in sizes])
            axis.xaxis.set_minor_formatter(ticker.NullFormatter())
            axis.set_xlabel("n (input points)")
            axis.grid(True, which="both", alpha=0.3)
        time_axis.legend(fontsize="small")
        if has_speedup:
            draw_speedup(row_axes[2], speedups(subset), engines, colours, distribution)
    figure.suptitle(title_of(comments, rows), fontsize="medium")
    save_figure(figure, figure_path, dpi=90)


def draw_speedup(axis, by_engine_n, engines, colours, distribution):
    sizes = sorted({n for _, n in by_engine_n})
    most = 1
    for (engine, n), points in sorted(by_engine_n.items(), key=lambda item: (engines.index(item[0][0]), item[0][1])):
        threads = [p[0] for p in points]
        most = max(most, max(threads))
        counterpart = sequential_counterpart(engine)
        label = "%s over %s, n = %s" % (engine, counterpart if counterpart in engines else "itself", format_n(n))
        axis.plot(threads, [p[1] for p in points], color=colours[engine],
                  marker=MARKERS[sizes.index(n) % len(MARKERS)], linestyle=LINE_STYLES[sizes.index(n) % 4],
                  label=label)
    axis.plot([1, most], [1, most], color="black", linewidth=0.8, linestyle=":", label="ideal")
    axis.set_xlabel("threads")
    axis.set_ylabel("speed-up over the sequential engine")
    axis.set_title("%s points: speed-up" % distribution)
    axis.set_xticks(range(1, most + 1))
    axis.set_ylim(bottom=0)
    axis.grid(True, alpha=0.3)
    axis.legend(fontsize="small")


def format_n(n):
    """1e5, 2e6 for a single digit times a power of ten from 1000 on (as --n is written), 123,456 otherwise."""
    digits = str(n).rstrip("0")
    return "%se%d" % (digits, len(str(n)) - 1) if len(digits) == 1 and n >= 1000 else "{:,}".format(n)


def main(argv):
    if len(argv) != 3 or argv[1] in ("-h", "--help"):
        sys.exit(__doc__.strip().splitlines()[2])
    results, figure = argv[1], argv[2]
    if os.path.splitext(figure)[1].lower() not in (".png", ".svg", ".pdf"):
        sys.exit("plot_benchmark: %s: the figure must end in .png, .svg or .pdf" % figure)
    rows, comments = read_results(results)
    draw(rows, comments, figure)
    print("plot_benchmark: wrote %s" % figure)


if __name__ == "__main__":
    main(sys.argv)
