#!/usr/bin/python3
"""Lays out the docs screenshots (scripts/docs_screenshots.sh calls it): crops the windows that
tests/blender/docs_session.py captured to their camera frames or editors, puts related shots side
by side with a caption over each, draws a final render's passes, and writes small PNGs (256-colour
palettes) into docs/img/; the viewport session's (tests/blender/viewport_session.py) become
docs/img/ui_*.png, cropped to the editor they show.

    /usr/bin/python3 scripts/docs_images.py VIEWPORT_SESSION_DIR DOCS_SESSION_DIR DOCS_IMG_DIR

Needs Pillow and numpy (Debian's python3-pil and python3-numpy, installed by scripts/setup.sh).
"""
import glob
import json
import os
import sys

import numpy as np
from PIL import Image, ImageDraw, ImageFont

CAPTION_H, GAP = 26, 4
DARK, TEXT = (40, 40, 40), (230, 230, 230)
CHECKER = (0.18, 0.25)  # display greys of the checkerboard behind transparent pixels, as Blender's


def font(size=15):
    for name in ("DejaVuSans.ttf", "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"):
        try:
            return ImageFont.truetype(name, size)
        except OSError:
            pass
    return ImageFont.load_default()


def captioned(tile, caption):
    out = Image.new("RGB", (tile.width, tile.height + CAPTION_H), DARK)
    out.paste(tile, (0, CAPTION_H))
    ImageDraw.Draw(out).text((8, 5), caption, fill=TEXT, font=font())
    return out


