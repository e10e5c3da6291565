#!/usr/bin/python3
"""Writes REPORT.md and the PNG plots of the speed-versus-error report from the JSON of
`exactccd study --json` and the Markdown tables of its --out-md (run by make_report.sh)."""

import argparse
import datetime
import json
import os
import platform

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)

# One colour per method kind; shades within a kind follow the setting's order.
KIND_COLOURS = {
    "float_only": ["#d62728"],
    "tolerance": ["#ffbb78", "#ff7f0e", "#a65200"],
    "filtered": ["#9ecae1", "#3182bd", "#08306b"],
    "exact": ["#000000"],
}
KIND_MARKERS = {"float_only": "v", "tolerance": "^", "filtered": "o", "exact": "s"}


def canonical(name):
    """A method or mode name as exactccd prints it now: JSON written before the rename says
    "default" for "filtered"."""
    return "filtered" if name == "default" else name


def style(method, index_in_kind):
    kind = canonical(method["method"])
    shades = KIND_COLOURS.get(kind, ["#7f7f7f"])
    return shades[min(index_in_kind, len(shades) - 1)], KIND_MARKERS.get(kind, "D")


def styled(methods):
    """(method, colour, marker) in order, the shade advancing within each kind."""
    seen = {}
    out = []
    for m in methods:
        k = seen.get(m["method"], 0)
        seen[m["method"]] = k + 1
        colour, marker = style(m, k)
        out.append((m, colour, marker))
    return out


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def fmt_ns(ns):
    return f"{ns:,.0f}" if ns >= 100 else f"{ns:.1f}"


def fmt_err(e):
    return "0" if e == 0 else f"{e:.1e}"


def place_labels(fig, ax, points):
    """Labels each (x, y, text) point next to it, trying positions around the point until the
    label overlaps no other label, marker or the legend and stays inside the axes."""
    renderer = fig.canvas.get_renderer()
    frame = ax.get_window_extent(renderer)
    legend = ax.get_legend()
    taken = [legend.get_window_extent(renderer)] if legend else []
    pixels = [ax.transData.transform((x, y)) for x, y, _ in points]
    marker = 6  # half a marker's size, in pixels
    # Beside the point first, then further up or down with a leader line.
    candidates = [(8, 3), (8, -13), (-8, 3), (-8, -13)]
    for dy in range(14, 120, 11):
        candidates += [(8, dy), (8, -dy - 10), (-8, dy), (-8, -dy - 10)]
    for i, (x, y, text) in enumerate(points):
        for dx, dy in candidates:
            far = abs(dy) > 20
            label = ax.annotate(text, (x, y), textcoords="offset pixels", xytext=(dx, dy),
                                ha="left" if dx > 0 else "right", fontsize=7, color="#333333",
                                arrowprops=dict(arrowstyle="-", color="#999999", lw=0.5,
                                                shrinkA=0, shrinkB=4) if far else None)
            label.update_positions(renderer)
            box = matplotlib.text.Text.get_window_extent(label, renderer)  # text, no leader
            inside = (box.x0 >= frame.x0 and box.x1 <= frame.x1 and box.y0 >= frame.y0
                      and box.y1 <= frame.y1)
            clear = not any(box.overlaps(t) for t in taken) and not any(
                box.x0 - marker < px < box.x1 + marker and box.y0 - marker < py < box.y1 + marker
                for j, (px, py) in enumerate(pixels) if j != i)
            if inside and clear:
                taken.append(box)
                break
            label.remove()
        else:  # nowhere free: the first position
            dx, dy = candidates[0]
            ax.annotate(text, (x, y), textcoords="offset pixels", xytext=(dx, dy), fontsize=7,
                        color="#333333")


def speed_vs_error_plot(dataset, path):
    fig, ax = plt.subplots(figsize=(7.5, 4.6), dpi=100)
    points = styled(dataset["methods"])
    for m, colour, marker in points:
        wrong = m["false_positives"] + m["false_negatives"]
        ax.scatter(m["mean_ns"], wrong, s=70, c=colour, marker=marker, edgecolors="black",
                   linewidths=0.6, zorder=3,
                   label=f'{m["label"]}: {m["false_positives"]} FP, {m["false_negatives"]} FN, '
                         f'{m["late_tois"]} late')
    ax.set_xscale("log")
    ax.set_yscale("symlog", linthresh=1)
    ax.set_ylim(bottom=-1, top=max(10, 4 * max(
        m["false_positives"] + m["false_negatives"] for m in dataset["methods"])))
    ax.set_xlabel("mean time per query (ns, single thread, log scale)")
    ax.set_ylabel("false positives + false negatives")
    ax.set_title(f'{dataset["name"]}: {dataset["queries"]:,} queries, '
                 f'{dataset["contacts"]:,} with contact', fontsize=10)
    ax.grid(True, which="major", alpha=0.3)
    ax.legend(fontsize=6.5, loc="upper right", framealpha=0.9)
    fig.tight_layout()
    place_labels(fig, ax, [(m["mean_ns"], m["false_positives"] + m["false_negatives"], m["label"])
                           for m, _, _ in points])
    fig.savefig(path)
    plt.close(fig)


