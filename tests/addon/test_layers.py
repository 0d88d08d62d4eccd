"""The add-on's layers, as docs/architecture.md states them. Every module but the package's
__init__ and compat.py lives in a layer's folder; a layer imports only from the layers below it
(bridge, geometry, linework, extract, passes, host; compat.py between linework and extract), in
functions too; the bpy-free layers (bridge, geometry, linework) import no Blender module, directly
or through what they import; a module elsewhere whose docstring says it imports no bpy ("No
bpy") keeps to that at its top level; and the add-on's own imports form no circle at module
level. Read from the sources (ast), nothing is imported."""
import ast
import os
import sys
import unittest

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "addon")
# Bottom to top: a module imports from its own layer and those before it.
LAYERS = ("bridge", "geometry", "linework", "compat", "extract", "passes", "host")
BPY_FREE = ("bridge", "geometry", "linework")
BLENDER = {"bpy", "gpu", "mathutils", "bmesh", "blf", "bpy_extras", "gpu_extras", "addon_utils", "bl_ui", "idprop"}


def modules():
    """{dotted name within the add-on: path}"""
    out = {}
    for dirpath, _dirs, files in os.walk(ROOT):
        for f in files:
            if f.endswith(".py"):
                rel = os.path.relpath(os.path.join(dirpath, f), ROOT)[:-3].replace(os.sep, ".")
                out[rel[:-len(".__init__")] if rel.endswith(".__init__") else rel] = os.path.join(dirpath, f)
    return out


def top_level_imports(name, path, known, nested=False):
    """(Blender modules, add-on modules, docstring) imported at the top level of module `name`
    (outside any function: a function's import runs only when it is called); `nested`: in its
    functions too."""
    with open(path, encoding="utf-8") as f:
        tree = ast.parse(f.read())
    package = name.rsplit(".", 1)[0] if "." in name and not path.endswith("__init__.py") else \
        (name if path.endswith("__init__.py") else "")
    blender, own = set(), set()

    def visit(nodes):
        for node in nodes:
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)) and not nested:
                continue
            if isinstance(node, ast.Import):
                for a in node.names:
                    if a.name.split(".")[0] in BLENDER:
                        blender.add(a.name.split(".")[0])
            elif isinstance(node, ast.ImportFrom):
                if node.level == 0:
                    if (node.module or "").split(".")[0] in BLENDER:
                        blender.add(node.module.split(".")[0])
                    continue
                base = package.split(".") if package else []
                base = base[:len(base) - (node.level - 1)] if node.level > 1 else base
                target = ".".join(base + ([node.module] if node.module else []))
                for a in node.names:
                    cand = f"{target}.{a.name}" if target else a.name
                    if cand in known:
                        own.add(cand)
                    elif target in known or target == "":
                        if target:
                            own.add(target)
            elif isinstance(node, (ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)):
                visit(node.body)
            else:
                visit(ast.iter_child_nodes(node))
    visit(tree.body)
    own.discard(name)
    return blender, own, ast.get_docstring(tree) or ""


def layer_of(name):
    """The layer of module `name` ("compat" for compat.py), None for the package's __init__ and
    for a module outside every layer."""
    head = name.split(".")[0]
    return head if head in LAYERS else None


class Layers(unittest.TestCase):
    def setUp(self):
        self.known = modules()
        self.graph = {n: top_level_imports(n, p, self.known) for n, p in self.known.items()}
        self.every = {n: top_level_imports(n, p, self.known, nested=True) for n, p in self.known.items()}

    def test_every_module_lives_in_a_layer(self):
        outside = sorted(n for n in self.known if n != "__init__" and layer_of(n) is None)
        self.assertEqual(outside, [], "modules outside the layers' folders")
        for layer in LAYERS:
            self.assertIn(layer, self.known, f"the {layer} layer")

    def test_layers_import_only_from_below(self):
        rank = {layer: i for i, layer in enumerate(LAYERS)}
        upward = []
        for name, (_b, own, _doc) in self.every.items():
            if name == "__init__":
                continue  # the package's __init__ registers every layer
            for dep in sorted(own):
                if dep == "__init__" or rank[layer_of(dep)] > rank[layer_of(name)]:
                    upward.append(f"{name} -> {dep}")
        self.assertEqual(upward, [], "imports from a higher layer")

    def test_bpy_free_layers_reach_no_blender_module(self):
        free = [n for n in self.known if layer_of(n) in BPY_FREE]
        self.assertGreaterEqual(len(free), 15, free)
        bad = {}
        for name in free:
            seen, todo = set(), [name]
            while todo:  # through imports in functions too: a lazy `import bpy` needs Blender all the same
                n = todo.pop()
                if n not in seen:
                    seen.add(n)
                    todo.extend(self.every[n][1])
            for dep in sorted(seen):
                if self.every[dep][0]:
                    bad.setdefault(name, []).append(f"{dep} imports {sorted(self.every[dep][0])}")
        self.assertEqual(bad, {}, "bpy-free layers that reach Blender")

    def closure(self, name):
        seen, todo = set(), [name]
        while todo:
            n = todo.pop()
            if n in seen:
                continue
            seen.add(n)
            todo.extend(self.graph[n][1])
        return seen

    def test_bpy_free_modules_import_no_blender_module(self):
        free = [n for n, (_b, _o, doc) in self.graph.items() if "No bpy" in doc]
        self.assertGreaterEqual(len(free), 10, free)
        bad = {}
        for name in free:
            for dep in sorted(self.closure(name)):
                if self.graph[dep][0]:
                    bad.setdefault(name, []).append(f"{dep} imports {sorted(self.graph[dep][0])}")
        self.assertEqual(bad, {}, "modules that claim no bpy but reach it")

    def test_no_import_circles(self):
        # The package's __init__ registers everything: it is the root, not part of a circle.
        circles = []
        for name in self.graph:
            if name == "__init__" or name == "":
                continue
            for dep in self.graph[name][1]:
                if dep not in ("__init__", "") and name in self.closure(dep):
                    circles.append(f"{name} -> {dep}")
        self.assertEqual(circles, [], "import circles at module level")


if __name__ == "__main__":
    sys.exit(unittest.main())
