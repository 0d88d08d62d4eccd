"""The F(phi, m) table from the native library, uploaded once as an R32F texture."""
import gpu
import numpy as np

from .. import compat, native

_state = {}


def table(lib=None):
    """(texture, params): params = (layout, m_max, warp_c, 0); the edge pass puts its method in w."""
    if "texture" not in _state:
        t = native.HighlightTable(lib=lib)  # the library's recommended default (docs/highlight_math.md)
        info = t.info()
        data = np.ascontiguousarray(t.data(), dtype=np.float32)
        buf = gpu.types.Buffer('FLOAT', data.size, data.ravel())
        _state["texture"] = compat.texture((info["phi_count"], info["m_count"]), 'R32F', buf)
        _state["params"] = (float(info["layout"]), float(info["m_max"]), float(info["warp_c"]), 0.0)
    return _state["texture"], _state["params"]


def clear():
    _state.clear()
