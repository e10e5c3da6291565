#!/usr/bin/env python3
"""Pictures of the "robust cloth" scene (bench/scenes/cloth.cpp).

    python3 bench/scenes/plot_cloth.py [DIR]      (DIR: the program's --out, by default
                                                   bench/scenes/out/cloth)

Writes into DIR:
  cloth_moments.png   the cloth over the spike and the wedge at eight moments (before, first
                      impact, landing and folding onto itself, at rest, end), shaded, with a
                      checker red on the top side and ochre underneath so that folds show;
  cloth_final.png     the last moment, large;
  cloth_steps.png     per step: contacts (cloth-obstacle, cloth-cloth), response rounds, CCD
                      time and intersection-check time, intersecting pairs (violations).

Needs matplotlib and numpy (Debian: `bash .ci/install-deps.sh --with-plots`).
"""
import json
import os
import sys


def _import_matplotlib():
    try:
        import matplotlib  # noqa: F401
        import numpy  # noqa: F401
    except ImportError:
        # install-deps.sh installs Debian's python3-matplotlib, which only the system
        # interpreter sees; run under it when the python3 on PATH is another one.
        system = "/usr/bin/python3"
        if os.path.realpath(sys.executable) != os.path.realpath(system) and os.path.exists(system):
            os.execv(system, [system] + sys.argv)
        sys.exit("plot_cloth.py: needs matplotlib and numpy "
                 "(bash .ci/install-deps.sh --with-plots)")


_import_matplotlib()

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

LIGHT = np.array([-0.45, -0.35, 0.82])
LIGHT = LIGHT / np.linalg.norm(LIGHT)
# The cloth: a 10 x 10 checker on each side, red on the side that faces up at the start, ochre
# underneath, so that folds and pleats read.
TOP_COLOURS = (np.array([0.78, 0.16, 0.14]), np.array([0.93, 0.52, 0.44]))
UNDER_COLOURS = (np.array([0.90, 0.62, 0.12]), np.array([0.98, 0.85, 0.50]))
OBSTACLE_COLOUR = np.array([0.55, 0.60, 0.68])
FLOOR_COLOURS = (np.array([0.93, 0.92, 0.89]), np.array([0.86, 0.85, 0.82]))


def normals(points, triangles):
    a, b, c = (points[triangles[:, k]] for k in range(3))
    n = np.cross(b - a, c - a)
    length = np.linalg.norm(n, axis=1, keepdims=True)
    return n / np.where(length > 0, length, 1.0)


def subdivide(points, triangles, k):
    """Each triangle into k*k smaller ones (for the painter's algorithm of mplot3d)."""
    out = []
    for t in triangles:
        a, b, c = points[t]
        grid = {}
        for i in range(k + 1):
            for j in range(k + 1 - i):
                grid[i, j] = a + (b - a) * i / k + (c - a) * j / k
        for i in range(k):
            for j in range(k - i):
                out.append([grid[i, j], grid[i + 1, j], grid[i, j + 1]])
                if i + j + 2 <= k:
                    out.append([grid[i + 1, j], grid[i + 1, j + 1], grid[i, j + 1]])
    return np.array(out)


def shade(base, n, view, two_sided):
    lambert = n @ LIGHT
    if two_sided:
        lambert = np.abs(lambert)
    lambert = np.clip(lambert, 0.0, 1.0)
    # A little specular-like lift towards the viewer, so that folds read.
    facing = np.clip(np.abs(n @ view), 0.0, 1.0)
    intensity = 0.38 + 0.52 * lambert + 0.10 * facing
    return np.clip(base * intensity[:, None], 0.0, 1.0)


