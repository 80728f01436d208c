#!/usr/bin/python3
"""The Python side-by-side: fast_delaunay_3.delaunay beside scipy.spatial.Delaunay and Gmsh's tetrahedralize.

usage: PYTHONPATH=build/python /usr/bin/python3 benchmark/python/bench_delaunay.py [--n 1e5,1e6] [--rounds 3]
           [--seed 1] [--engines scipy,ours-1,ours-2,c++-1,c++-2,gmsh] [--cxx-benchmark PROGRAM] [--plot FIGURE.png]

Every engine triangulates the same array: n points uniform in the unit cube, float64, from numpy's default_rng(seed).
Every run is a fresh child process (this script with --child) that makes the array, times the one call and reports
the seconds, the number of tetrahedra and its own peak RSS (VmHWM), so that the peak memory of the C++ code inside each
engine, which tracemalloc does not see, is that engine's alone. The engines are interleaved in each round; the table
shows medians. Peak MiB includes the interpreter, numpy and the points, alike for every engine: the baseline row is
a child that only makes the points.

The engines:
  scipy   scipy.spatial.Delaunay(points) (Qhull), 1 thread
  ours-1  fast_delaunay_3.delaunay(points, threads=1), the module of this repository, from PYTHONPATH
  ours-2  the same with threads=2
  c++-1   the same engine called from C++: delaunay_benchmark --engines fast (a run of it, its own uniform points,
          std::mt19937_64), the reference of the binding's cost: ours-1 / c++-1 is what Python adds
  c++-2   delaunay_benchmark --engines fast-par --threads 2
  gmsh    gmsh.model.mesh.tetrahedralize(points.ravel()) with General.NumThreads = 1; it leaves out tetrahedra near
          the convex hull (on uniform points its tetrahedra cover 98.8% of the hull's volume at 2e4 points), so
          its count is not compared
Engines whose module cannot be imported are left out with a note. Exit status 1 when ours finds a different number
of tetrahedra than scipy, or a run fails.
"""

import argparse
import datetime
import importlib.util
import json
import math
import os
import platform
import resource
import statistics
import subprocess
import sys
import time

ENGINES = ["scipy", "ours-1", "ours-2", "c++-1", "c++-2", "gmsh"]
MODULE_OF = {"scipy": "scipy", "ours-1": "fast_delaunay_3", "ours-2": "fast_delaunay_3", "c++-1": None,
             "c++-2": None, "gmsh": "gmsh"}
DESCRIPTION = {
    "scipy": "scipy.spatial.Delaunay",
    "ours-1": "fast_delaunay_3, 1 thread",
    "ours-2": "fast_delaunay_3, 2 threads",
    "c++-1": "(C++ engine, 1 thread)",
    "c++-2": "(C++ engine, 2 threads)",
    "gmsh": "gmsh tetrahedralize",
}
# delaunay_benchmark's engine and thread count for the C++ rows.
CXX_ENGINE = {"c++-1": ("fast", 1), "c++-2": ("fast-par", 2)}
CXX_BENCHMARK = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "build", "benchmark",
                             "Fast_Delaunay_triangulation_3", "delaunay_benchmark")


# ------------------------------------------------------------------------------------------------ child

def make_points(n, seed):
    import numpy
    return numpy.random.default_rng(seed).random((n, 3))


def triangulate(engine, points):
    """Runs one engine once on `points`; returns (seconds, tetrahedra). Only the call is timed."""
    if engine == "none":
        return 0.0, 0
    if engine == "scipy":
        import scipy.spatial
        start = time.perf_counter()
        tets = scipy.spatial.Delaunay(points).simplices
        return time.perf_counter() - start, len(tets)
    if engine in ("ours-1", "ours-2"):
        import fast_delaunay_3
        start = time.perf_counter()
        tets, _neighbors = fast_delaunay_3.delaunay(points, threads=int(engine[-1]))
        return time.perf_counter() - start, len(tets)
    if engine == "gmsh":
        import gmsh
        gmsh.initialize()
        try:
            gmsh.option.setNumber("General.Terminal", 0)
            gmsh.option.setNumber("General.NumThreads", 1)
            gmsh.model.add("bench_delaunay")
            start = time.perf_counter()
            tets = gmsh.model.mesh.tetrahedralize(points.ravel())
            return time.perf_counter() - start, len(tets) // 4
        finally:
            gmsh.finalize()
    raise ValueError("unknown engine " + engine)


def peak_kib():
    """The peak RSS of this process's own address space: VmHWM, which starts afresh at exec. getrusage's ru_maxrss
    does not: Linux carries it across exec from the forked copy of the parent (here 50 MiB more than the child's)."""
    try:
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1])
    except OSError:
        pass
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss


