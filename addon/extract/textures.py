"""Images a material draws (materials.BaseTexture): the GPU texture the surface pass samples
(Blender's own, gpu.texture.from_image: its colour space decoded as EEVEE's), and their mean
colour, for what draws the material without the image (edge bands, corner patches, a toon ramp's
default stops), read from the image's pixels once per image and change. Nothing is written to
the image."""
import numpy as np

# (image pointer, size, its file, whether it has unsaved edits) -> linear mean colour
_means = {}


def srgb_to_linear(c):
    c = np.asarray(c, np.float64)
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def is_srgb_bytes(image):
    """Whether Blender's pixels of the image are sRGB-encoded (a byte image in sRGB): Blender
    gives a float image's pixels linear, and a byte image's in its own colour space."""
    return not image.is_float and image.colorspace_settings.name == 'sRGB'


def linearise_bytes(px):
    """Decodes (h, w, c) float32 pixels of an sRGB byte image to linear in place, colour
    channels only, through the 256 values a byte holds and a band of rows at a time: a large
    image costs its own floats and little more."""
    lut = srgb_to_linear(np.arange(256) / 255.0).astype(np.float32)
    colour = min(px.shape[2], 3)
    for y0 in range(0, px.shape[0], 256):
        band = px[y0:y0 + 256, :, :colour]
        band[...] = lut[np.rint(band * 255.0).astype(np.uint8)]
    return px


def linear_pixels(image):
    """(h, w, channels) float32 of the image's pixels, scene-linear (is_srgb_bytes: decoded here;
    Non-Color and linear spaces as they are): this read's own copy, nothing written to the image."""
    w, h = image.size
    c = image.channels
    px = np.empty(w * h * c, np.float32)
    image.pixels.foreach_get(px)
    px = px.reshape(h, w, c)
    if is_srgb_bytes(image):
        linearise_bytes(px)
    return px


def mean_color(image):
    """The image's mean colour, scene-linear (is_srgb_bytes: decoded here; Non-Color and linear
    spaces as they are)."""
    key = (image.as_pointer(), tuple(image.size), image.filepath, image.is_dirty, image.colorspace_settings.name)
    if key not in _means:
        px = linear_pixels(image)
        c = px.shape[2]
        rgb = px.reshape(-1, c)[:, :3 if c >= 3 else 1]  # a grey image: its one value in all three
        mean = np.broadcast_to(rgb.mean(axis=0, dtype=np.float64), (3,)) if len(rgb) else np.full(3, 0.8)
        if len(_means) > 64:
            _means.clear()
        _means[key] = tuple(float(v) for v in mean)
    return _means[key]


def gpu_texture(image):
    """Blender's GPU texture of the image (it caches and frees it with the image)."""
    import gpu
    return gpu.texture.from_image(image)


_placeholder = {}


def no_image():
    """A 1 x 1 texture bound where a node program reads no image (its sampler must be bound)."""
    if "texture" not in _placeholder:
        import gpu

        from .. import compat
        _placeholder["texture"] = compat.texture((1, 1), 'RGBA32F', gpu.types.Buffer('FLOAT', 4, [0.0] * 4))
    return _placeholder["texture"]
