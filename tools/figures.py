#!/usr/bin/env python3
"""Renders the paper's figures that SomiCage reproduces, and the user guide's screenshots, from the shared models.

usage: tools/figures.sh DIR [NAME...]      (run through xvfb-run by figures.sh; NAME: see FIGURES, default all)

Each figure NAME writes DIR/NAME.png and DIR/NAME.md: the command lines that made it and, for every pane, the
numbers `somicage analyze --json` gives for it (volume change, fold-overs, det J, distortion). A figure whose model
is missing from the models folder (SOMICAGE_MODELS, default ../shared/models) is skipped with a line saying so.
SOMICAGE (default build/app/somicage) is the executable; SOMICAGE_FIG09_MODELS (default cactus,botijo) the shared
models Fig. 9's plot measures besides the 2D star (empty: the star only, as the CI check runs it).
The 2D shapes (star, hexagon, L) are made here. Plots are drawn with matplotlib (Debian's python3-matplotlib).
docs/gallery.md shows the results; docs/guide.md the guide's screenshots.
"""
import json
import math
import os
import subprocess
import sys
import tempfile

import numpy as np
from PIL import Image

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.environ.get("SOMICAGE", os.path.join(ROOT, "build", "app", "somicage"))
MODELS = os.path.normpath(os.environ.get("SOMICAGE_MODELS", os.path.join(ROOT, "..", "shared", "models")))
PANE_SIZE = (340, 340)  # one pane of a figure; a shot of n panes is n * 340 wide
# Fig. 3's panes: wider, so the selected vertex's gizmo ring (100 pixels, framed inside the pane: docs/editor.md,
# "Framing") leaves the bar most of the width.
FIG03_PANE = (500, 400)
# The written PNGs have COLORS palette colours (docs/gallery stays under the budget tests/docs checks), among them
# the colours a median cut would merge into the greys because they cover few pixels, when the image has them: the
# colour maps' stops (render/color_maps.cpp: cool-warm, viridis), which the legends show, and the fold-over magenta
# (render/mesh_renderer.h, kFoldoverColor).
COLORS = 32
KEEP = [(59, 76, 192), (98, 130, 234), (141, 176, 254), (184, 208, 249), (221, 221, 221), (245, 196, 173),
        (244, 154, 123), (222, 96, 77), (180, 4, 38),
        (68, 1, 84), (71, 44, 122), (59, 82, 139), (44, 114, 142), (33, 145, 140), (40, 174, 128), (94, 201, 98),
        (173, 220, 48), (253, 231, 37),
        (230, 0, 230)]

# Shared models: (mesh, rest cage, posed cage) under MODELS.
MODEL_FILES = {
    "firehydrant": ("firehydrant/fireHydrant.obj", "firehydrant/fireHydrant_cages_triangulated.obj",
                    "firehydrant/fireHydrant_cages_triangulated_deformed.obj"),
    "manhead": ("manhead/manHead.obj", "manhead/manHead_cages_triangulated.obj",
                "manhead/manHead_cages_triangulated_deformed.obj"),
    "ogre": ("ogre/ogre.obj", "ogre/ogre_cages_triangulated.obj", "ogre/ogre_cages_triangulated_deformed.obj"),
    "cactus": ("cactus/cactus.obj", "cactus/cactus_cages_triangulated.obj",
               "cactus/cactus_cages_triangulated_deformed.obj"),
    "botijo": ("botijo/botijo.obj", "botijo/botijo_cages_triangulated.obj",
               "botijo/botijo_cages_triangulated_deformed.obj"),
    "chessbishop": ("chessbishop/chessBishop.obj", "chessbishop/bishop_cages_triangulated.obj",
                    "chessbishop/bishop_cages_triangulated_deformed.obj"),
    "wiresphere": ("wiresphere/wireSphere.obj", "wiresphere/wireSphere_cages_triangulated.obj",
                   "wiresphere/wireSphere_cages_triangulated_deformed.obj"),
}


class Skip(Exception):
    """A figure that cannot be made here (a model is absent): reported, not an error."""


def log(*words):
    print(*words, flush=True)


def run(args):
    """Runs a somicage command; a failure stops the script with the command and its output."""
    done = subprocess.run(args, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit("figures: failed (exit %d): %s\n%s%s" % (done.returncode, " ".join(args), done.stdout, done.stderr))
    return done.stdout


def shown(args):
    """A command line as the figure's .md shows it: the executable as `somicage`, files by their model path."""
    words = []
    for a in args:
        a = str(a)
        if a == EXE:
            a = "somicage"
        elif a.startswith(MODELS):
            a = "../shared/models" + a[len(MODELS):]
        elif os.path.isabs(a) and "/scenes/" in a:
            a = "scenes/" + os.path.basename(a)
        elif os.path.isabs(a) and "/somicage-figures-" in a:  # a working file of this run
            a = os.path.basename(a)
        words.append(a)
    return " ".join(words)


# ---------------------------------------------------------------------------------------------------------------
# Scenes: the shared models, and the 2D shapes made here.

def model(name):
    files = [os.path.join(MODELS, f) for f in MODEL_FILES[name]]
    missing = [f for f in files if not os.path.exists(f)]
    if missing:
        raise Skip("%s is absent" % shown(missing))
    return files


def write_obj(path, vertices, faces=(), loop=False):
    with open(path, "w") as f:
        for v in vertices:
            f.write("v %.17g %.17g %.17g\n" % (v[0], v[1], v[2] if len(v) > 2 else 0.0))
        if loop:  # a 2D cage: one polyline loop
            f.write("l " + " ".join(str(i + 1) for i in range(len(vertices))) + " 1\n")
        for t in faces:
            f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))