def toi_error_plot(datasets, path):
    """Per data set and method: late (non-conservative) TOIs by how late, and the largest late
    and early TOI errors."""
    fig, axes = plt.subplots(2, len(datasets), figsize=(3.4 * len(datasets) + 1.2, 6.4),
                             dpi=100, squeeze=False)
    floor = 1e-18  # zero errors are drawn at this floor and labelled 0
    for col, d in enumerate(datasets):
        methods = d["methods"]
        xs = list(range(len(methods)))
        # Top: how many TOIs are late by more than each threshold (the bins' upper ends).
        ax = axes[0][col]
        bins = list(methods[0]["late_by"].keys())  # "<=1e-15", ..., ">1e-3"
        thresholds = ["any"] + [">" + b[2:] for b in bins[:-1]]
        for (m, colour, marker), offset in zip(styled(methods), [i * 0.04 for i in xs]):
            counts = [m["late_by"][b] for b in bins]
            later_than = [sum(counts[k:]) for k in range(len(counts))]
            ax.plot([k + offset - 0.14 for k in range(len(thresholds))], later_than,
                    marker=marker, color=colour, markeredgecolor="black", markeredgewidth=0.5,
                    markersize=5, linewidth=1, label=m["label"])
        ax.set_yscale("symlog", linthresh=1)
        ax.set_ylim(bottom=-0.3, top=max(10, 6 * max(m["late_tois"] for m in methods)))
        ax.set_xticks(range(len(thresholds)))
        ax.set_xticklabels(thresholds, fontsize=7)
        ax.set_xlabel("late by (reported - t*)", fontsize=7)
        ax.set_title(d["name"], fontsize=9)
        ax.grid(True, alpha=0.3)
        if col == 0:
            ax.set_ylabel("late TOIs")
        if col == len(datasets) - 1:
            ax.legend(fontsize=5.5, loc="upper right", framealpha=0.9)

        ax = axes[1][col]
        late = [m["max_late_by"] for m in methods]
        early = [m["max_early_by"] for m in methods]
        w = 0.4
        ax.bar([x - w / 2 for x in xs], [max(e, floor) for e in late], width=w, color="#de2d26",
               edgecolor="black", linewidth=0.4, label="largest late error (unsafe)")
        ax.bar([x + w / 2 for x in xs], [max(e, floor) for e in early], width=w, color="#6baed6",
               edgecolor="black", linewidth=0.4, label="largest early error (conservative)")
        for x, a, b in zip(xs, late, early):
            ax.text(x - w / 2, max(a, floor), fmt_err(a), ha="center", va="bottom", fontsize=5.5,
                    rotation=90)
            ax.text(x + w / 2, max(b, floor), fmt_err(b), ha="center", va="bottom", fontsize=5.5,
                    rotation=90)
        ax.set_yscale("log")
        ax.set_ylim(floor / 2, 1e5)
        ax.set_xticks(xs)
        ax.set_xticklabels([m["label"] for m in methods], rotation=60, ha="right", fontsize=6.5)
        ax.grid(True, axis="y", alpha=0.3)
        if col == 0:
            ax.set_ylabel("|reported TOI - t*|")
        if col == len(datasets) - 1:
            ax.legend(fontsize=6, loc="upper right", framealpha=0.9)
    fig.suptitle("TOI error: late (non-conservative) TOIs by how late (top); largest late and "
                 "early error per method (bottom)", fontsize=9.5)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


# ---------------------------------------------------------------------------------------------
# Minimum separation (issue 12): `exactccd bench --json --min-separation ...` runs.

def load_min_separation(specs):
    """[(name, [bench JSON objects])] in the order given; specs are NAME=FILE, several files
    may share a NAME (one set benched at several absolute deltas)."""
    sets = {}
    for spec in specs:
        name, _, path = spec.partition("=")
        if not path:
            raise SystemExit(f"plot_report: --min-separation wants NAME=FILE, got {spec!r}")
        with open(path) as f:
            sets.setdefault(name, []).extend(json.load(f))
    return list(sets.items())


def separation_method(row):
    if row["mode"] == "float_only":
        return "float cubic" if row["min_separation"] == 0 else "common practice"
    return canonical(row["mode"])


def separation_label(row):
    if "min_separation_factor" in row:
        f = row["min_separation_factor"]
        return "0" if f == 0 else f"{f:g} x size"
    return f'{row["min_separation"]:g}'


