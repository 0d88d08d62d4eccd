"""Add-on modules that import no bpy, loaded in plain Python for the tests in this folder."""
import importlib
import importlib.machinery
import importlib.util
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def addon_module(name):
    """addon/NAME ("bridge.native", "passes.camera") imported as part of its package, without
    running the package's __init__ (which registers with Blender)."""
    if "edgelight" not in sys.modules:
        pkg = importlib.util.module_from_spec(importlib.machinery.ModuleSpec("edgelight", None, is_package=True))
        pkg.__path__ = [os.path.join(ROOT, "addon")]
        sys.modules["edgelight"] = pkg
    return importlib.import_module("edgelight." + name)