def web_mesh(polygon, center, rings=20, per_edge=12):
    """A triangle mesh of a polygon that is star-shaped about center: rings of the boundary scaled towards the
    center (up to 0.985 of the way out, so every vertex is strictly inside the cage), joined by triangle strips."""
    c = np.asarray(center, float)
    boundary = []
    for i in range(len(polygon)):
        a, b = np.asarray(polygon[i], float), np.asarray(polygon[(i + 1) % len(polygon)], float)
        boundary += [a + (b - a) * k / per_edge for k in range(per_edge)]
    m = len(boundary)
    vertices, faces = [tuple(c)], []
    for r in range(1, rings + 1):
        t = 0.985 * r / rings
        vertices += [tuple(c + t * (p - c)) for p in boundary]
    for k in range(m):  # the fan around the center
        faces.append([0, 1 + k, 1 + (k + 1) % m])
    for r in range(1, rings):
        inner, outer = 1 + (r - 1) * m, 1 + r * m
        for k in range(m):
            k1 = (k + 1) % m
            faces += [[inner + k, outer + k, outer + k1], [inner + k, outer + k1, inner + k1]]
    return vertices, faces


def rotate(p, center, degrees):
    a = math.radians(degrees)
    x, y = p[0] - center[0], p[1] - center[1]
    return (center[0] + x * math.cos(a) - y * math.sin(a), center[1] + x * math.sin(a) + y * math.cos(a))


def shape_2d(name):
    """(rest polygon, posed polygon, a point the polygon is star-shaped about), counter-clockwise: the paper's
    STAR (Fig. 4), hexagon and L (Fig. 10)."""
    if name == "star":
        rest = [(math.cos(math.radians(90 + 36 * k)) * (1.0 if k % 2 == 0 else 0.45),
                 math.sin(math.radians(90 + 36 * k)) * (1.0 if k % 2 == 0 else 0.45)) for k in range(10)]
        posed = list(rest)
        posed[0] = rotate(rest[0], (0, 0), -25)            # the top arm bends right
        posed[2] = (rest[2][0] * 1.25, rest[2][1] * 1.25)  # the left arm stretches
        posed[6] = rotate(rest[6], rest[5], 15)            # the lower right arm swings in
        return rest, posed, (0, 0)
    if name == "hexagon":
        rest = [(math.cos(math.radians(60 * k)), math.sin(math.radians(60 * k))) for k in range(6)]
        posed = list(rest)
        posed[1] = (rest[1][0] + 0.45, rest[1][1] + 0.35)  # one corner pulled out and sideways
        posed[4] = (rest[4][0] * 0.7, rest[4][1] * 0.7)    # the opposite one pushed in
        return rest, posed, (0, 0)
    if name == "L":
        rest = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 3), (0, 3)]
        posed = list(rest)
        posed[4] = rotate(rest[4], (0.5, 1.2), -50)  # the upright leg bends over to the right
        posed[5] = rotate(rest[5], (0.5, 1.2), -50)
        return rest, posed, (0.5, 0.5)
    raise ValueError(name)


def scene_2d(work, name):
    """Writes the 2D shape's mesh, rest and posed cage into work/scenes; returns the three paths."""
    rest, posed, center = shape_2d(name)
    folder = os.path.join(work, "scenes")
    os.makedirs(folder, exist_ok=True)
    files = [os.path.join(folder, "%s_%s.obj" % (name, part)) for part in ("mesh", "cage", "posed")]
    if not os.path.exists(files[0]):
        vertices, faces = web_mesh(rest, center)
        write_obj(files[0], vertices, faces)
        write_obj(files[1], rest, loop=True)
        write_obj(files[2], posed, loop=True)
    return files


# ---------------------------------------------------------------------------------------------------------------
# Panes: a view of the editor (METHOD[:nu=X][:gamma=Y][:variant=V]) and its numbers from `somicage analyze`.

def view_options(view, editor=False):
    """The options of one view for `analyze` (or, editor=True, for the editor, which spells the variant --local)."""
    method, *keys = view.split(":")
    values = dict(k.split("=") for k in keys)
    args = ["--method", method]
    if "nu" in values:
        args += ["--nu", values["nu"]]
    if "gamma" in values:
        args += ["--gamma", values["gamma"]]
    if "variant" in values:
        args += ["--" + values["variant"]] if editor else ["--variant", values["variant"]]
    if "tet-level" in values:
        args += ["--tet-level", values["tet-level"]]
    return args


def analyze(scene, view, extra=()):
    mesh, cage, posed = scene
    args = [EXE, "analyze", "--cage", cage, "--posed", posed, "--mesh", mesh, "--json"] + view_options(view)
    args += list(extra)
    a = json.loads(run(args))
    change = a["volume_change"] if a["volume_change"] is not None else a.get("volume_change_capped")
    return {"view": view, "volume_change": change, "capped": a["volume_change"] is None,
            "foldover_vertices": a["foldover_vertices"], "jacobian_det": a["jacobian_det"],
            "conformal_distortion_p95": a["conformal_distortion"]["p95"], "seam_jump": a.get("seam_jump"),
            "command": shown(args)}


