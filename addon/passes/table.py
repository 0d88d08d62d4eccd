"""The F(phi, m) table from the native library, uploaded once as an R32F texture."""
import gpu
import numpy as np

from .. import compat
from ..bridge import native

_state = {}


def table(lib=None):
    """(texture, info): info is the table's el_table_info by field name, from which the edge pass
    takes its defines and push constants (shaders/passes.json)."""
    if "texture" not in _state:
        t = native.HighlightTable(lib=lib)  # the library's recommended default (docs/highlight_math.md)
        info = t.info()
        data = np.ascontiguousarray(t.data(), dtype=np.float32)
        buf = gpu.types.Buffer('FLOAT', data.size, data.ravel())
        _state["texture"] = compat.texture((info["phi_count"], info["m_count"]), 'R32F', buf)
        _state["info"] = info
    return _state["texture"], _state["info"]


def clear():
    _state.clear()
