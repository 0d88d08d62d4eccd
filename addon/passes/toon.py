"""Textures of toon shading: a material's shade ramp (256 x 1) and X-Toon map, built on demand
and cached by their contents, so an unchanged material uploads nothing."""
from dataclasses import replace

import numpy as np

from .. import compat
from ..extract import textures

RAMP_SIZE = 256
# Texels an X-Toon map keeps per axis: the lookup reads lighting (x) and depth or orientation
# (y), each a value in [0, 1] filtered linearly, so 512 levels per axis resolve more than an
# 8-bit image's steps; a larger image is box-averaged down to this, which also keeps any map
# within every GPU's texture limit (OpenGL 3.3 promises 1024) and a 8192 x 8192 image from
# costing a GiB of texture (docs/lines.md, "Toon shading").
MAP_MAX = 512
_ramps = {}
_maps = {}


def ramp_texels(stops, smooth, size=RAMP_SIZE):
    """(size, 4) colours at x = i / (size - 1). Stepped: the last stop at or below x (the first
    stop below it); smooth: linear between stops, constant outside them."""
    pos = np.array([p for p, _ in stops], np.float64)
    col = np.array([c for _, c in stops], np.float64)
    x = np.arange(size) / (size - 1)
    if smooth:
        rgb = np.stack([np.interp(x, pos, col[:, k]) for k in range(3)], axis=1)
    else:
        # A stop at x holds from x on; a tiny tolerance keeps x = position on the stop's side.
        rgb = col[np.clip(np.searchsorted(pos, x + 1e-9, side="right") - 1, 0, len(pos) - 1)]
    return np.c_[rgb, np.ones(size)].astype(np.float32)


def _upload(rgba):
    import gpu
    h, w = rgba.shape[:2] if rgba.ndim == 3 else (1, rgba.shape[0])
    flat = np.ascontiguousarray(rgba, np.float32).ravel()
    return compat.texture((w, h), 'RGBA32F', gpu.types.Buffer('FLOAT', flat.size, flat))


def ramp_texture(toon):
    key = (toon.ramp, toon.smooth)
    tex = _ramps.get(key)
    if tex is None:
        tex = _ramps[key] = _upload(ramp_texels(toon.ramp, toon.smooth))
    return tex


def builtin_map(base, width=64, height=32):
    """X-Toon's default map: two soft bands of the material's colour along x, fading towards a
    light grey along y (detail falls off with distance, as in X-Toon's aerial perspective)."""
    x = (np.arange(width) + 0.5) / width
    y = (np.arange(height) + 0.5) / height
    lit = 0.35 + 0.65 / (1.0 + np.exp(-(x - 0.5) * 40.0))
    col = lit[None, :, None] * np.asarray(base, np.float64)[None, None, :]
    grey = np.full(3, 0.6)
    fade = (0.85 * y)[:, None, None]
    rgb = (1.0 - fade) * col + fade * grey
    return np.concatenate([rgb, np.ones((height, width, 1))], axis=2).astype(np.float32)


def box_reduce(px, axis, size):
    """px averaged along `axis` into `size` equal spans (each output texel the mean of the input
    texels whose centres fall in its span); unchanged if it has no more than `size`."""
    n = px.shape[axis]
    if n <= size:
        return px
    starts = (np.arange(size) * n) // size
    counts = np.diff(np.r_[starts, n]).astype(np.float32)
    shape = [1] * px.ndim
    shape[axis] = size
    return np.add.reduceat(px, starts, axis=axis) / counts.reshape(shape)


def image_texels(image):
    """(h, w, 4) scene-linear texels of a Blender image (rows bottom-up, as Blender stores them),
    reduced to at most MAP_MAX per axis."""
    w, h = image.size
    if w < 2 or h < 2:
        raise ValueError(f"X-Toon image '{image.name}' is {w} x {h}; it needs at least 2 x 2 pixels")
    c = image.channels
    px = np.empty(w * h * c, np.float32)
    image.pixels.foreach_get(px)
    px = px.reshape(h, w, c)
    srgb = textures.is_srgb_bytes(image)
    if srgb and (w > MAP_MAX or h > MAP_MAX):
        textures.linearise_bytes(px)  # averaged in linear light
        srgb = False
    px = box_reduce(box_reduce(px, 1, MAP_MAX), 0, MAP_MAX)
    if c < 4:
        px = np.concatenate([px, np.ones(px.shape[:2] + (4 - c,), np.float32)], axis=2)
    if srgb:
        px[..., :3] = textures.srgb_to_linear(px[..., :3])
    return np.ascontiguousarray(px, np.float32)


def map_texture(toon, base):
    """The X-Toon map of a material: its image, or the built-in map of its colour."""
    if toon.image is None:
        key = ("builtin", tuple(round(c, 6) for c in base))
        make = lambda: builtin_map(base)  # noqa: E731
    else:
        key = ("image", toon.image.name_full, tuple(toon.image.size))
        make = lambda: image_texels(toon.image)  # noqa: E731
    tex = _maps.get(key)
    if tex is None:
        try:
            texels = make()
        except ValueError:  # the image changed since the material was read (and reported)
            return map_texture(replace(toon, image=None), base)
        tex = _maps[key] = _upload(texels)
    return tex


def forget_images():
    """Images may have been edited: re-read them on next use."""
    for key in [k for k in _maps if k[0] == "image"]:
        del _maps[key]
