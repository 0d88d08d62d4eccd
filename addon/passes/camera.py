"""The camera a frame is drawn from, and the sub-pixel jitter of its samples (Halton 2, 3)."""
from dataclasses import dataclass

import numpy as np


@dataclass
class Camera:
    view: np.ndarray          # world -> view, 4x4 row-major
    projection: np.ndarray    # view -> clip, 4x4 row-major
    eye: tuple
    view_dir: tuple           # direction the camera looks along
    orthographic: bool
    width: int
    height: int
    # A region's camera: the whole frame's projection and where the region starts in it (pixels
    # from the bottom left), so that what is fitted to the frame (a sun's shadow cascades, the
    # soft shadow's noise) is the same in every region. None, (0, 0): the camera is the frame's.
    frame_projection: np.ndarray = None
    pixel_origin: tuple = (0, 0)

    @property
    def whole(self):
        """The whole frame's camera (itself when it is not a region's)."""
        if self.frame_projection is None:
            return self
        return Camera(self.view, self.frame_projection, self.eye, self.view_dir, self.orthographic, self.width, self.height)

    @property
    def px_per_unit(self):
        """Pixels per world unit at distance 1 (perspective) or anywhere (orthographic)."""
        return float(self.projection[0, 0]) * self.width / 2.0


def from_view(view, projection, orthographic, width, height, frame_projection=None, pixel_origin=(0, 0)):
    """The one camera builder (the final render's, the viewport's, the SVG export's): the camera
    of world -> view matrix `view` and view -> clip `projection` (4 x 4 each), its eye and the
    unit direction it looks along read from the view's inverse. A region's camera also takes the
    whole frame's projection and the region's first pixel (Camera.frame_projection)."""
    view = np.asarray(view, np.float64)
    world = np.linalg.inv(view)
    forward = -world[:3, 2] / np.linalg.norm(world[:3, 2])
    return Camera(view=view, projection=np.asarray(projection, np.float64), eye=tuple(world[:3, 3]),
                  view_dir=tuple(forward), orthographic=bool(orthographic), width=int(width), height=int(height),
                  frame_projection=None if frame_projection is None else np.asarray(frame_projection, np.float64),
                  pixel_origin=(int(pixel_origin[0]), int(pixel_origin[1])))


def halton(i, base):
    f, r = 1.0, 0.0
    while i > 0:
        f /= base
        r += f * (i % base)
        i //= base
    return r


def jitter(sample):
    """Sub-pixel offset of a sample; sample 0 is the pixel centre, so one sample is exact."""
    if sample == 0:
        return 0.0, 0.0
    return halton(sample, 2) - 0.5, halton(sample, 3) - 0.5


def jittered_projection(projection, width, height, dx, dy):
    t = np.eye(4, dtype=np.float64)
    t[0, 3] = 2.0 * dx / width
    t[1, 3] = 2.0 * dy / height
    return t @ projection
