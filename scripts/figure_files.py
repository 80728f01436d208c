"""What plot_benchmark.py and plot_mesh_quality.py share: matplotlib without a display, and the figure file: PNG
with a 128-colour palette, which keeps a figure of many antialiased lines at a third of its size
(doc/Fast_Delaunay_triangulation_3/fig/ holds figures below 200 KB); SVG and PDF as matplotlib writes them."""

import io
import os
import sys


def import_pyplot(program):
    """matplotlib.pyplot on the Agg backend; without matplotlib, `program` stops with a message and status 1."""
    try:
        import matplotlib
    except ImportError:
        sys.exit("%s: matplotlib is not installed for %s (Debian: apt-get install python3-matplotlib, which "
                 "scripts/install_dependencies.sh does)" % (program, sys.executable))
    matplotlib.use("Agg")
    import matplotlib.pyplot as pyplot
    return pyplot


def save_figure(figure, path, dpi):
    if os.path.splitext(path)[1].lower() != ".png":
        figure.savefig(path, dpi=dpi)
        return
    try:
        from PIL import Image  # python3-pil, a dependency of python3-matplotlib
    except ImportError:
        figure.savefig(path, dpi=dpi)
        return
    buffer = io.BytesIO()
    figure.savefig(buffer, format="png", dpi=dpi)
    buffer.seek(0)
    Image.open(buffer).convert("RGB").quantize(colors=128).save(path, optimize=True)