def child(engine, n, seed):
    points = make_points(n, seed)
    seconds, tetrahedra = triangulate(engine, points)
    print(json.dumps({"seconds": seconds, "tetrahedra": tetrahedra, "peak_kib": peak_kib()}))


def run_cxx(engine, n, program):
    """{seconds, tetrahedra, peak_kib} of one delaunay_benchmark run (its medians of one round), or {error}."""
    name, threads = CXX_ENGINE[engine]
    command = [program, "--n", str(n), "--engines", name, "--threads", str(threads), "--rounds", "1", "--csv", "-"]
    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    rows = [line.split(",") for line in done.stdout.splitlines() if line and not line.startswith("#")]
    if done.returncode != 0 or len(rows) != 2:
        return {"error": "%s: status %d" % (program, done.returncode)}
    row = dict(zip(rows[0], rows[1]))
    return {"seconds": float(row["median_seconds"]), "tetrahedra": int(row["finite_cells"]),
            "peak_kib": float(row["peak_mib"]) * 1024}


def run_child(engine, n, seed, cxx_program=CXX_BENCHMARK):
    """{seconds, tetrahedra, peak_kib} of one run in a fresh interpreter, or {error}."""
    if engine in CXX_ENGINE:
        return run_cxx(engine, n, cxx_program)
    command = [sys.executable, os.path.abspath(__file__), "--child", engine, str(n), str(seed)]
    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        lines = done.stderr.strip().splitlines()
        return {"error": "status %d: %s" % (done.returncode, lines[-1] if lines else "no message")}
    return json.loads(done.stdout.strip().splitlines()[-1])


# ------------------------------------------------------------------------------------------------ parent

def parse_sizes(text):
    sizes = []
    for item in text.split(","):
        try:
            value = float(item)
        except ValueError:
            raise argparse.ArgumentTypeError("'%s' is not a number" % item)
        if not value >= 4 or value != int(value):
            raise argparse.ArgumentTypeError("'%s' is not a whole number of at least 4 points" % item)
        sizes.append(int(value))
    return sizes


def parse_engines(text):
    engines = [e for e in text.split(",") if e]
    for e in engines:
        if e not in ENGINES:
            raise argparse.ArgumentTypeError("unknown engine '%s' (known: %s)" % (e, ",".join(ENGINES)))
    return engines