def fmt_time(ns):
    return f"{ns / 1000:.2f} µs" if ns >= 1000 else f"{ns:.1f} ns"


def min_separation_table(rows):
    """One line per delta and method; 'vs delta = 0' is the mean over the same set's delta = 0
    mean in the same mode (the cost of asking for a separation)."""
    at_zero = {r["mode"]: r["mean_ns"] for r in rows if r["min_separation"] == 0}
    out = ["| delta | method | mean | vs delta = 0 | median | false pos. / neg. | late TOIs | "
           "max TOI error |",
           "|---|---|---:|---:|---:|:---:|---:|---:|"]
    for r in rows:
        zero = r["min_separation"] == 0
        ratio = "" if zero or r["mode"] not in at_zero else \
            f'{r["mean_ns"] / at_zero[r["mode"]]:.2f}x'
        late = "-" if "late_tois" not in r else f'{r["late_tois"]:,}'
        err = "-" if "max_toi_error" not in r else fmt_err(r["max_toi_error"])
        out.append(f'| {separation_label(r)} | {separation_method(r)} | {fmt_time(r["mean_ns"])} | '
                   f'{ratio} | {fmt_time(r["median_ns"])} | {r["false_positives"]:,} / '
                   f'{r["false_negatives"]:,} | {late} | {err} |')
    return "\n".join(out)


def min_separation_plot(sets, path):
    """Per set: mean time against wrong verdicts + late TOIs, one marker per method, one
    colour per delta."""
    fig, axes = plt.subplots(1, len(sets), figsize=(4.6 * len(sets), 4.2), dpi=100,
                             squeeze=False)
    markers = {"float cubic": "v", "common practice": "^", "filtered": "o", "exact": "s"}
    for ax, (name, rows) in zip(axes[0], sets):
        labels = []
        for r in rows:
            if r["min_separation"] != 0 and separation_label(r) not in labels:
                labels.append(separation_label(r))
        colours = dict(zip(labels, ["#9ecae1", "#3182bd", "#08306b", "#6a51a3", "#54278f"]))
        for r in rows:
            if r["min_separation"] == 0:
                continue
            method = separation_method(r)
            wrong = r["false_positives"] + r["false_negatives"] + r.get("late_tois", 0)
            ax.scatter(r["mean_ns"], wrong, s=60, c=colours[separation_label(r)],
                       marker=markers.get(method, "D"), edgecolors="black", linewidths=0.6,
                       zorder=3, label=f"{method}, delta {separation_label(r)}")
        ax.set_xscale("log")
        ax.set_yscale("symlog", linthresh=1)
        worst = max(r["false_positives"] + r["false_negatives"] + r.get("late_tois", 0)
                    for r in rows)
        ax.set_ylim(bottom=-1, top=max(10, 6 * worst))
        ax.margins(x=0.15)
        ax.set_xlabel("mean time per query (ns, log scale)", fontsize=8)
        ax.set_ylabel("false pos. + false neg. + late TOIs", fontsize=8)
        ax.set_title(f'{name} ({rows[0]["queries"]:,} queries)', fontsize=9)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=5.5, loc="upper right", framealpha=0.9)
    fig.suptitle("Minimum separation: speed against error (every delta > 0)", fontsize=9.5)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def min_separation_section(sets, command):
    lines = ["## Minimum separation (barrier methods)", "",
             f"From `{command}`. A query comes within delta iff the Euclidean distance between "
             "the closed primitives is at most delta at some t in [0, 1]; truth and exact TOIs "
             "come from the exact path at each delta (`proofs/min_separation.md`). Methods: "
             "`common practice` (the float cubic's roots, the distance at each root compared "
             "with delta, uncertified: `float_only` with delta > 0), `filtered` (exactccd's "
             "certified path at delta, TOIs tightened to adjacent doubles), `exact` (the exact "
             "procedure alone). delta as `F x size` is F times the set's size (the diagonal of "
             "the box of all its coordinates); a bare number is an absolute delta. Late TOIs: "
             "contacts whose reported toi_lo lies after the exact toi_hi (the simulator advances "
             "past the first time within delta); max TOI error: the largest |toi_lo - exact "
             "toi_lo| over the contacts both report. `vs delta = 0`: the mean over the same "
             "mode's mean at delta = 0 in the same run.", "",
             "![minimum separation: speed against error](min_separation.png)", ""]
    for name, rows in sets:
        relative = any("min_separation_factor" in r for r in rows)
        lines += [f"### {name}", "",
                  f'{rows[0]["queries"]:,} queries' +
                  (f'; size (box diagonal) {rows[0]["size"]:.6g}.' if relative else
                   "; delta absolute."), "",
                  min_separation_table(rows), ""]
    return lines


