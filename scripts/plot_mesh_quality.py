#!/usr/bin/python3
"""Draws the quality histograms that `mesher_benchmark --json FILE` writes (`mesher_benchmark --plot` runs this).

usage: /usr/bin/python3 scripts/plot_mesh_quality.py RESULTS.json FIGURE.png|FIGURE.svg

One row of panels per surface: the radius-edge ratio (circumradius / shortest edge, 0.612 for the regular
tetrahedron; the mesher's quality report's bins) and the smallest dihedral angle of each tetrahedron (slivers are
the first bins), as the share of the tool's tetrahedra in each bin, on a log scale so that the few bad tetrahedra
show. Each tool keeps one colour; its thread counts differ by line style. The title carries the machine and date.
"""

import json
import os
import sys

from figure_files import import_pyplot, save_figure  # beside this script

# One colour per tool, the same in every figure; tools not listed take the remaining colours in order.
TOOL_COLOURS = {
    "ours": "tab:blue",
    "gmsh-hxt": "tab:orange",
    "tetgen-pq1.4": "tab:green",
    "tetgen-pYq1.4": "tab:red",
}
SPARE_COLOURS = ["tab:purple", "tab:brown", "tab:pink", "tab:gray", "tab:olive", "tab:cyan"]
LINE_STYLES = ["-", "--", ":", "-."]


def read_results(path):
    with open(path) as f:
        results = json.load(f)
    if results.get("benchmark") != "mesher_benchmark" or "rows" not in results:
        sys.exit("plot_mesh_quality: %s is not the output of mesher_benchmark --json" % path)
    for row in results["rows"]:
        if "failure" in row:
            print("plot_mesh_quality: %s, %s on %d thread(s) failed (%s): not drawn"
                  % (row["surface"], row["tool"], row["threads"], row["failure"]))
    results["rows"] = [row for row in results["rows"] if "failure" not in row and row["tetrahedra"] > 0]
    if not results["rows"]:
        sys.exit("plot_mesh_quality: %s has no successful rows" % path)
    return results


def colours_for(tools):
    unknown = [t for t in tools if t not in TOOL_COLOURS]
    return {t: TOOL_COLOURS.get(t) or SPARE_COLOURS[unknown.index(t) % len(SPARE_COLOURS)] for t in tools}


def shares(counts):
    total = sum(counts)
    return [100.0 * c / total for c in counts]


def label_of(row, several_thread_counts):
    threads = ", %d thread%s" % (row["threads"], "" if row["threads"] == 1 else "s") if several_thread_counts else ""
    boundary = "" if row["boundary_equals_input"] else ", boundary not kept"
    return "%s%s: {:,} tets, min dihedral %.2f\N{DEGREE SIGN}%s".format(row["tetrahedra"]) % (
        row["tool"], threads, row["min_dihedral_degrees"], boundary)


def draw(results, figure_path):
    pyplot = import_pyplot("plot_mesh_quality")
    rows = results["rows"]
    surfaces = list(dict.fromkeys(r["surface"] for r in rows))
    tools = list(dict.fromkeys(r["tool"] for r in rows))
    colours = colours_for(tools)
    thread_counts = {t: sorted({r["threads"] for r in rows if r["tool"] == t}) for t in tools}

    radius_edge_edges = list(results["radius_edge_bin_lower"])
    radius_edge_edges.append(radius_edge_edges[-1] + (radius_edge_edges[-1] - radius_edge_edges[-2]))
    width = results["min_dihedral_bin_degrees"]

    figure, axes = pyplot.subplots(len(surfaces), 2, figsize=(15, 3.4 * len(surfaces)), squeeze=False,
                                   layout="constrained")
    for (ratio_axis, angle_axis), surface in zip(axes, surfaces):
        for row in (r for r in rows if r["surface"] == surface):
            counts = thread_counts[row["tool"]]
            common = dict(color=colours[row["tool"]], linewidth=1.4,
                          linestyle=LINE_STYLES[counts.index(row["threads"]) % len(LINE_STYLES)])
            ratio_axis.stairs(shares(row["radius_edge_histogram"]), radius_edge_edges, **common)
            angles = row["min_dihedral_histogram"]
            angle_axis.stairs(shares(angles), [width * k for k in range(len(angles) + 1)],
                              label=label_of(row, len(counts) > 1), **common)
        ratio_axis.set_title("%s: radius-edge ratio" % surface)
        ratio_axis.set_xlabel("circumradius / shortest edge (last bin: %g and above)" % radius_edge_edges[-2])
        angle_axis.set_title("%s: smallest dihedral angle" % surface)
        angle_axis.set_xlabel("smallest dihedral angle of the tetrahedron, degrees")
        angle_axis.set_xlim(0, 75)
        for axis in (ratio_axis, angle_axis):
            axis.set_yscale("log")
            axis.set_ylabel("% of the tetrahedra")
            axis.grid(True, which="major", alpha=0.3)
        angle_axis.legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.03, 1.0), borderaxespad=0)
    figure.suptitle("Mesh quality, the same surfaces and size field for every tool, no mesh improvement\n"
                    "mesher_benchmark, %s; %s" % (results["date"], results["machine"]), fontsize="medium")
    save_figure(figure, figure_path, dpi=80)


def main(argv):
    if len(argv) != 3 or argv[1] in ("-h", "--help"):
        sys.exit(__doc__.strip().splitlines()[2])
    results, figure = argv[1], argv[2]
    if os.path.splitext(figure)[1].lower() not in (".png", ".svg", ".pdf"):
        sys.exit("plot_mesh_quality: %s: the figure must end in .png, .svg or .pdf" % figure)
    draw(read_results(results), figure)
    print("plot_mesh_quality: wrote %s" % figure)


if __name__ == "__main__":
    main(sys.argv)