def importable(module):
    """Whether a fresh interpreter imports `module` (a module found but failing to load counts as missing)."""
    if importlib.util.find_spec(module) is None:
        return False, "not found on sys.path / PYTHONPATH"
    done = subprocess.run([sys.executable, "-c", "import " + module], stdout=subprocess.DEVNULL,
                          stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        lines = done.stderr.strip().splitlines()
        return False, "import failed: " + (lines[-1] if lines else "status %d" % done.returncode)
    return True, ""


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def load_average():
    try:
        return os.getloadavg()[0]
    except OSError:
        return float("nan")


def module_version(module):
    try:
        return getattr(__import__(module), "__version__", "?")
    except ImportError:
        return None


def header(args, engines):
    date = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    machine = "%s, %d hardware threads, %d usable by this process" % (cpu_model(), os.cpu_count() or 0,
                                                                      len(os.sched_getaffinity(0)))
    versions = ["Python %s" % platform.python_version()]
    for module in ("numpy", "scipy", "gmsh", "fast_delaunay_3"):
        if any(MODULE_OF[e] == module for e in engines) or module == "numpy":
            version = module_version(module)
            versions.append("%s %s" % (module, version))
    lines = [
        "Python Delaunay benchmark, %s" % date,
        "machine: %s" % machine,
        "build:   %s" % ", ".join(versions),
        "method:  n points uniform in the unit cube (numpy default_rng(%d), float64), the same array for every engine;"
        % args.seed,
        "         every run a fresh process; seconds = the triangulating call alone, median of %d interleaved rounds;"
        % args.rounds,
        "         vs scipy = scipy's seconds / the engine's; peak MiB = the child's peak RSS (VmHWM: interpreter,",
        "         numpy, the points, the engine's modules and its own memory)",
    ]
    return date, machine, lines


def measure(args, engines, n, load):
    baseline = run_child("none", n, args.seed)
    runs = {e: [] for e in engines}
    for _ in range(args.rounds):
        for e in engines:
            runs[e].append(run_child(e, n, args.seed, args.cxx_benchmark))
    rows = []
    for e in engines:
        good = [r for r in runs[e] if "error" not in r]
        errors = [r["error"] for r in runs[e] if "error" in r]
        row = {"engine": e, "n": n, "errors": errors, "load": load}
        if good:
            counts = {r["tetrahedra"] for r in good}
            row.update(seconds=statistics.median(r["seconds"] for r in good), tetrahedra=good[-1]["tetrahedra"],
                       counts_vary=len(counts) > 1, peak_mib=max(r["peak_kib"] for r in good) / 1024.0,
                       rounds=len(good))
        rows.append(row)
    return baseline, rows


def print_table(n, baseline, rows, load):
    baseline_text = ("%.0f MiB" % (baseline["peak_kib"] / 1024.0)) if "error" not in baseline else "failed"
    print("\nn = {:,} uniform points; baseline peak (interpreter, numpy, points) {}; load average {:.2f}".format(
        n, baseline_text, load))
    print("%-28s %10s %9s %12s %8s %10s %9s" % ("engine", "n", "seconds", "tetrahedra", "Mtets/s", "vs scipy",
                                                 "peak MiB"))
    scipy_row = next((r for r in rows if r["engine"] == "scipy" and "seconds" in r), None)
    for r in rows:
        if "seconds" not in r:
            print("%-28s %10s   failed: %s" % (DESCRIPTION[r["engine"]], "{:,}".format(n), r["errors"][0]))
            continue
        ratio = "%.2fx" % (scipy_row["seconds"] / r["seconds"]) if scipy_row else "-"
        print("%-28s %10s %9.3f %12s %8.2f %10s %9.0f" % (
            DESCRIPTION[r["engine"]], "{:,}".format(n), r["seconds"], "{:,}".format(r["tetrahedra"]),
            r["tetrahedra"] / r["seconds"] / 1e6, ratio, r["peak_mib"]))
    by_engine = {r["engine"]: r for r in rows if "seconds" in r}
    for threads in (1, 2):
        ours, cxx = by_engine.get("ours-%d" % threads), by_engine.get("c++-%d" % threads)
        if ours and cxx:
            print("binding cost, %d thread%s: Python %.3f s / C++ %.3f s = %.2fx" % (
                threads, "s" if threads > 1 else "", ours["seconds"], cxx["seconds"], ours["seconds"] / cxx["seconds"]))
    sys.stdout.flush()


def warnings_of(rows):
    """Failed runs, counts that vary between rounds, and ours against scipy's count (gmsh is not compared)."""
    warnings = []
    scipy_row = next((r for r in rows if r["engine"] == "scipy" and "seconds" in r), None)
    for r in rows:
        for error in r["errors"]:
            warnings.append("%s failed: %s" % (DESCRIPTION[r["engine"]], error))
        if r.get("counts_vary"):
            warnings.append("%s found different numbers of tetrahedra in different rounds" % DESCRIPTION[r["engine"]])
        # The C++ rows triangulate other points (std::mt19937_64): their counts differ a little.
        compared = scipy_row and r["engine"].startswith("ours") and "seconds" in r
        if compared and r["tetrahedra"] != scipy_row["tetrahedra"]:
            warnings.append("{} has {:,} tetrahedra, scipy {:,}".format(DESCRIPTION[r["engine"]], r["tetrahedra"],
                                                                         scipy_row["tetrahedra"]))
    return warnings


def plot(path, rows, date, machine):
    try:
        import matplotlib
    except ImportError:
        sys.exit("bench_delaunay: --plot needs matplotlib for %s (Debian: apt-get install python3-matplotlib)"
                 % sys.executable)
    matplotlib.use("Agg")
    import matplotlib.pyplot as pyplot
    colours = {"scipy": "tab:orange", "ours-1": "tab:blue", "ours-2": "tab:green", "c++-1": "lightsteelblue",
               "c++-2": "palegreen", "gmsh": "tab:purple"}
    sizes = sorted({r["n"] for r in rows})
    engines = [e for e in ENGINES if any(r["engine"] == e and "seconds" in r for r in rows)]
    figure, (time_axis, rate_axis, memory_axis) = pyplot.subplots(1, 3, figsize=(15, 4.2), layout="constrained")
    width = 0.8 / max(1, len(engines))
    for k, e in enumerate(engines):
        by_n = {r["n"]: r for r in rows if r["engine"] == e and "seconds" in r}
        x = [i + (k - (len(engines) - 1) / 2) * width for i, n in enumerate(sizes) if n in by_n]
        present = [n for n in sizes if n in by_n]
        time_axis.bar(x, [by_n[n]["seconds"] for n in present], width, color=colours[e], label=DESCRIPTION[e])
        rate_axis.bar(x, [by_n[n]["tetrahedra"] / by_n[n]["seconds"] / 1e6 for n in present], width,
                      color=colours[e], label=DESCRIPTION[e])
        memory_axis.bar(x, [by_n[n]["peak_mib"] for n in present], width, color=colours[e], label=DESCRIPTION[e])
    for axis in (time_axis, rate_axis, memory_axis):
        axis.set_xticks(range(len(sizes)))
        axis.set_xticklabels(["n = {:,}".format(n) for n in sizes])
        axis.grid(True, axis="y", which="both", alpha=0.3)
    # Log seconds, so that a 90 s and a 0.1 s bar both show: from a decade below the shortest bar's decade, and
    # a decade of room above the longest for the legend.
    time_axis.set_yscale("log")
    seconds = [r["seconds"] for r in rows if "seconds" in r]
    time_axis.set_ylim(10 ** (math.floor(math.log10(min(seconds))) - 1), 10 * max(seconds))
    time_axis.set_ylabel("seconds (median)")
    time_axis.set_title("time of one triangulation")
    time_axis.legend(fontsize="small", loc="upper left")
    rate_axis.set_ylabel("million tetrahedra per second")
    rate_axis.set_title("throughput")
    memory_axis.set_ylabel("peak MiB of the process")
    memory_axis.set_title("peak memory (interpreter and points included)")
    loads = sorted({r["load"] for r in rows})
    load = "%.2f" % loads[0] if len(loads) == 1 else "%.2f to %.2f" % (loads[0], loads[-1])
    figure.suptitle("Python Delaunay benchmark, uniform points, %s\n%s; load average %s" % (date, machine, load),
                    fontsize="medium")
    figure.savefig(path, dpi=90)
    print("bench_delaunay: wrote %s" % path)


def main():
    if len(sys.argv) == 5 and sys.argv[1] == "--child":
        child(sys.argv[2], int(sys.argv[3]), int(sys.argv[4]))
        return 0

    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument("--n", type=parse_sizes, default=[100000, 1000000], help="sizes, e.g. 1e5,1e6 (default)")
    parser.add_argument("--rounds", type=int, default=3, help="runs of every engine, interleaved (default 3)")
    parser.add_argument("--seed", type=int, default=1, help="seed of numpy's default_rng (default 1)")
    parser.add_argument("--engines", type=parse_engines, default=list(ENGINES),
                        help="among %s (default: all that import)" % ",".join(ENGINES))
    parser.add_argument("--cxx-benchmark", default=CXX_BENCHMARK, metavar="PROGRAM",
                        help="delaunay_benchmark, for the c++ rows (default: the one in build/)")
    parser.add_argument("--plot", metavar="FIGURE", help="also draw seconds and Mtets/s per engine (.png or .svg)")
    args = parser.parse_args()
    if args.rounds < 1:
        parser.error("--rounds must be at least 1")
    if args.plot and importlib.util.find_spec("matplotlib") is None:
        sys.exit("bench_delaunay: --plot needs matplotlib for %s (Debian: apt-get install python3-matplotlib)"
                 % sys.executable)

    engines, notes = [], []
    if any(e in CXX_ENGINE for e in args.engines):
        if os.access(args.cxx_benchmark, os.X_OK):
            engines += [e for e in args.engines if e in CXX_ENGINE]
        else:
            notes.append("note: %s is not built: the c++ rows are left out (cmake --build build --target "
                         "delaunay_benchmark)" % args.cxx_benchmark)
    for module in dict.fromkeys(MODULE_OF[e] for e in args.engines if MODULE_OF[e]):
        ok, why = importable(module)
        if ok:
            engines += [e for e in args.engines if MODULE_OF[e] == module]
        else:
            notes.append("note: %s %s: %s left out%s" % (
                module, why, ", ".join(e for e in args.engines if MODULE_OF[e] == module),
                " (build the module, then PYTHONPATH=build/python)" if module == "fast_delaunay_3" else ""))
    engines = [e for e in args.engines if e in engines]
    if not engines:
        print("\n".join(notes))
        sys.exit("bench_delaunay: no engine to run")

    date, machine, lines = header(args, engines)
    print("\n".join(lines + notes))
    all_rows, all_warnings = [], []
    for n in args.n:
        load = load_average()
        baseline, rows = measure(args, engines, n, load)
        print_table(n, baseline, rows, load)
        warnings = warnings_of(rows)
        for warning in warnings:
            print("WARNING: " + warning)
        if "gmsh" in engines:
            print("(gmsh's tetrahedralize leaves out tetrahedra near the convex hull: its count is not compared)")
        all_rows += rows
        all_warnings += warnings
    if args.plot:
        plot(args.plot, all_rows, date, machine)
    return 1 if all_warnings else 0


if __name__ == "__main__":
    sys.exit(main())
