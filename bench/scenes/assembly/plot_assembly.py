#!/usr/bin/env python3
"""Pictures of the assembly demonstration (bench/scenes/assembly) from its summary.json.

assembly_contact.png: top view of the lock and key at the first contact of the plan that turns
past the stop (the bit at the start and end of the contact step and at the contact), and the
distance to the axis of the bit's leading tip corner over that step, along the arc (the rigid
motion) and along the chord (the linear-vertex approximation): the arc meets the stop rib, the
chord passes under it.

assembly_chord.png: the same for a vertex of the barrel's inner wall over any turn step (the
chord dips into the drill pin, which the barrel clears by 2^-20), and the contacts the chord
approximation invents and misses in each step, against the exact answer.

Usage: plot_assembly.py [OUT_DIR]   (default bench/scenes/out/assembly). Display only: every
number drawn comes from the summary or is recomputed in floating point for the picture.
"""
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Circle, Polygon  # noqa: E402


def rotate(p, degrees):
    a = math.radians(degrees)
    return (p[0] * math.cos(a) - p[1] * math.sin(a), p[0] * math.sin(a) + p[1] * math.cos(a))


def hull(points):
    """Convex hull of 2D points (monotone chain)."""
    pts = sorted(set(points))
    if len(pts) < 3:
        return pts

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def section(box, z):
    """The cross-section at height z of a box given by its 8 corners (corner i differs from
    corner j in one coordinate of the box's frame when i ^ j is 1, 2 or 4)."""
    points = []
    for i in range(8):
        for bit in (1, 2, 4):
            j = i ^ bit
            if j < i:
                continue
            (x0, y0, z0), (x1, y1, z1) = box[i], box[j]
            if (z0 - z) * (z1 - z) <= 0 and z0 != z1:
                t = (z - z0) / (z1 - z0)
                points.append((x0 + t * (x1 - x0), y0 + t * (y1 - y0)))
    return hull(points)


def bit_outline(bit, degrees):
    return hull([rotate((x, y), degrees) for x, y, _ in bit])


def chord_radius(radius, step_degrees, s):
    """Distance to the axis at s of the straight line between two points of a circle."""
    a = math.radians(step_degrees)
    x = (1 - s) + s * math.cos(a)
    y = s * math.sin(a)
    return radius * math.hypot(x, y)


def contact_figure(summary, out_dir):
    d = summary["dimensions"]
    stop = next(v for v in summary["variants"] if v["first_contact"])
    fc = stop["first_contact"]
    a0, a1, ac = fc["angle_from"], fc["angle_to"], fc["angle_lo"]
    fig, (top, zoom, radial) = plt.subplots(1, 3, figsize=(15, 5.0),
                                            gridspec_kw=dict(width_ratios=[1, 0.8, 1.15],
                                                             wspace=0.3))
    # Top view, and a close-up of the contact: the section at the contact's height.
    z = fc["contact_point"][2]
    cx, cy = fc["contact_point"][0], fc["contact_point"][1]
    for ax in (top, zoom):
        for r, color, label in [(d["outer"], "black", "lock: chamber"),
                                (d["chamber_inscribed"], "black", None),
                                (d["pin_radius"], "0.4", "drill pin"),
                                (d["barrel_outer"], "tab:blue", "key: barrel"),
                                (d["barrel_inner_vertex_radius"], "tab:blue", None)]:
            ax.add_patch(Circle((0, 0), r, fill=False, linewidth=0.8, color=color, label=label))
        ax.add_patch(Circle((0, 0), d["pin_radius"], color="0.85"))
        ax.add_patch(Polygon(section(summary["rib"], z), closed=True, color="0.35",
                             label="stop rib (section)"))
        for deg, style, label in [(a0, ":", f"bit at {a0:g}° (step start)"),
                                  (a1, "--", f"bit at {a1:g}° (step end)"),
                                  (ac, "-", f"bit at the first contact, {ac:.4f}°")]:
            ax.add_patch(Polygon(bit_outline(summary["bit"], deg), closed=True, fill=False,
                                 linestyle=style, color="tab:red", linewidth=1.1, label=label))
        ax.plot([cx], [cy], "k.", markersize=5, label="contact point")
        ax.set_aspect("equal")
    top.set_xlim(-1.3, 1.3)
    top.set_ylim(-0.35, 1.3)
    top.add_patch(plt.Rectangle((cx - 0.09, cy - 0.07), 0.18, 0.14, fill=False, linewidth=0.6))
    top.set_title(f"top view, section at z = {z:.4f} (the contact's height)", fontsize=10)
    top.legend(fontsize=7, loc="lower left", ncol=2)
    zoom.set_xlim(cx - 0.09, cx + 0.09)
    zoom.set_ylim(cy - 0.07, cy + 0.07)
    zoom.set_title("close-up of the contact", fontsize=10)

    # The bit's leading tip corner: distance to the axis along the arc and the chord.
    half = d["bit_half_width"]
    corner = (d["bit_tip"], half)
    r_corner = math.hypot(*corner)
    n = 200
    angles = [a0 + (a1 - a0) * k / n for k in range(n + 1)]
    radial.plot(angles, [r_corner] * (n + 1), color="tab:red",
                label="arc (rigid motion): the corner stays at radius 1.000488")
    # The chord's angle and radius at s (the corner's own angle offset included).
    offset = math.degrees(math.atan2(corner[1], corner[0]))
    chord_a, chord_r = [], []
    for k in range(n + 1):
        s = k / n
        p0, p1 = rotate(corner, a0), rotate(corner, a1)
        x, y = (1 - s) * p0[0] + s * p1[0], (1 - s) * p0[1] + s * p1[1]
        chord_a.append(math.degrees(math.atan2(y, x)) - offset)
        chord_r.append(math.hypot(x, y))
    radial.plot(chord_a, chord_r, color="tab:orange", linestyle="--",
                label="chord (linear vertices): dips to 0.992")
    # The rib's extent in (angle, radius), at the bit's height, as a block.
    rib_angles = [math.degrees(math.atan2(y, x)) for x, y, _ in summary["rib"]]
    rib_in = min(math.hypot(x, y) for x, y, _ in summary["rib"])
    radial.fill_between([min(rib_angles) - offset, max(rib_angles) - offset], rib_in, 1.0025,
                        color="0.45", alpha=0.6, label=f"stop rib (reaches in to {rib_in:g})")
    radial.axhline(d["chamber_inscribed"], color="black", linewidth=0.8,
                   label="chamber wall (inscribed circle)")
    radial.axvline(ac, color="tab:red", linewidth=0.6, linestyle=":")
    radial.annotate(f"exact first contact\n{fc['kind']}\nangle {ac:.6f}°\n"
                    f"t in [{fc['t_lo']:.15g},\n      {fc['t_hi']:.15g}]",
                    xy=(ac, r_corner), xytext=(a0 + 0.3, 1.0012), fontsize=7,
                    arrowprops=dict(arrowstyle="->", linewidth=0.6))
    radial.set_xlim(a0, a1)
    radial.set_ylim(0.990, 1.0045)
    radial.set_xlabel("angle of the bit's centre line (degrees)")
    radial.set_ylabel("distance of the bit's leading tip corner to the axis")
    radial.set_title(f"contact step {a0:g}°-{a1:g}°: the arc meets the rib, "
                     "the chord misses", fontsize=10)
    radial.legend(fontsize=7, loc="lower right")
    fig.savefig(os.path.join(out_dir, "assembly_contact.png"), dpi=90, bbox_inches="tight")
    plt.close(fig)


