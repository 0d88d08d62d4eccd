"""The world's environment image, filtered for lighting (docs/highlight_math.md, "The world's
environment"): one RGBA32F atlas of equirectangular tiles that shaders/environment.glsl reads.

- Specular levels at GGX roughness 0, 1/4, 1/2, 3/4 and 1: the radiance the split sum's first
  factor needs, prefiltered with the lobe D(h) (n.l) under n = v = r (Karis). Level 0 is the
  image itself, downsampled.
- The irradiance tile: E(n) / pi, the cosine-weighted mean radiance, which a Lambertian albedo
  scales into outgoing radiance.

Level 0 keeps the image's texels (rows at their centres). The filtered tiles hold values at
directions whose rows run from pole to pole, both included (tile_directions): the value at a
pole is one direction's, the same in every column, so a floor's normal, pointing exactly there,
reads it (with rows at texel centres, the last row is 5 degrees short of the pole and differs
by azimuth, and a floor read one azimuth's value: 19 % too bright under Blender's courtyard).

Directions follow Blender's Environment Texture (equirectangular): u = 1/2 - atan2(y, x) / 2pi,
v = 1/2 + asin(z) / pi, row 0 at v = 0 (Blender's pixels start at the bottom row). A uniform
image gives its own value in every tile, so a plain world colour and an image of that colour
light alike. No bpy: the add-on hands in the pixels (world_light.py)."""
from dataclasses import dataclass

import numpy as np

# (width, height) of each specular level past the first, and its GGX roughness: a level's texels
# are about a quarter of its lobe's width (alpha = roughness^2), so the filter samples the lobe
# well. Level 0 (a mirror, and the background) is the image at its own width, within
# TOP_WIDTH: a small image is not enlarged (the lookup blends its texels, as EEVEE's does).
SPECULAR_LEVELS = ((512, 256), (128, 64), (64, 32), (32, 16), (32, 16))
TOP_WIDTH = (16, 2048)
ROUGHNESS = tuple(k / (len(SPECULAR_LEVELS) - 1) for k in range(len(SPECULAR_LEVELS)))
IRRADIANCE = (32, 16)
# The resolution each filtered tile is computed on (box-filtered from level 0), then box-filtered
# to the tile: finer than the tile.
_SOURCE = ((256, 128), (128, 64), (64, 32), (64, 32))
_IRRADIANCE_SOURCE = (64, 32)


@dataclass(frozen=True)
class EnvironmentAtlas:
    pixels: np.ndarray    # (height, width, 4) float32, scene-linear, alpha 1
    levels: tuple         # (x, y, w, h) texel rect of each specular level, ROUGHNESS order
    irradiance: tuple     # (x, y, w, h) of the irradiance tile
    mean: tuple           # the image's mean radiance over the sphere (by solid angle), rgb


def directions(w, h):
    """(h, w, 3) unit directions at the texel centres of a w x h equirectangular image."""
    u = (np.arange(w) + 0.5) / w
    v = (np.arange(h) + 0.5) / h
    phi = (0.5 - u) * 2.0 * np.pi
    el = (v - 0.5) * np.pi
    ce = np.cos(el)[:, None]
    return np.stack(np.broadcast_arrays(ce * np.cos(phi)[None, :], ce * np.sin(phi)[None, :],
                                        np.sin(el)[:, None]), axis=-1)


def tile_directions(w, h):
    """(h, w, 3) unit directions of a filtered tile: columns at their centres, rows from the
    south pole (row 0) to the north pole (row h - 1), both included."""
    u = (np.arange(w) + 0.5) / w
    phi = (0.5 - u) * 2.0 * np.pi
    el = (np.arange(h) / (h - 1) - 0.5) * np.pi
    ce = np.cos(el)[:, None]
    return np.stack(np.broadcast_arrays(ce * np.cos(phi)[None, :], ce * np.sin(phi)[None, :],
                                        np.sin(el)[:, None]), axis=-1)


def solid_angles(w, h):
    """(h,) solid angle of one texel in each row: 2pi / w times the row's band of sin(elevation)."""
    edges = np.sin((np.arange(h + 1) / h - 0.5) * np.pi)
    return (2.0 * np.pi / w) * np.diff(edges)


