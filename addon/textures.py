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


def mean_color(image):
    """The image's mean colour, scene-linear: Blender's pixels are linear for a float image, and in
    the image's colour space for a byte one (sRGB decoded here; Non-Color and linear spaces as
    they are)."""
    key = (image.as_pointer(), tuple(image.size), image.filepath, image.is_dirty, image.colorspace_settings.name)
    if key not in _means:
        w, h = image.size
        px = np.empty(w * h * image.channels, np.float32)
        image.pixels.foreach_get(px)
        rgb = px.reshape(-1, image.channels)[:, :3] if image.channels >= 3 else np.repeat(px.reshape(-1, 1), 3, axis=1)
        mean = rgb.astype(np.float64).mean(axis=0) if len(rgb) else np.full(3, 0.8)
        if not image.is_float and image.colorspace_settings.name == 'sRGB':
            mean = srgb_to_linear(rgb).mean(axis=0) if len(rgb) else mean
        if len(_means) > 64:
            _means.clear()
        _means[key] = tuple(float(v) for v in mean)
    return _means[key]


def gpu_texture(image):
    """Blender's GPU texture of the image (it caches and frees it with the image)."""
    import gpu
    return gpu.texture.from_image(image)