def chord_figure(summary, out_dir):
    d = summary["dimensions"]
    step = summary["step_degrees"]
    c = summary["clearance"]
    fig, (radial, counts) = plt.subplots(1, 2, figsize=(11, 4.4),
                                         gridspec_kw=dict(wspace=0.3))
    r = d["barrel_inner_vertex_radius"]
    n = 200
    s = [k / n for k in range(n + 1)]
    scale = 1e3 / d["pin_radius"]
    radial.plot([step * x for x in s], [0.0 * x for x in s], color="tab:blue",
                label=f"arc (rigid motion): at {r:.9f}")
    radial.plot([step * x for x in s], [(chord_radius(r, step, x) - r) * scale for x in s],
                color="tab:orange", linestyle="--", label="chord (linear vertices)")
    radial.axhline((d["pin_radius"] - r) * scale, color="black", linewidth=0.8,
                   label=f"drill pin (clearance 2^-{summary['clearance_bits']} = {c:.2g})")
    radial.set_xlabel("angle turned within a step (degrees)")
    radial.set_ylabel("change of distance to the axis (10^-3 of the pin's radius)")
    radial.set_title("a vertex of the barrel's inner wall over a 15° step", fontsize=10)
    radial.annotate(f"the pin's surface: {(r - d['pin_radius']) * scale:.4f} below the arc",
                    xy=(step / 2, (d["pin_radius"] - r) * scale), xytext=(step * 0.3, -2),
                    fontsize=7, arrowprops=dict(arrowstyle="->", linewidth=0.6))
    radial.legend(fontsize=7, loc="lower center")

    stop = next(v for v in summary["variants"] if v["first_contact"])
    turns = [x for x in stop["steps"] if x["phase"] == "turn"]
    labels = [f"{x['angle_from']:g}-{x['angle_to']:g}" for x in turns]
    invented = [x["chord"]["invented"] for x in turns]
    missed = [x["chord"]["missed"] for x in turns]
    exact = [x["exact"]["contacts"] for x in turns]
    xs = range(len(turns))
    counts.bar([x - 0.27 for x in xs], [max(v, 0.8) for v in exact], width=0.27,
               color="tab:green", label="exact contacts (pairs)")
    counts.bar(list(xs), [max(v, 0.8) for v in invented], width=0.27, color="tab:orange",
               label="chord: invented")
    counts.bar([x + 0.27 for x in xs], [max(v, 0.8) for v in missed], width=0.27,
               color="tab:red", label="chord: missed")
    counts.set_yscale("log")
    counts.set_ylim(0.7, max(invented + [10]) * 3)
    counts.set_xticks(list(xs))
    counts.set_xticklabels(labels, fontsize=7)
    counts.set_xlabel("turn step (degrees)")
    counts.set_ylabel("pairs in contact (0 drawn as a stub)")
    counts.set_title("per step, against the exact answer", fontsize=10)
    counts.legend(fontsize=7, loc="upper left")
    fig.savefig(os.path.join(out_dir, "assembly_chord.png"), dpi=90, bbox_inches="tight")
    plt.close(fig)


def main():
    out_dir = sys.argv[1] if len(sys.argv) > 1 else "bench/scenes/out/assembly"
    with open(os.path.join(out_dir, "summary.json")) as f:
        summary = json.load(f)
    contact_figure(summary, out_dir)
    chord_figure(summary, out_dir)
    print(f"plot_assembly.py: assembly_contact.png, assembly_chord.png in {out_dir}")


if __name__ == "__main__":
    main()