def shot(scene, views, out, extra=(), size=None, ui=False, labels=None):
    """One editor screenshot of the scene with 1-3 panes; returns its command line. Without the panel (ui=False) a
    shared 3D model is drawn without its cage, at twice the size, and each pane zoomed onto its mesh (zoom_panes),
    and each pane is labelled (labels, default the views)."""
    width, height = size or (PANE_SIZE[0] * len(views), PANE_SIZE[1])
    zoom = 1 if ui or "/scenes/" in scene[0] else 2
    args = [EXE] + list(scene)
    if len(views) == 1:
        args += view_options(views[0], editor=True)
    else:
        for v in views:
            args += ["--view", v]
    args += list(extra) + ["--size", "%dx%d" % (zoom * width, zoom * height), "--screenshot", out]
    if not ui:
        args.append("--hide-ui")
        if zoom > 1:  # a shared 3D model: its cage's many handles would hide the mesh
            args.append("--hide-cage")
    run(args)
    if zoom > 1:
        zoom_panes(out, len(views), zoom)
    if not ui:  # --hide-ui hides the panes' titles: write each view's name over its pane
        label_panes(out, labels or views)
    return shown(args)


def editor_boxes(pane, background):
    """The editor's numbers box (top left) and legend (bottom right) in a pane, as (y, x, height, width), found by
    their fill: (20, 20, 24) at alpha 170 and 190 over the background (app/editor/ui/quantity_overlay.cpp). A row or
    column of a box has >= 10 pixels of it; a few mesh pixels of that colour do not make one."""
    H, W = pane.shape[:2]
    found = []
    for alpha, rows, cols in ((170, slice(0, H // 4), slice(0, W // 2)), (190, slice(H // 2, H), slice(W // 3, W))):
        fill = alpha / 255 * np.array([20, 20, 24]) + (1 - alpha / 255) * background
        match = np.abs(pane[rows, cols].astype(float) - fill).max(axis=2) <= 3
        ys, xs = np.nonzero(match.sum(axis=1) >= 10)[0], np.nonzero(match.sum(axis=0) >= 10)[0]
        if len(ys) and len(xs):
            found.append((rows.start + ys.min(), cols.start + xs.min(), ys.ptp() + 1, xs.ptp() + 1))
    return found


def clear_crop(mesh, boxes, size, zoom, least=0):
    """The crop (y0, x0, side) of a pane (`mesh`: its mesh's pixels) that zoom_panes scales to `size` (h, w): the
    closest (smallest side, from the mesh's box with a 5 % margin up to twice the pane: beyond the pane is background)
    that holds the mesh and keeps it out of the overlay boxes pasted back at their own size (the editor frames its
    scene clear of them, docs/editor.md "Framing"; pasted over a zoomed crop they would cover it again), and of
    those the one that centres the mesh best; `least`: the smallest side to try. Coordinates are the pane's; y0 and x0
    may be negative."""
    H, W = mesh.shape
    h, w = size
    pad = H // 2
    padded = np.pad(mesh, pad)
    inside = np.pad(padded.astype(np.int32).cumsum(0).cumsum(1), ((1, 0), (1, 0)))  # integral image

    def any_mesh(y_lo, y_hi, x_lo, x_hi):
        y_lo, y_hi = max(int(y_lo) + pad, 0), min(int(np.ceil(y_hi)) + pad, H + 2 * pad)
        x_lo, x_hi = max(int(x_lo) + pad, 0), min(int(np.ceil(x_hi)) + pad, W + 2 * pad)
        if y_lo >= y_hi or x_lo >= x_hi:
            return False
        return inside[y_hi, x_hi] - inside[y_lo, x_hi] - inside[y_hi, x_lo] + inside[y_lo, x_lo] > 0

    ys, xs = np.nonzero(mesh)
    if len(ys) == 0:
        return 0, 0, H
    pasted = [(y if y < H // 2 else h - (H - y), x if x < W // 2 else w - (W - x), bh, bw) for y, x, bh, bw in boxes]
    pasted.append((0, 0, 24, w))  # the view's name, which label_panes writes over the top
    smallest = max(least, int(np.clip(max(ys.ptp() + 1, (xs.ptp() + 1) * h / w) * 1.05, H // zoom, H)))
    for side in sorted(set(np.linspace(smallest, 2 * H, 60).astype(int))):
        sw, k = side * w // h, side / h  # pane pixels per output pixel
        best = None
        for y0 in range(max(-pad, ys.max() + 1 - side), min(ys.min(), H + pad - side) + 1, 2):
            for x0 in range(max(-pad, xs.max() + 1 - sw), min(xs.min(), W + pad - sw) + 1, 2):
                if any(any_mesh(y0 + py * k, y0 + (py + bh) * k, x0 + px * k, x0 + (px + bw) * k)
                       for py, px, bh, bw in pasted):
                    continue
                off = abs(y0 + side / 2 - (ys.min() + ys.max()) / 2) + abs(x0 + sw / 2 - (xs.min() + xs.max()) / 2)
                if best is None or off < best[0]:
                    best = (off, y0, x0)
        if best is not None:
            return best[1], best[2], side
    return 0, 0, H  # nothing clear: the whole pane


def zoom_panes(path, count, zoom):
    """The editor frames the mesh and the whole posed cage, so a 3D mesh fills little of its pane. Each pane of the
    zoom-times larger shot is cropped to a square around its mesh (at most zoom times closer: pixels stay sharp; as
    close as keeps the mesh clear of the boxes, clear_crop), scaled to the pane's size, and the editor's numbers (top
    left) and legend (bottom right) are put back on it at their own size."""
    big = np.asarray(Image.open(path).convert("RGB"))
    colours, counts = np.unique(big.reshape(-1, 3), axis=0, return_counts=True)
    background = colours[counts.argmax()]
    H, W = big.shape[0], big.shape[1] // count
    h, w = H // zoom, W // zoom
    result = Image.new("RGB", (w * count, h))
    panes = []
    for k in range(count):
        pane = big[:, k * W:(k + 1) * W]
        drawn = np.abs(pane.astype(int) - background).max(axis=2) > 12
        boxes = editor_boxes(pane, background)
        overlay = np.zeros_like(drawn)
        for y, x, bh, bw in boxes:
            overlay[y:y + bh, x:x + bw] = True
        panes.append((pane, boxes, overlay, clear_crop(drawn & ~overlay, boxes, (h, w), zoom)))
    common = max(crop[2] for _, _, _, crop in panes)  # one scale for every pane: their meshes compare
    for k, (pane, boxes, overlay, _) in enumerate(panes):
        drawn = np.abs(pane.astype(int) - background).max(axis=2) > 12
        y0, x0, side = clear_crop(drawn & ~overlay, boxes, (h, w), zoom, least=common)
        sw = side * w // h
        clean = pane.copy()
        clean[overlay] = background  # the boxes must not come along, scaled down, in the crop
        pad = H // 2  # a crop may reach beyond the pane (clear_crop): background there
        clean = np.pad(clean, ((pad, pad), (pad, pad), (0, 0)))
        clean[:pad], clean[-pad:], clean[:, :pad], clean[:, -pad:] = background, background, background, background
        crop = Image.fromarray(clean[pad + y0:pad + y0 + side, pad + x0:pad + x0 + sw]).resize((w, h), Image.LANCZOS)
        for y, x, bh, bw in boxes:  # back at their own size, as far from the same corner
            crop.paste(Image.fromarray(pane[y:y + bh, x:x + bw]), (x if x < W // 2 else w - (W - x),
                                                                    y if y < H // 2 else h - (H - y)))
        result.paste(crop, (k * w, 0))
    result.save(path)


def label_panes(path, views):
    from matplotlib import font_manager
    from PIL import ImageDraw, ImageFont
    font = ImageFont.truetype(font_manager.findfont("DejaVu Sans"), 14)
    image = Image.open(path).convert("RGB")
    draw = ImageDraw.Draw(image)
    for k, view in enumerate(views):
        text = view.replace(":", "  ").replace("somigliana", "Somigliana").replace("green", "Green") \
                   .replace("mvc", "MVC").replace("bem", "BEM").replace("phong", "Phong") \
                   .replace("nu=", "ν=").replace("gamma=", "γ=")
        x = k * image.width // len(views) + 8
        draw.rectangle(draw.textbbox((x, 6), text, font=font), fill=(30, 32, 38))
        draw.text((x, 6), text, fill=(235, 235, 235), font=font)
    image.save(path)


def save_png(images, path, vertical=True, colors=COLORS):
    """Stacks the shots (rows, or columns when not vertical) and writes them as a small palette PNG."""
    quantized(stitched(images, vertical), colors).save(path, optimize=True)


def stitched(images, vertical=True):
    """The images (files) stacked top to bottom, or left to right when not vertical, on the editor's background."""
    images = [Image.open(i).convert("RGB") for i in images]
    if vertical:
        size = (max(i.width for i in images), sum(i.height for i in images))
    else:
        size = (sum(i.width for i in images), max(i.height for i in images))
    canvas, at = Image.new("RGB", size, (46, 49, 56)), 0
    for i in images:
        canvas.paste(i, (0, at) if vertical else (at, 0))
        at += i.height if vertical else i.width
    return canvas


def quantized(image, colors=COLORS):
    """The image in `colors` palette colours, without dithering (it would cost more bytes than it saves colours):
    the KEEP colours the image has (a pixel within 8 of it), the rest a median cut."""
    pixels = np.asarray(image).reshape(-1, 3).astype(np.int16)
    keep = [c for c in KEEP if (np.abs(pixels - c).max(axis=1) <= 8).any()]
    palette = image.quantize(colors=colors - len(keep), method=Image.Quantize.MEDIANCUT).getpalette()
    palette = palette[:3 * (colors - len(keep))] + [c for rgb in keep for c in rgb]
    target = Image.new("P", (1, 1))
    target.putpalette(palette + palette[:3] * (256 - len(palette) // 3))  # the spare entries repeat colour 0
    return image.quantize(palette=target, dither=Image.Dither.NONE)


def pyplot():
    import matplotlib
    matplotlib.use("Agg")  # no display: the plots are written to files
    import matplotlib.pyplot as plt
    return plt


def save_plot(out, name, fig, axes):
    """Finishes a plot (the legend on the first axes, a light grid on all) and writes it as DIR/NAME.png."""
    axes[0].legend(fontsize=7)
    for ax in axes:
        ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    plot = os.path.join(out.work, name + "_plot.png")
    fig.savefig(plot)
    pyplot().close(fig)
    save_png([plot], os.path.join(out.dir, name + ".png"))


def percent(x):
    return "n/a" if x is None else "%+.1f %%" % (100 * x)


def write_numbers(path, title, commands, panes, notes=()):
    """NAME.md beside NAME.png: the commands that made it and each pane's analysis."""
    lines = ["# %s" % title, "", "Made by `tools/figures.sh DIR %s`, which ran:" % os.path.basename(path)[:-3], ""]
    lines += ["    " + c for c in commands]
    if panes:
        lines += ["", "| scene | view | volume change | fold-overs | det J min / median / max | distortion p95 |",
                  "|---|---|---|---|---|---|"]
        for scene, p in panes:
            j = p["jacobian_det"]
            lines.append("| %s | `%s` | %s%s | %d | %.3g / %.3g / %.3g | %.3g |" % (
                scene, p["view"], percent(p["volume_change"]), " (capped)" if p["capped"] else "",
                p["foldover_vertices"], j["min"], j["p50"], j["max"], p["conformal_distortion_p95"]))
    lines += [""] + list(notes)
    with open(path, "w") as f:
        f.write("\n".join(lines).rstrip() + "\n")


def shots(out, name, rows, extra=(), ui=False, size=None, analyzed=True):
    """rows: [(scene label, scene files, views)]; one shot per row, written to out.work. Returns the command lines,
    the panes' numbers (analyzed) and the shots' files."""
    commands, panes, images = [], [], []
    for k, (label, scene, views) in enumerate(rows):
        image = os.path.join(out.work, "%s_%d.png" % (name, k))
        commands.append(shot(scene, views, image, extra, size, ui))
        images.append(image)
        if analyzed:
            panes += [(label, analyze(scene, v)) for v in views]
    return commands, panes, images


def figure(out, name, title, rows, extra=(), ui=False, size=None, analyzed=True, vertical=True, notes=()):
    """rows: [(scene label, scene files, views)]; one shot per row, stacked."""
    commands, panes, images = shots(out, name, rows, extra, ui, size, analyzed)
    save_png(images, os.path.join(out.dir, name + ".png"), vertical)
    write_numbers(os.path.join(out.dir, name + ".md"), title, commands, panes, notes)


def editor_figure(out, name, title, args, notes=()):
    """One editor screenshot from the command line args (without --screenshot), as DIR/NAME.png and NAME.md."""
    image = os.path.join(out.work, name + "_0.png")
    args = [EXE] + list(args) + ["--screenshot", image]
    run(args)
    save_png([image], os.path.join(out.dir, name + ".png"))
    write_numbers(os.path.join(out.dir, name + ".md"), title, [shown(args)], [], notes)


# ---------------------------------------------------------------------------------------------------------------
# The figures. Panes are coloured by det J (the editor then writes each view's volume change, fold-overs and p95
# distortion under its label, and the legend on the last pane).
DETJ = ["--show", "detj"]

def hero(out):  # README: the editor with FIREHYDRANT, three panes and the det J legend (numbers: under the labels)
    figure(out, "hero", "The editor: FIREHYDRANT, MVC | Green | Somigliana (nu = 0.3, gamma = 1), det J",
           [("firehydrant", model("firehydrant"), ["mvc", "green", "somigliana"])],
           extra=DETJ + ["--nu", "0.3", "--gamma", "1", "--hide-cage"], ui=True, size=(1200, 520), analyzed=False)


def fig11(out):  # paper Figs. 1 and 11: MVC | GC | Somigliana, global, gamma = 1, nu = 0.3
    figure(out, "fig11", "Figs. 1 / 11: MVC | Green | Somigliana (global, nu = 0.3, gamma = 1)",
           [(m, model(m), ["mvc", "green", "somigliana:nu=0.3:gamma=1:variant=global"])
            for m in ("botijo", "wiresphere")], extra=DETJ)


def fig02(out):  # paper Fig. 2: MANHEAD face lift over nu x gamma, global variant
    scene = model("manhead")
    rows = [("manhead", scene, ["somigliana:nu=%s:gamma=%s" % (nu, g) for nu in ("-0.5", "0", "0.45")])
            for g in ("0", "4")]
    figure(out, "fig02", "Fig. 2: MANHEAD, nu = -0.5 / 0 / 0.45 (columns), gamma = 0 / 4 (rows), global", rows,
           extra=DETJ)


def fig03(out):  # paper Fig. 3: the 2D kernels at two nu (the built-in 2D demo)
    editor_figure(out, "fig03", "Fig. 3: |T_0 n_0| of cage vertex 0 at nu = 0 and 0.45",
                  ["--demo", "2d", "--view", "somigliana:nu=0", "--view", "somigliana:nu=0.45", "--show", "field:0",
                   "--hide-ui", "--size", "%dx%d" % (2 * FIG03_PANE[0], FIG03_PANE[1])],
                  ["The legend's range (printed as `legend field`) leaves out the most extreme 2 % of the vertices."])


def fig04(out):  # paper Fig. 4: global vs local, STAR 2D (nu = 0.38) and FIREHYDRANT (nu = 0.3), gamma = 0
    star = scene_2d(out.work, "star")
    figure(out, "fig04", "Fig. 4: global | local, STAR (nu = 0.38) and FIREHYDRANT (nu = 0.3), gamma = 0",
           [("star", star, ["somigliana:nu=0.38:variant=global", "somigliana:nu=0.38:variant=local"])] +
           [("firehydrant", model("firehydrant"),
             ["somigliana:nu=0.3:variant=global", "somigliana:nu=0.3:variant=local"])],
           extra=DETJ, vertical=False)


def fig05(out):  # paper Fig. 5: bulging, gamma sweep at nu = 0, global
    figure(out, "fig05", "Fig. 5: gamma = 0 / 2 / 4, nu = 0, global (CACTUS and the STAR)",
           [("cactus", model("cactus"), ["somigliana:nu=0:gamma=%s" % g for g in ("0", "2", "4")]),
            ("star", scene_2d(out.work, "star"), ["somigliana:nu=0:gamma=%s" % g for g in ("0", "2", "4")])],
           extra=DETJ)


def fig07(out):  # paper Fig. 7: nu = inf against Green, 2D (equal) and OGRE (not)
    figure(out, "fig07", "Fig. 7: Green | Somigliana nu = inf, gamma = 0 (hexagon 2D, OGRE): difference to Green",
           [("hexagon", scene_2d(out.work, "hexagon"), ["green", "somigliana:nu=inf:gamma=0"]),
            ("ogre", model("ogre"), ["green", "somigliana:nu=inf:gamma=0"])],
           extra=["--show", "detj,difference"], vertical=False)


def fig08(out):  # paper Fig. 8: Phong over a coarse and a finer tetrahedral mesh against Somigliana local, nu = 0
    """Shading, as the paper shows it: each method's deformed mesh (`somicage deform`) is drawn by the editor at rest
    in a box (MVC reproduces it there), so the creases where Phong's J jumps across tetrahedra show in the light.
    The numbers are `analyze`'s for the method itself."""
    scene = model("chessbishop")
    views = ["phong", "phong:tet-level=2", "somigliana:nu=0:variant=local"]
    labels = ["Phong, the cage's star (coarse)", "Phong, --tet-level 2 (finer)", "Somigliana local, ν=0"]
    folder = os.path.join(out.work, "fig08")
    os.makedirs(folder, exist_ok=True)
    commands, panes, images = [], [], []
    for k, view in enumerate(views):
        deformed = os.path.join(folder, "fig08_%d.obj" % k)
        args = [EXE, "deform", "--cage", scene[1], "--posed", scene[2], "--mesh", scene[0], "--out", deformed,
                "--quiet"] + view_options(view)
        run(args)
        commands.append(shown(args))
        box = os.path.join(folder, "fig08_%d_box.obj" % k)
        write_box(box, read_vertices(deformed))
        image = os.path.join(folder, "fig08_%d.png" % k)
        commands.append(shot([deformed, box, box], ["mvc"], image, size=(PANE_SIZE[0], 2 * PANE_SIZE[1]),
                             labels=[labels[k]]))  # tall panes: the bishop is tall
        images.append(image)
        panes.append(("bishop", analyze(scene, view, ["--seams"])))  # J's jumps across the view's tetrahedra
    # More colours than the others: a few shades of one material band like creases, which are what this shows.
    save_png(images, os.path.join(out.dir, "fig08.png"), vertical=False, colors=80)
    seams = ["Jumps of J where mesh edges cross tetrahedra (`analyze --seams`, seam_jump p50 / p95 / max):", ""]
    seams += ["- `%s`: %.3g / %.3g / %.3g" % (p["view"], p["seam_jump"]["p50"], p["seam_jump"]["p95"],
                                            p["seam_jump"]["max"]) for _, p in panes]
    write_numbers(os.path.join(out.dir, "fig08.md"),
                  "Fig. 8: Phong (the cage's star | --tet-level 2) | Somigliana local, nu = 0 (CHESSBISHOP), shaded",
                  commands, panes, seams)


def write_box(path, points):
    """A box 5 % larger than the points' bounding box, as a closed triangle cage."""
    lo, hi = points.min(axis=0), points.max(axis=0)
    center, half = (lo + hi) / 2, (hi - lo) / 2 * 1.05
    corners = [center + half * np.array([1 if i & 1 else -1, 1 if i & 2 else -1, 1 if i & 4 else -1])
               for i in range(8)]
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]  # outward
    write_obj(path, corners, [t for q in quads for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))])


def fig10(out):  # paper Fig. 10: 2D hexagon and L, MVC | GC | Somigliana global | local, gamma = 2, nu = 0.1
    rows = []
    for shape in ("hexagon", "L"):
        scene = scene_2d(out.work, shape)
        rows.append((shape, scene, ["mvc", "green"]))
        rows.append((shape, scene, ["somigliana:nu=0.1:gamma=2:variant=global",
                                    "somigliana:nu=0.1:gamma=2:variant=local"]))
    commands, panes, images = shots(out, "fig10", rows, DETJ + ["--range", "0.05:20"])  # one colour scale for all
    strips = []
    for r in range(0, 4, 2):  # one strip per shape: MVC | GC | global | local
        strip = os.path.join(out.work, "fig10_strip%d.png" % r)
        stitched(images[r:r + 2], vertical=False).save(strip)
        strips.append(strip)
    save_png(strips, os.path.join(out.dir, "fig10.png"))
    write_numbers(os.path.join(out.dir, "fig10.md"),
                  "Fig. 10: MVC | Green | Somigliana global | local, gamma = 2, nu = 0.1 (hexagon, L)", commands, panes)


def read_vertices(path):
    with open(path) as f:
        return np.array([[float(x) for x in line.split()[1:4]] for line in f if line.startswith("v ")])


def scaled_pose(work, scene, a):
    """The rest cage plus a times the pose's displacement, written as an OBJ with the rest cage's other lines."""
    mesh, cage, posed = scene
    rest, moved = read_vertices(cage), read_vertices(posed)
    path = os.path.join(work, "scenes", "%s_a%g.obj" % (os.path.basename(cage)[:-4], a))
    os.makedirs(os.path.dirname(path), exist_ok=True)
    vertices = iter(rest + a * (moved - rest))
    with open(cage) as src, open(path, "w") as dst:
        for line in src:
            dst.write("v %.17g %.17g %.17g\n" % tuple(next(vertices)) if line.startswith("v ") else line)
    return path


def fig09(out):  # paper Fig. 9: distance to BEM against the pose's amplitude (global, nu = 0, gamma = 2)
    amplitudes = [1, 0.3, 0.1, 0.03, 0.01]
    methods = {"Somigliana": ["--method", "somigliana", "--nu", "0", "--gamma", "2"], "MVC": ["--method", "mvc"]}
    scenes = [("star (2D)", scene_2d(out.work, "star"))]
    skipped = []
    for name in filter(None, os.environ.get("SOMICAGE_FIG09_MODELS", "cactus,botijo").split(",")):
        try:
            scenes.append((name, model(name)))
        except Skip as e:
            skipped.append("Skipped %s: %s." % (name, e))
    rows, commands = [], []
    for label, scene in scenes:
        mesh, cage, _ = scene
        rest_cage, rest_mesh = read_vertices(cage), read_vertices(mesh)
        diameter = np.linalg.norm(rest_cage.max(axis=0) - rest_cage.min(axis=0))
        for a in amplitudes:
            posed = scaled_pose(out.work, scene, a)
            result = {}
            for m, options in [("BEM", ["--method", "bem", "--nu", "0"])] + list(methods.items()):
                path = os.path.join(out.work, "fig09_out.obj")
                args = [EXE, "deform", "--cage", cage, "--posed", posed, "--mesh", mesh, "--out", path] + options
                run(args)
                if a == 1:
                    commands.append(shown(args))
                result[m] = read_vertices(path)
            displacement = np.linalg.norm(result["BEM"] - rest_mesh, axis=1).max() / diameter
            for m in methods:
                distance = np.linalg.norm(result[m] - result["BEM"], axis=1).max() / diameter
                rows.append((label, m, a, distance, displacement))
    plt = pyplot()
    fig, (left, right) = plt.subplots(1, 2, figsize=(9, 3.4), dpi=80)
    for k, (label, _) in enumerate(scenes):
        for m, style in (("Somigliana", "-o"), ("MVC", "--s")):
            pts = [(r[2], r[3], r[3] / r[4]) for r in rows if r[0] == label and r[1] == m]
            colour = "C%d" % k
            left.loglog([p[0] for p in pts], [p[1] for p in pts], style, color=colour, label="%s, %s" % (m, label))
            right.semilogx([p[0] for p in pts], [p[2] for p in pts], style, color=colour)
    left.set(xlabel="amplitude a of the pose", ylabel="max |x - x_BEM| / cage diameter",
             title="distance to BEM (nu = 0)")
    right.set(xlabel="amplitude a of the pose", ylabel="max distance / max BEM displacement",
              title="relative to the displacement", ylim=(0, None))
    save_plot(out, "fig09", fig, [left, right])
    table = ["| scene | method | amplitude a | max distance to BEM (diameters) | max BEM displacement | ratio |",
             "|---|---|---|---|---|---|"]
    table += ["| %s | %s | %g | %.3g | %.3g | %.3f |" % (r[0], r[1], r[2], r[3], r[4], r[3] / r[4]) for r in rows]
    write_numbers(os.path.join(out.dir, "fig09.md"),
                  "Fig. 9: distance to BEM against the pose's amplitude (Somigliana global, nu = 0, gamma = 2; MVC)",
                  commands + ["(and the same for each amplitude a: the posed cage is rest + a (posed - rest))"], [],
                  table + [""] + skipped)
    # The panes: BEM | Somigliana | MVC at a = 1 on the star, coloured by the distance to BEM.
    views = ["bem:nu=0", "somigliana:nu=0:gamma=2", "mvc"]
    figure(out, "fig09_panes", "Fig. 9 panes: BEM | Somigliana (nu = 0, gamma = 2) | MVC, distance to BEM",
           [(label, scene, views) for label, scene in scenes[:2]], extra=["--show", "detj,difference,difference"])


def fig06(out):  # paper Fig. 6: partition-of-unity error against the quadrature points per triangle
    mesh, cage, posed = model("firehydrant")
    rows, commands, exact = [], [], []
    for n in (2, 4, 8, 16, 32, 50):
        args = [EXE, "bench", "--mesh", mesh, "--cage", cage, "--posed", posed, "--frames", "1", "--repeat", "1",
                "--baseline-quadrature", str(n), "--baseline-points", "300", "--json"]
        b = json.loads(run(args))
        commands.append(shown(args))
        rows.append((3 * n * n, b["baseline_pou_max"], b["baseline_speedup"]))
        exact.append(b["pou_max"])
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6, 3.4), dpi=80)
    ax.loglog([r[0] for r in rows], [r[1] for r in rows], "-o", label="paper's Gauss rule (3 N² points)")
    ax.axhline(max(exact), color="C2", label="SomiCage's closed form (max %.1e)" % max(exact))
    ax.axhline(1e-2, color="0.5", ls=":", label="paper: no visible artifacts below 1e-2")
    ax.set(xlabel="quadrature points per cage triangle", ylabel="max |Σ T_i − I| (300 points)",
           title="FIREHYDRANT: partition of unity")
    save_plot(out, "fig06", fig, [ax])
    table = ["| points per triangle | max partition-of-unity error | Gauss time / closed-form time |", "|---|---|---|"]
    table += ["| %d | %.3g | %.0f× |" % r for r in rows]
    table += ["", "Closed form on all 39,028 vertices: max %.3g." % max(exact)]
    write_numbers(os.path.join(out.dir, "fig06.md"), "Fig. 6: partition of unity against quadrature points",
                  commands, [], table)


# The user guide's screenshots (docs/guide.md), with the editor's panel.
def guide_editor(out):
    figure(out, "guide_editor", "Guide: the editor on FIREHYDRANT",
           [("firehydrant", model("firehydrant"), ["somigliana:nu=0.3"])], ui=True, size=(1000, 560),
           analyzed=False)


def guide_pose(out):  # --show field:N selects cage vertex N, so its gizmo is drawn
    figure(out, "guide_pose", "Guide: a selected handle and its gizmo (cage vertex 30)",
           [("firehydrant", model("firehydrant"), ["somigliana:nu=0.3"])], extra=["--show", "field:30"], ui=True,
           size=(1000, 560), analyzed=False)


def guide_analysis(out):
    figure(out, "guide_analysis", "Guide: det J | distortion | fold-overs, CACTUS, local variant at nu = 0.3",
           [("cactus", model("cactus"), ["somigliana:nu=0.3:variant=local"] * 3)],
           extra=["--show", "detj,distortion,foldover", "--range", "0.1:10"])  # the automatic range would reach 6,000


def guide_nuplot(out):
    figure(out, "guide_nuplot", "Guide: Sweep nu (volume change and fold-overs against nu)",
           [("cactus", model("cactus"), ["somigliana:nu=0.3:variant=local"])],
           extra=["--nu-plot"], ui=True, size=(1000, 560), analyzed=False)


def guide_makecage(out):
    figure(out, "guide_makecage", "Guide: File > Make cage... with 200 faces",
           [("botijo", model("botijo")[:1], ["somigliana"])],
           extra=["--make-cage", "200"], ui=True, size=(1000, 560), analyzed=False)


def keyed_session(out):
    """A session of CACTUS with two poses, rest and bent (the paper's pose), keyed at frames 1 and 48 (the pose
    library and the timeline show); written once into out.work, its path returned."""
    path = os.path.join(out.work, "keyed_session.json")
    if os.path.exists(path):
        return path
    mesh, cage, posed = model("cactus")
    rest, moved = read_vertices(cage), read_vertices(posed)
    points = np.vstack([read_vertices(mesh), rest, moved])
    lo, hi = points.min(axis=0), points.max(axis=0)
    radius = 0.5 * np.linalg.norm(hi - lo)
    half_fov = math.radians(35) / 2  # the editor's framing (app/editor/interaction/camera.cpp, OrbitCamera::frame)
    session = {
        "format": "somicage-session", "version": 3, "mesh": mesh, "cage": cage, "demoDim": 3,
        "pose": moved.tolist(), "method": "somigliana",
        "params": {"blend": 0, "nu": 0.3, "gamma": 0, "tractionCorrection": True, "corotational": False},
        "compare": False, "compareMethods": [],
        "camera": {"target": ((lo + hi) / 2).tolist(), "distance": 1.1 * radius / math.sin(half_fov),
                   "yaw": 0.6, "pitch": 0.35},
        "poses": [{"name": "rest", "vertices": rest.tolist()}, {"name": "bent", "vertices": moved.tolist()}],
        "timeline": {"fps": 24, "first": 1, "last": 48, "loop": True, "interpolation": "catmull-rom",
                     "keys": [{"frame": 1, "pose": "rest"}, {"frame": 48, "pose": "bent"}]},
    }
    with open(path, "w") as f:
        json.dump(session, f)
    return path


SESSION_NOTE = "keyed_session.json: CACTUS with the poses rest and bent (its shared pose), keyed at frames 1 and 48."


def guide_timeline(out):
    editor_figure(out, "guide_timeline", "Guide: poses and keys (CACTUS, rest at frame 1, the paper's pose at 48)",
                  ["--session", keyed_session(out), "--size", "1000x560"], [SESSION_NOTE])


def guide_export(out):  # the file name is absolute so that the dialog does not show this run's working folder
    editor_figure(out, "guide_export", "Guide: File > Export animation... (the keyed CACTUS session)",
                  ["--session", keyed_session(out), "--export-dialog", "/tmp/cactus.glb", "--size", "1000x560"],
                  [SESSION_NOTE])


FIGURES = {"hero": hero, "fig02": fig02, "fig03": fig03, "fig04": fig04, "fig05": fig05, "fig06": fig06,
           "fig07": fig07, "fig08": fig08, "fig09": fig09, "fig10": fig10, "fig11": fig11,
           "guide_editor": guide_editor, "guide_pose": guide_pose, "guide_analysis": guide_analysis,
           "guide_nuplot": guide_nuplot, "guide_makecage": guide_makecage, "guide_timeline": guide_timeline,
           "guide_export": guide_export}


class Output:
    def __init__(self, folder, work):
        self.dir, self.work = folder, work


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        print(__doc__ + "\nfigures: " + " ".join(FIGURES))
        return 0 if len(argv) >= 2 else 2
    names = argv[2:] or list(FIGURES)
    unknown = [n for n in names if n not in FIGURES]
    if unknown:
        print("figures: unknown figure %s; the figures are: %s" % (", ".join(unknown), " ".join(FIGURES)),
              file=sys.stderr)
        return 2
    if not os.access(EXE, os.X_OK):
        print("figures: no executable %s: build it (cmake --build build --target somicage) or set SOMICAGE" % EXE,
              file=sys.stderr)
        return 2
    os.makedirs(argv[1], exist_ok=True)
    skipped = []
    with tempfile.TemporaryDirectory(prefix="somicage-figures-") as work:
        for name in names:
            log("figures: %s ..." % name)
            try:
                FIGURES[name](Output(argv[1], work))
            except Skip as e:
                skipped.append(name)
                log("figures: SKIPPED %s: %s" % (name, e))
    log("figures: done in %s%s" % (argv[1], "; skipped: " + " ".join(skipped) if skipped else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