def resample(px, w, h):
    """(h, w, c) box-filtered image: texels averaged over the source texels they cover (rows by
    their solid angle, so the poles weigh what they cover), or repeated where the source is
    coarser."""
    hi, wi = px.shape[:2]
    if wi >= w:
        cols = np.add.reduceat(px, np.arange(w) * wi // w, axis=1)
        cols /= np.diff(np.append(np.arange(w) * wi // w, wi))[None, :, None]
    else:
        cols = px[:, np.arange(w) * wi // w]
    if hi >= h:
        starts = np.arange(h) * hi // h
        sa = solid_angles(wi, hi)[:, None, None]
        rows = np.add.reduceat(cols * sa, starts, axis=0)
        rows /= np.maximum(np.add.reduceat(sa, starts, axis=0), 1e-30)
        return rows.astype(np.float32)
    return cols[np.arange(h) * hi // h].astype(np.float32)


def _convolve(src, weight, out_rows):
    """(out_rows, w, 3) filtered image, the source's columns and rows from pole to pole
    (tile_directions): per output direction r, the sum of L(l) weight(r.l) dw over the source's
    texels l, over the sum of weight(r.l) dw (normalised: a uniform source gives itself). The
    weight depends on r's row, l's row and their azimuths' difference only, so each pair of rows
    is a circular convolution along the row: one FFT."""
    h, w = src.shape[:2]
    el_in = ((np.arange(h) + 0.5) / h - 0.5) * np.pi
    el = (np.arange(out_rows) / (out_rows - 1) - 0.5) * np.pi
    dphi = np.arange(w) * (2.0 * np.pi / w)
    cos_t = (np.sin(el)[:, None, None] * np.sin(el_in)[None, :, None]
             + np.cos(el)[:, None, None] * np.cos(el_in)[None, :, None] * np.cos(dphi)[None, None, :])
    k = weight(cos_t) * solid_angles(w, h)[None, :, None]  # (out row, source row, azimuth step)
    k_hat = np.fft.rfft(k, axis=2)
    l_hat = np.fft.rfft(src.astype(np.float64), axis=1)  # (source row, frequency, rgb)
    out = np.fft.irfft(np.einsum("oif,ifc->ofc", k_hat, l_hat), n=w, axis=1)
    return out / np.maximum(k.sum(axis=(1, 2)), 1e-300)[:, None, None]


def _columns(tile, w):
    """A filtered tile box-filtered along its rows to w columns (its rows stay: they are
    directions, the poles among them)."""
    ws = tile.shape[1]
    starts = np.arange(w) * ws // w
    out = np.add.reduceat(tile, starts, axis=1) / np.diff(np.append(starts, ws))[None, :, None]
    return out.astype(np.float32)


def ggx_weight(roughness):
    """The prefilter's weight of a direction at cos_t to the reflection r: D(h) (n.l) with
    n = v = r, so n.h = cos(t / 2); GGX with alpha = roughness^2."""
    a2 = max(roughness, 1e-3) ** 4

    def weight(cos_t):
        nh2 = np.clip(0.5 * (1.0 + cos_t), 0.0, 1.0)
        d = a2 / (np.pi * (nh2 * (a2 - 1.0) + 1.0) ** 2)
        return d * np.maximum(cos_t, 0.0)
    return weight


def cosine_weight(cos_t):
    return np.maximum(cos_t, 0.0)


def prefilter(rgb):
    """The atlas of an (h, w, 3) scene-linear equirectangular image (finite, non-negative:
    world_light.py cleans it)."""
    rgb = np.asarray(rgb, np.float32)
    top = int(np.clip(rgb.shape[1], *TOP_WIDTH))
    base = resample(rgb, top, top // 2)
    src = base if top >= _SOURCE[0][0] else rgb  # the filtered levels from the finer of the two
    tiles = [base]
    for (w, h), (ws, hs), r in zip(SPECULAR_LEVELS[1:], _SOURCE, ROUGHNESS[1:]):
        tiles.append(_columns(_convolve(resample(src, ws, hs), ggx_weight(r), h), w))
    irr = _columns(_convolve(resample(src, *_IRRADIANCE_SOURCE), cosine_weight, IRRADIANCE[1]), IRRADIANCE[0])
    # Layout: level 0 across the top band; the others, then the irradiance, side by side below.
    width = max(top, sum(w for w, _h in SPECULAR_LEVELS[1:]) + IRRADIANCE[0])
    row_h = max(h for _w, h in SPECULAR_LEVELS[1:] + (IRRADIANCE,))
    y0 = top // 2
    atlas = np.zeros((y0 + row_h, width, 4), np.float32)  # the corner right of a small level 0: unused
    atlas[..., 3] = 1.0
    rects = [(0, 0, top, top // 2)]
    x = 0
    for tile in tiles[1:] + [irr]:
        h, w = tile.shape[:2]
        rects.append((x, y0, w, h))
        x += w
    assert x <= width, "the filtered tiles fit below level 0"
    for (x, y, w, h), tile in zip(rects, tiles + [irr]):
        atlas[y:y + h, x:x + w, :3] = tile
    sa = solid_angles(top, top // 2)
    mean = (base * sa[:, None, None]).sum(axis=(0, 1)) / (sa.sum() * base.shape[1])
    return EnvironmentAtlas(atlas, tuple(rects[:-1]), rects[-1], tuple(float(c) for c in mean))
