#!/usr/bin/env python3
"""Pictures of the thin-sheet scene (bench/scenes/thin_sheet.cpp) from its summary.json.

Top: the share of start phases in which each method found the body's passage through the slab,
against speed * dt / h, with what any test at instants can see at best (the exact sampling
prediction). Bottom: side views (y-z plane) of single runs at a few time steps: the slab, the
body at the instants the discrete baseline looks at, the swept path that continuous detection
covers, and the exact first contact.

Usage: plot_thin_sheet.py [OUT_DIR]   (default bench/scenes/out/thin_sheet; writes
OUT_DIR/thin_sheet.png). Needs matplotlib (.ci/install-deps.sh --with-plots installs
python3-matplotlib for the system python, /usr/bin/python3).
"""
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Circle, Polygon  # noqa: E402

METHODS = [("ccd", "CCD (swept BVH)", "tab:green", "o"),
           ("static_bvh", "static BVH + exact narrow phase", "tab:orange", "s"),
           ("discrete", "discrete (triangle intersection at instants)", "tab:red", "v")]


def detection_panel(ax, summary):
    table = summary["table"]
    ratios = [row["ratio"] for row in table]
    runs = [len(row["runs"]) for row in table]
    for key, label, color, marker in METHODS:
        share = [row["hits"][key] / n for row, n in zip(table, runs)]
        ax.plot(ratios, share, marker=marker, color=color, label=label, linewidth=1.5,
                markersize=6, alpha=0.9)
    sampled = [row["hits"]["sampling_predicts"] / n for row, n in zip(table, runs)]
    ax.plot(ratios, sampled, "k:", linewidth=1.2,
            label="best any test at instants can do (exact)")
    h = summary["sheet"]["thickness"]
    overlap = summary["overlap_length"] / h
    ax.axvline(overlap, color="gray", linestyle="--", linewidth=1)
    ax.text(overlap * 1.05, 0.5, "speed·dt = h + body extent", rotation=90, va="center",
            color="gray", fontsize=8)
    ax.set_xscale("log")
    ax.set_ylim(-0.05, 1.08)
    ax.set_xlabel("speed · dt / h")
    ax.set_ylabel(f"passages found (share of {runs[0]} start phases)")
    ax.set_title("Body shot through a thin slab: which methods see the passage")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(loc="lower left", fontsize=8)


def pick_run(row):
    """A run the discrete baseline missed, when there is one (the interesting case)."""
    for run in row["runs"]:
        if not run["discrete"]["detected"]:
            return run
    return row["runs"][len(row["runs"]) // 2]


def side_view(ax, summary, row):
    sheet, body = summary["sheet"], summary["body"]
    h, slope, r = sheet["thickness"], sheet["slope"], body["radius"]
    y0 = body["path_y"]
    run = pick_run(row)
    zs = run["centers_z"]
    z_lo, z_hi = min(zs) - 2 * r, max(zs) + 2 * r
    half_height = max((z_hi - z_lo) / 2, 6 * r)
    z_mid = (z_hi + z_lo) / 2
    half_width = half_height * 0.6  # the same shape in every panel
    y_lo, y_hi = y0 - half_width, y0 + half_width
    # The slab: slope * y - h/2 <= z <= slope * y + h/2.
    ax.add_patch(Polygon([(y_lo, slope * y_lo - h / 2), (y_hi, slope * y_hi - h / 2),
                          (y_hi, slope * y_hi + h / 2), (y_lo, slope * y_lo + h / 2)],
                         closed=True, facecolor="tab:blue", edgecolor="navy", alpha=0.6,
                         label="slab (thickness h)"))
    # The swept path of the body (continuous detection covers all of it).
    ax.add_patch(Polygon([(y0 - r, zs[0]), (y0 + r, zs[0]), (y0 + r, zs[-1]), (y0 - r, zs[-1])],
                         closed=True, facecolor="tab:green", alpha=0.15, edgecolor="none",
                         label="swept path (CCD)"))
    # The body at the instants k dt (what the discrete baseline sees).
    labelled = set()
    for z in zs:
        f = z - slope * y0
        touching = abs(f) <= h / 2 + body["extent"] / 2  # the f ranges overlap
        label = ("body at an instant k·dt, meeting the slab" if touching
                 else "body at an instant k·dt, clear of the slab")
        ax.add_patch(Circle((y0, z), r, facecolor="tab:red" if touching else "none",
                            edgecolor="darkred" if touching else "dimgray", linewidth=1,
                            alpha=0.55 if touching else 0.9,
                            label=None if label in labelled else label))
        labelled.add(label)
    # The exact first contact.
    ref = run["reference"]
    if ref["contact"]:
        k, t = ref["step"], ref["toi"]
        z = zs[k] + t * (zs[k + 1] - zs[k])
        ax.add_patch(Circle((y0, z), r, facecolor="none", edgecolor="tab:green", linewidth=2,
                            label="first contact (CCD, exact)"))
    ax.set_xlim(y_lo, y_hi)
    ax.set_ylim(z_mid - half_height, z_mid + half_height)
    ax.set_aspect("equal")
    verdict = "found" if run["discrete"]["detected"] else "MISSED"
    static = "MISSED"
    if run["static_bvh"]["detected"]:
        late = (run["static_bvh"]["step"] + run["static_bvh"]["toi_lo"]
                - run["reference"]["step"] - run["reference"]["toi"])
        static = f"{late:.2f} steps late" if late > 1e-9 else "found"
    ax.set_title(f"speed·dt = {row['ratio']:g} h\ndiscrete: {verdict}\nstatic BVH: {static}\n"
                 f"CCD: found, exact TOI", fontsize=9)
    ax.set_xlabel("y")
    ax.tick_params(labelsize=7)


def main():
    out_dir = sys.argv[1] if len(sys.argv) > 1 else "bench/scenes/out/thin_sheet"
    with open(os.path.join(out_dir, "summary.json")) as f:
        summary = json.load(f)
    wanted = [1, 3, 5, 20]
    rows = [row for row in summary["table"] if row["ratio"] in wanted]
    if not rows:
        rows = summary["table"][:: max(1, len(summary["table"]) // 4)][:4]
    fig = plt.figure(figsize=(12, 10))
    grid = fig.add_gridspec(2, len(rows), height_ratios=[1, 1.5], hspace=0.25, bottom=0.1,
                            top=0.96)
    detection_panel(fig.add_subplot(grid[0, :]), summary)
    handles = {}
    for i, row in enumerate(rows):
        ax = fig.add_subplot(grid[1, i])
        side_view(ax, summary, row)
        if i == 0:
            ax.set_ylabel("z")
        for handle, label in zip(*ax.get_legend_handles_labels()):
            handles.setdefault(label, handle)
    fig.legend(handles.values(), handles.keys(), loc="lower center", ncol=3, fontsize=8,
               bbox_to_anchor=(0.5, 0.0))
    fig.text(0.5, 0.085, "side views (y-z plane) of one run per time step, a run the discrete "
             "baseline missed where there is one", ha="center", fontsize=9)
    path = os.path.join(out_dir, "thin_sheet.png")
    fig.savefig(path, dpi=110, bbox_inches="tight")
    print(path)


if __name__ == "__main__":
    main()
