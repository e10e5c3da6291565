#!/usr/bin/env python3
"""Picture of the peg-in-hole scene (bench/scenes/peg_in_hole.cpp) from its summary.json.

Side view (x-z plane through the hole's axis): the block's walls, the planned path of the peg's
bottom center, the peg at the plan's waypoints; an inset magnifies the hole's right top corner,
in units of the clearance c, with the peg's right side in each variant and the first contact the
CCD reports for the variant shifted by 2c.

Usage: plot_peg_in_hole.py [OUT_DIR]   (default bench/scenes/out/peg_in_hole; writes
OUT_DIR/peg_in_hole.png). Needs matplotlib (.ci/install-deps.sh --with-plots installs
python3-matplotlib for the system python, /usr/bin/python3).
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import ConnectionPatch, Rectangle  # noqa: E402

COLORS = {"nominal": "tab:green", "near_wall": "tab:olive", "flush": "tab:orange",
          "offset_2c": "tab:red"}


def verdict(variant):
    ccd = variant["ccd"]
    if not ccd["detected"]:
        return "certified collision-free"
    exp = variant["expected"]
    return (f"contact in {exp['segment']} step {exp['segment_step']}, "
            f"t in [{ccd['toi_lo']:.17g}, {ccd['toi_hi']:.17g}] (exact {exp['toi_exact']})")


def main():
    out_dir = sys.argv[1] if len(sys.argv) > 1 else "bench/scenes/out/peg_in_hole"
    with open(os.path.join(out_dir, "summary.json")) as f:
        s = json.load(f)
    hole, top, c = s["hole"], s["block_top"], s["clearance"]
    side, height = s["peg"]["side"], s["peg"]["height"]
    variants = {v["name"]: v for v in s["variants"]}

    fig, (ax, inset) = plt.subplots(1, 2, figsize=(13, 8.2),
                                    gridspec_kw=dict(width_ratios=[1.05, 1], wspace=0.25))
    # The block's cross-section at y = 0: the two boxes beside the hole in x.
    for b in s["block_boxes"][:2]:
        ax.add_patch(Rectangle((b["lo"][0], b["lo"][2]), b["hi"][0] - b["lo"][0],
                               b["hi"][2] - b["lo"][2], facecolor="lightgray", edgecolor="black",
                               label="block (hole walls at x = ±s/2)" if b is s["block_boxes"][0]
                               else None))
    # The nominal plan: the bottom center's path and the peg at the waypoints.
    nominal = variants["nominal"]
    xs = [p[0] for p in nominal["poses"]]
    zs = [p[2] for p in nominal["poses"]]
    ax.plot(xs, zs, ".-", color="tab:green", markersize=3, linewidth=1,
            label="planned path of the peg's bottom center (one dot per step)")
    waypoints = [s["plan"][0]["from"]] + [seg["to"] for seg in s["plan"]]
    names = ["start", "after approach", "after align", "inserted"]
    for (x, y, z), name in zip(waypoints, names):
        ax.add_patch(Rectangle((x - side / 2, z), side, height, facecolor="tab:green",
                               alpha=0.12, edgecolor="tab:green", linewidth=1))
        ax.annotate(name, (x, z + height), textcoords="offset points", xytext=(0, 4),
                    ha="center", fontsize=8, color="darkgreen")
    ax.set_xlim(-1.7, 2.2)
    ax.set_ylim(-0.7, 4.7)
    ax.set_aspect("equal")
    ax.set_xlabel("x (hole side s = 1)")
    ax.set_ylabel("z")
    ax.set_title(f"Peg in hole: clearance c = {s['clearance_exact']} s ≈ {c:.3g} s per side,\n"
                 f"planned path sampled into {len(nominal['poses']) - 1} steps (side view, y = 0)",
                 fontsize=10)

    # The magnified corner: x - s/2 and z - top in units of c.
    span = 3.0
    inset.add_patch(Rectangle((0, -span), span, span, facecolor="lightgray", edgecolor="black"))
    inset.text(1.5, -1.5, "block", ha="center", va="center", fontsize=8)
    for name, v in variants.items():
        right = (v["shift_x"] + side / 2 - hole / 2) / c  # the peg's right side
        exp = v["expected"]
        label = {"nominal": "nominal", "near_wall": "shifted c - 2^-40 (10^-6 c left of the wall)",
                 "flush": "shifted c (flush)", "offset_2c": "shifted 2c"}.get(name, name)
        inset.plot([right, right], [-span, span], color=COLORS.get(name, "k"), linewidth=1.5,
                   linestyle="-" if v["ccd"]["detected"] else "--",
                   label=f"{label}: " + ("contact" if v["ccd"]["detected"] else "free"))
    # The peg shifted by 2c at its first contact: bottom face on the block's top, overlapping the
    # block by c.
    off = variants.get("offset_2c")
    if off and off["ccd"]["detected"]:
        right = (off["shift_x"] + side / 2 - hole / 2) / c
        inset.add_patch(Rectangle((-span, 0), right + span, span, facecolor="tab:red",
                                  alpha=0.15, edgecolor="none"))
        inset.plot([0, right], [0, 0], color="tab:red", linewidth=4, solid_capstyle="butt")
        contact = off["ccd"].get("contact")
        if contact:
            px, _, pz = contact["first_primitive_at_toi"][0]
            inset.plot([(px - hole / 2) / c], [(pz - top) / c], "o", color="darkred",
                       markersize=6, label="CCD's earliest pair (a peg vertex) at its TOI")
        inset.annotate("first contact of the peg shifted 2c:\nits bottom on the block's top,\n"
                       "overlap c", (right / 2, 0), xytext=(-2.8, 1.6),
                       fontsize=9, color="darkred",
                       arrowprops=dict(arrowstyle="->", color="darkred", linewidth=0.8))
    inset.set_xlim(-span, span)
    inset.set_ylim(-span, span)
    inset.set_aspect("equal")
    inset.set_xlabel("(x - s/2) / c", fontsize=9)
    inset.set_ylabel("(z - block top) / c", fontsize=9)
    inset.set_title("inset: the hole's right top corner magnified ~10^6 (units of c);\n"
                    "the peg's right side in each variant", fontsize=10)
    inset.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.1), ncol=1)
    # Where the inset looks.
    ax.add_patch(Rectangle((hole / 2 - 0.04, top - 0.04), 0.08, 0.08, fill=False,
                           edgecolor="black", linewidth=0.8))
    for corner in [(0, 1), (0, 0)]:
        fig.add_artist(ConnectionPatch((hole / 2 + 0.04, top + (0.04 if corner[1] else -0.04)),
                                       corner, "data", "axes fraction", axesA=ax, axesB=inset,
                                       color="gray", linewidth=0.6))

    def late(v, key, field):
        d, exp = v[key], v["expected"]
        if not d["detected"]:
            return "none"
        if not exp["contact"]:
            return "found a contact the exact answer excludes"
        delay = d["step"] + d[field] - exp["step"] - exp["toi"]
        return f"found, {delay:.2g} steps late" if delay > 0 else "found"

    lines = [f"{name}: CCD {verdict(v)}; discrete {late(v, 'discrete', 'toi_hi')}; "
             f"static BVH {late(v, 'static_bvh', 'toi_lo')}" for name, v in variants.items()]
    fig.text(0.08, -0.06, "\n".join(lines), va="top", fontsize=8,
             bbox=dict(facecolor="white", alpha=0.9, edgecolor="lightgray"))
    ax.legend(loc="upper center", fontsize=8, bbox_to_anchor=(0.5, -0.08))
    path = os.path.join(out_dir, "peg_in_hole.png")
    fig.savefig(path, dpi=110, bbox_inches="tight")
    print(path)


if __name__ == "__main__":
    main()