def grid(tiles, columns, scale=1.0):
    """Captioned tiles (image, caption) in rows of `columns`, scaled by `scale` first."""
    if scale != 1.0:
        tiles = [(t.resize((round(t.width * scale), round(t.height * scale)), Image.LANCZOS), c) for t, c in tiles]
    cells = [captioned(t, c) for t, c in tiles]
    w, h = max(c.width for c in cells), max(c.height for c in cells)
    rows = (len(cells) + columns - 1) // columns
    out = Image.new("RGB", (columns * w + (columns - 1) * GAP, rows * h + (rows - 1) * GAP), (255, 255, 255))
    for i, cell in enumerate(cells):
        out.paste(cell, ((i % columns) * (w + GAP), (i // columns) * (h + GAP)))
    return out


def save(image, path):
    """A 256-colour palette PNG (no dithering: flat UI colours and smooth shading both compress
    well, where dithering noise would not)."""
    image.convert("RGB").quantize(colors=256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE).save(
        path, optimize=True)
    print(f"docs_images: {path} {image.width} x {image.height}, {os.path.getsize(path) // 1024} KB")


def trim(image, margin=12):
    """Cuts the margins of the background colour (the top-left pixel's) down to `margin`."""
    a = np.asarray(image.convert("RGB")).astype(int)
    content = np.abs(a - a[0, 0]).max(axis=2) > 8
    ys, xs = np.flatnonzero(content.any(axis=1)), np.flatnonzero(content.any(axis=0))
    if not len(ys):
        return image
    return image.crop((max(xs[0] - margin, 0), max(ys[0] - margin, 0),
                       min(xs[-1] + margin + 1, image.width), min(ys[-1] + margin + 1, image.height)))


# ---- a render's passes, as Blender's Image Editor shows them ----------------------------------------
def srgb(linear):
    c = np.clip(linear, 0.0, 1.0)
    return np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1.0 / 2.4) - 0.055)


def linear(display):
    return np.where(display <= 0.04045, display / 12.92, np.power((display + 0.055) / 1.055, 2.4))


def to_image(display):
    """(h, w, 3) display values, bottom row first (as the render wrote them) -> an image."""
    return Image.fromarray((np.clip(display[::-1], 0.0, 1.0) * 255.0 + 0.5).astype(np.uint8), "RGB")


def over_checker(rgba):
    """Premultiplied scene-linear RGBA over a checkerboard, to display values."""
    h, w = rgba.shape[:2]
    y, x = np.mgrid[0:h, 0:w]
    checker = np.where(((x // 12) + (y // 12)) % 2 == 0, CHECKER[0], CHECKER[1])[..., None]
    return srgb(rgba[..., :3] + (1.0 - rgba[..., 3:4]) * linear(checker))


def pass_tiles(folder):
    p = {os.path.basename(f)[:-4]: np.load(f) for f in glob.glob(os.path.join(folder, "*.npy"))}
    depth = p["Depth"][..., 0]
    drawn = depth < 1e9  # render_passes.BACKGROUND_DEPTH where nothing was drawn
    near, far = depth[drawn].min(), depth[drawn].max()
    depth_display = np.where(drawn, 1.0 - 0.85 * (depth - near) / max(far - near, 1e-9), 0.0)
    normal_display = np.where(drawn[..., None], 0.5 + 0.5 * p["Normal"][..., :3], 0.0)
    return [
        (to_image(over_checker(p["Surface"])), "Surface"),
        (to_image(over_checker(p["Highlights"])), "Highlights"),
        (to_image(over_checker(p["Lines"])), "Lines"),
        (to_image(srgb(p["Combined"][..., :3])), "Combined"),
        (to_image(np.repeat(depth_display[..., None], 3, axis=2)), "Depth (near light, for display)"),
        (to_image(normal_display), "Normal (as 0.5 + 0.5 N)"),
    ]


# The viewport session's screenshots in docs/img/ (as ui_<name>.png), each cropped to its editor
# and scaled: the 3D view to 0.6 (its shading compresses poorly: about 120 KB, not 260).
VIEWPORT_SHOTS = {"rendered": 0.6, "lines": 0.6, "properties_material": 1.0, "properties_data": 1.0,
                  "properties_world": 1.0}


def viewport_shots(session, docs):
    with open(os.path.join(session, "areas.json")) as f:
        areas = json.load(f)
    for name, scale in VIEWPORT_SHOTS.items():
        image = Image.open(os.path.join(session, name + ".png")).convert("RGB").crop(tuple(areas[name]))
        if scale != 1.0:
            image = image.resize((round(image.width * scale), round(image.height * scale)), Image.LANCZOS)
        save(image, os.path.join(docs, f"ui_{name}.png"))


def main(viewport_session, session, docs):
    with open(os.path.join(session, "shots.json")) as f:
        shots = json.load(f)

    def tile(name):
        return Image.open(os.path.join(session, name + ".png")).convert("RGB").crop(tuple(shots[name]["box"]))

    def tiles(*names):
        return [(tile(n), shots[n]["caption"]) for n in names]

    os.makedirs(docs, exist_ok=True)
    out = os.path.join(docs, "{}.png").format
    save(grid(tiles("highlights_off", "highlights_on"), 2), out("highlights_before_after"))
    save(grid(tiles("lines_silhouette", "lines_crease", "lines_border", "lines_contour",
                    "lines_marked", "lines_material", "lines_none", "lines_debug"), 4, scale=0.75), out("line_types"))
    save(grid(tiles("toon_phong", "toon_ramp", "toon_xtoon_depth", "toon_xtoon_orientation"), 2), out("toon_modes"))
    compositor = trim(tile("compositor"))
    if compositor.width > 1000:
        compositor = compositor.resize((1000, round(compositor.height * 1000 / compositor.width)), Image.LANCZOS)
    save(compositor, out("compositor_nodes"))
    save(grid(pass_tiles(os.path.join(session, "passes")), 3, scale=0.75), out("compositor_passes"))
    save(tile("clamp_note"), out("ui_radius_clamp_note"))
    viewport_shots(viewport_session, docs)


if __name__ == "__main__":
    if len(sys.argv) != 4:
        raise SystemExit(__doc__)
    main(*sys.argv[1:])