def summary_table(datasets):
    """One row per method; per data set: mean ns/query and FP / FN / late TOIs."""
    head = "| method | " + " | ".join(
        f'{d["name"]}: ns/query | {d["name"]}: FP / FN / late' for d in datasets) + " |"
    rule = "|---|" + "|".join("---:|:---:" for _ in datasets) + "|"
    rows = [head, rule]
    for k, m in enumerate(datasets[0]["methods"]):
        cells = [m["label"] + (" (certified)" if m["certified"] else "")]
        for d in datasets:
            r = d["methods"][k]
            cells.append(fmt_ns(r["mean_ns"]))
            cells.append(f'{r["false_positives"]} / {r["false_negatives"]} / {r["late_tois"]}')
        rows.append("| " + " | ".join(cells) + " |")
    return "\n".join(rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--json", required=True, help="exactccd study --json output")
    parser.add_argument("--tables", required=True, help="exactccd study --out-md output")
    parser.add_argument("--out-dir", required=True)
    parser.add_argument("--command", required=True, help="the command that made the report")
    parser.add_argument("--study-command", default="", help="the exactccd study command it ran")
    parser.add_argument("--compiler", default="")
    parser.add_argument("--commit", default="")
    parser.add_argument("--study-status", type=int, default=0)
    parser.add_argument("--min-separation", nargs="*", default=[], metavar="NAME=FILE",
                        help="exactccd bench --json --min-separation output, one set each")
    parser.add_argument("--min-separation-command", default="",
                        help="the exactccd bench commands that made them")
    args = parser.parse_args()

    with open(args.json) as f:
        study = json.load(f)
    with open(args.tables) as f:
        tables = f.read()
    datasets = study["datasets"]

    plots = []
    for d in datasets:
        name = f'speed_vs_error_{d["name"]}.png'
        speed_vs_error_plot(d, os.path.join(args.out_dir, name))
        plots.append((d["name"], name))
    toi_error_plot(datasets, os.path.join(args.out_dir, "toi_error.png"))
    separation_sets = load_min_separation(args.min_separation)
    if separation_sets:
        min_separation_plot(separation_sets, os.path.join(args.out_dir, "min_separation.png"))

    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    timing = study["timing"]
    lines = [
        "# Speed versus error: uncertified floating-point CCD against the exact truth",
        "",
        f"Generated by `{args.command}` on {now}"
        + (f", which ran `{args.study_command}`." if args.study_command else "."),
        "",
        f"- Machine: {cpu_model()}, `nproc` = {os.cpu_count()} "
        f"({platform.system()} {platform.release()}, {platform.machine()}).",
    ]
    if args.compiler:
        lines.append(f"- Compiler: {args.compiler}; Release build.")
    if args.commit:
        lines.append(f"- Source: commit {args.commit}.")
    lines += [
        f"- Timing: single thread; mean time per query = median over {timing['repetitions']} "
        "timed samples of (sample time / queries in it), a sample being one or more whole "
        "passes over a data set (or a suite family) of at least 0.2 ms. The machine is shared, "
        "so times are indicative (a few tens of percent).",
        "- Reference: the exact first contact time t* and the verdict of the exact path "
        "(rational arithmetic, exact root isolation); see each data set's line for where they "
        "come from.",
        "- Methods: `float_only` (the classic cubic test in doubles: coplanarity roots, "
        "inclusion signs in doubles); `tolerance eps=E` (the same roots, then contact iff the "
        "distance between the primitives at the root, computed in doubles, is <= E, an "
        "ABSOLUTE distance: scale-dependent); `filtered width=W` (exactccd's certified path, "
        "TOI enclosure of width <= W, toi = its lower end); `exact` (the exact path alone).",
        "- FP / FN: false positives / false negatives against the exact verdict. Late TOIs: "
        "reported toi > t* (a missed first contact: the simulator advances past it). TOI error: "
        "reported toi minus t*, as the signed distance to the exact tightest pair of doubles "
        "around t* (resolution one ulp), over the queries both the method and the reference "
        "call a contact. 'max late by': the largest positive error.",
        "",
    ]
    if args.study_status != 0:
        lines += ["**WARNING: `exactccd study` or a minimum-separation bench exited with status "
                  f"{args.study_status}: a certified method disagreed with the reference.**", ""]
    lines += ["## Summary", "", summary_table(datasets), "",
              "FP / FN / late: false positives / false negatives / late (non-conservative) TOIs.",
              ""]
    lines += ["## Plots", ""]
    for name, png in plots:
        lines += [f"![speed versus error, {name}]({png})", ""]
    lines += ["![TOI error per method](toi_error.png)", ""]
    if separation_sets:
        lines += min_separation_section(separation_sets, args.min_separation_command)
    lines += ["## Per data set", "", tables.strip(), ""]
    with open(os.path.join(args.out_dir, "REPORT.md"), "w") as f:
        f.write("\n".join(lines))


if __name__ == "__main__":
    main()