class Scene:
    def __init__(self, folder):
        with open(os.path.join(folder, "summary.json")) as f:
            self.summary = json.load(f)
        s = self.summary
        self.folder = folder
        self.floor_z = s["settings"]["floor_z"]
        self.n = s["cloth"]["n"]
        self.cloth_triangles = np.array(s["cloth"]["triangles_list"], dtype=np.int64)
        self.obstacles = []
        for name in ("spike", "wedge"):
            m = s["obstacles"][name]
            self.obstacles.append((np.array(m["vertices"]), np.array(m["triangles"])))
        self.frames = {f["step"]: f["file"] for f in s["frames"]}
        # Checker square of each triangle: that of its grid cell, the smallest column and row of
        # its vertices (vertex = row * n + column).
        t = self.cloth_triangles
        column = (t % self.n).min(axis=1)
        row = (t // self.n).min(axis=1)
        size = max(1.0, (self.n - 1) / 10)
        self.checker = ((column // size + row // size) % 2) == 0
        self.z_top = 0.8  # raised by draw_range to the highest point drawn

    def draw_range(self, steps):
        for step in steps:
            self.z_top = max(self.z_top, float(self.cloth(step)[:, 2].max()) - self.floor_z)

    def cloth(self, step):
        data = np.fromfile(os.path.join(self.folder, self.frames[step]), dtype="<f8")
        return data.reshape(-1, 3)

    def floor_quads(self, half, cells):
        edges = np.linspace(-half, half, cells + 1)
        quads, colours = [], []
        for i in range(cells):
            for j in range(cells):
                x0, x1, y0, y1 = edges[i], edges[i + 1], edges[j], edges[j + 1]
                quads.append([[x0, y0, 0], [x1, y0, 0], [x1, y1, 0], [x0, y1, 0]])
                colours.append(FLOOR_COLOURS[(i + j) % 2])
        return quads, colours

    def draw(self, ax, step, title, elev=24, azim=-122, zoom=1.3):
        x = self.cloth(step).copy()
        x[:, 2] -= self.floor_z
        azim_r, elev_r = np.radians(azim), np.radians(elev)
        view = np.array([np.cos(elev_r) * np.cos(azim_r), np.cos(elev_r) * np.sin(azim_r),
                         np.sin(elev_r)])
        # The painter's algorithm of mplot3d sorts polygons by depth. The floor lies under
        # everything, so it is drawn first on its own; cloth resting on an obstacle ties with
        # it in depth, so in this orthographic view the cloth is moved a little towards the
        # viewer (which moves no pixel, only the depth order), and the obstacles are cut into
        # small triangles so that their depths are local.
        ax.computed_zorder = False
        quads, floor_colours = self.floor_quads(0.6, 12)
        floor = Poly3DCollection(quads, facecolors=floor_colours, edgecolors="none",
                                 linewidths=0, antialiased=False, zorder=0)
        ax.add_collection3d(floor)
        polys, colours = [], []
        for points, triangles in self.obstacles:
            p = points.copy()
            p[:, 2] -= self.floor_z
            small = subdivide(p, triangles, 16)
            a, b, c = small[:, 0], small[:, 1], small[:, 2]
            n = np.cross(b - a, c - a)
            n /= np.linalg.norm(n, axis=1, keepdims=True)
            polys.extend(small)
            colours.extend(shade(OBSTACLE_COLOUR, n, view, True))
        t = self.cloth_triangles
        n = normals(x, t)
        # The grid's triangles are wound so that n points up at the start: the side the viewer
        # sees is the top side where n faces the viewer.
        top = (n @ view) >= 0
        square = self.checker
        side = np.where(top[:, None],
                        np.where(square[:, None], TOP_COLOURS[0], TOP_COLOURS[1]),
                        np.where(square[:, None], UNDER_COLOURS[0], UNDER_COLOURS[1]))
        lambert = np.clip(np.abs(n @ LIGHT), 0.0, 1.0)
        intensity = 0.45 + 0.55 * lambert
        polys.extend(x[t] + 0.015 * view)
        colours.extend(np.clip(side * intensity[:, None], 0, 1))
        collection = Poly3DCollection(polys, facecolors=colours, edgecolors="none",
                                      linewidths=0, antialiased=False, zorder=1)
        ax.add_collection3d(collection)
        ax.set_proj_type("ortho")
        ax.set_xlim(-0.6, 0.6)
        ax.set_ylim(-0.6, 0.6)
        ax.set_zlim(0.0, self.z_top)
        ax.set_box_aspect((1.2, 1.2, self.z_top), zoom=zoom)
        ax.view_init(elev=elev, azim=azim)
        ax.set_axis_off()
        ax.set_title(title, fontsize=12, pad=-4)


def moments(scene, interior=4):
    """(step, title) of the saved frames to show: the start, the first impact, `interior`
    frames spread between it and the step where the cloth has come to rest (its mean speed
    below 5% of its peak; the one with the most cloth-cloth contacts titled "folding onto
    itself"), that step, and the end."""
    s = scene.summary
    saved = sorted(scene.frames)
    dt = s["settings"]["dt"]
    per_step = {st["step"]: st for st in s["steps"]}

    def nearest(step):
        return min(saved, key=lambda k: (abs(k - step), k))

    first = s["events"]["first_contact_step"]
    if first < 0:  # no contact at all: frames spread evenly
        count = interior + 4
        picks = {saved[round(i * (len(saved) - 1) / (count - 1))] for i in range(count)}
        return [(k, f"step {k}, t = {k * dt:.2f} s") for k in sorted(picks)]
    speeds = [(st["step"], st["mean_speed"]) for st in s["steps"]]
    peak = max(range(len(speeds)), key=lambda i: speeds[i][1])
    rest = next((step for step, v in speeds[peak:] if v < 0.05 * speeds[peak][1]),
                speeds[-1][0])
    titles = {saved[0]: "before", nearest(first): "first impact", saved[-1]: "end"}
    titles.setdefault(nearest(rest), "at rest")
    between = []
    for i in range(1, interior + 1):
        k = nearest(first + (rest - first) * i / (interior + 1))
        if k not in titles:
            titles[k] = "landing"
            between.append(k)
    if between:
        fold = max(between, key=lambda k: (per_step[k]["self_contacts"] if k in per_step else 0))
        if fold in per_step and per_step[fold]["self_contacts"] > 0:
            titles[fold] = "folding onto itself"
    return [(k, f"{titles[k]}: step {k}, t = {k * dt:.2f} s") for k in sorted(titles)]


def plot_moments(scene, path):
    chosen = moments(scene)
    scene.draw_range(k for k, _ in chosen)
    columns = 4
    rows = (len(chosen) + columns - 1) // columns
    fig = plt.figure(figsize=(5.0 * columns, 5.6 * rows))
    height = 0.93 / rows
    for k, (step, title) in enumerate(chosen):
        row, column = divmod(k, columns)
        ax = fig.add_axes([column / columns, 0.93 - (row + 1) * height, 1 / columns, height],
                          projection="3d")
        ax.patch.set_alpha(0.0)
        scene.draw(ax, step, title, zoom=1.2)
    s = scene.summary
    fig.suptitle(f"{s['cloth']['n']} x {s['cloth']['n']} cloth dropped on a spike and a wedge, "
                 f"dt = {s['settings']['dt']:.3g} s: {s['totals']['violations']} "
                 f"intersecting triangle pairs in {len(s['steps'])} steps (exact test, every "
                 f"step)", fontsize=16, y=0.985)
    fig.savefig(path, dpi=90)
    plt.close(fig)


def plot_final(scene, path):
    last = max(scene.frames)
    scene.z_top = 0.8
    scene.draw_range([last])
    s = scene.summary
    fig = plt.figure(figsize=(10, 7.5))
    ax = fig.add_axes([-0.1, 0.0, 1.2, 1.3], projection="3d")
    scene.draw(ax, last, "", elev=32, azim=-135, zoom=1.6)
    fig.text(0.5, 0.96, f"after {last} steps of {s['settings']['dt']:.3g} s: every step certified "
             f"contact-free by exact CCD, {s['totals']['violations']} intersecting triangle pairs",
             ha="center", va="top", fontsize=13)
    fig.savefig(path, dpi=130)
    plt.close(fig)


def plot_steps(scene, path):
    steps = scene.summary["steps"]
    k = np.array([s["step"] for s in steps])
    obstacle = np.array([s["obstacle_contacts"] for s in steps])
    self_ = np.array([s["self_contacts"] for s in steps])
    rounds = np.array([s["rounds"] for s in steps])
    ccd = np.array([s["ccd_ms"] for s in steps])
    check = np.array([s["check_ms"] for s in steps])
    violations = np.array([s["violations"] for s in steps])
    pinned = np.array([s["pinned"] for s in steps])
    stopped = np.array([s["stopped"] for s in steps])

    fig, axes = plt.subplots(3, 1, figsize=(10, 10), sharex=True)
    ax = axes[0]
    ax.bar(k, obstacle, color="#7f8ea3", label="cloth-obstacle")
    ax.bar(k, self_, bottom=obstacle, color="#c8382e", label="cloth-cloth")
    ax.set_ylabel("contacts of the proposed motion")
    ax.legend(loc="upper left", frameon=False)
    ax.set_title("Contacts, response and cost per step")

    ax = axes[1]
    ax.plot(k, stopped, color="#e0a030", label="vertices stopped short of their TOI")
    ax.plot(k, pinned, color="#4060a0", label="vertices pinned at their start")
    ax.set_ylabel("vertices")
    twin = ax.twinx()
    twin.step(k, rounds, where="mid", color="black", lw=1.2, label="rounds")
    twin.set_ylabel("rounds (CCD calls with contacts)")
    twin.set_ylim(0, max(3, rounds.max() + 1))
    lines = ax.get_legend_handles_labels()
    lines2 = twin.get_legend_handles_labels()
    ax.legend(lines[0] + lines2[0], lines[1] + lines2[1], loc="upper left", frameon=False)

    ax = axes[2]
    ax.plot(k, ccd, color="#2a7f62", label="CCD (all rounds)")
    ax.plot(k, check, color="#9b59b6", label="exact triangle-triangle check")
    ax.set_ylabel("ms per step")
    ax.set_xlabel("step")
    ax.set_ylim(bottom=0)
    ax.legend(loc="upper left", frameon=False)
    total = int(violations.sum())
    ax.text(0.99, 0.95, f"intersecting triangle pairs, all steps: {total}",
            transform=ax.transAxes, ha="right", va="top", fontsize=11,
            color="#2a7f62" if total == 0 else "red")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else "bench/scenes/out/cloth"
    scene = Scene(folder)
    outputs = [("cloth_moments.png", plot_moments), ("cloth_final.png", plot_final),
               ("cloth_steps.png", plot_steps)]
    for name, plot in outputs:
        path = os.path.join(folder, name)
        plot(scene, path)
        print(path)


if __name__ == "__main__":
    main()
