"""The line pass on any conforming GPU (docs/lines.md, "Depth on every GPU").

Each pixel keeps its most opaque stroke through the depth test on the depth the fragment shader
writes (1 - alpha). Blender 4.x declares gl_FragDepth depth_unchanged for a program that
declares nothing, and a driver that honours that declaration tests and stores the rasterised
depth instead: on NVIDIA every stroke's join lost its ink. llvmpipe ignores the declaration, so
these tests check the declaration itself, and check the toon sample's strokes with a measure
that is shown to find the NVIDIA break when the line program is made to keep the rasterised
depth, as such a driver does."""
import os
import shutil
import tempfile
import unittest

import bpy
import numpy as np

import helpers

# The line pass draws a chord for up to 8 segments when none strays farther than this from it
# (passes/line_pass.py TOLERANCE_PX): the drawn stroke's centre may lie this far from a segment.
CHORD_PX = 0.25
WRITE = "gl_FragDepth = 1.0 - alpha;"


def line_variant(replace):
    """A folder with line.frag.glsl changed by `replace` (text -> text), for shader_lib's
    use_variant; the caller removes it."""
    specs = helpers.addon().bridge.shader_specs
    with open(os.path.join(specs.shader_dir(), "line.frag.glsl"), encoding="utf-8") as f:
        text = f.read()
    changed = replace(text)
    assert changed != text, "line.frag.glsl no longer has what the variant changes"
    folder = tempfile.mkdtemp(prefix="edgelight_line_variant_")
    with open(os.path.join(folder, "line.frag.glsl"), "w", encoding="utf-8") as f:
        f.write(changed)
    return folder


class variant:
    """Renders inside it draw the line program from `folder` (programs.json's description)."""

    def __init__(self, folder):
        self.folder = folder

    def __enter__(self):
        a = helpers.addon()
        a.passes.shader_lib.use_variant("line", a.bridge.shader_specs.program("line"), self.folder)

    def __exit__(self, *exc):
        helpers.addon().passes.shader_lib.use_variant("line")
        shutil.rmtree(self.folder, ignore_errors=True)


def render_toon():
    scene = helpers.open_sample("toon", samples=8)
    scene.edgelight.use_lines = True
    out = tempfile.mkdtemp(prefix="edgelight_strokes_")
    scene.render.filepath = os.path.join(out, "frame_")
    scene.edgelight_svg.enabled = True  # the record's vector data: depths and ids for visibility
    try:
        return helpers.render()
    finally:
        shutil.rmtree(out, ignore_errors=True)


def under_inked(rec):
    """(visible centre-line samples, those whose pixel has less ink than the stroke covers it).

    Every half pixel along every drawn segment, the pixel under the point: where the line pass's
    visibility rule (line_visibility.py, at the pixel's closest point of the segment) shows the
    stroke, its alpha must reach the stroke's own box-filtered coverage of that pixel, taken
    CHORD_PX farther out (a chord's offset): strokes overlapping there only add ink."""
    alpha = rec["lines"][..., 3]
    shown = bad = 0
    for _, style, pix, p, q, visible in helpers.line_samples(rec, per_px=2):
        assert style.taper <= 0.0 and not style.scene_units, "the measure takes a fixed width in pixels"
        d = np.linalg.norm(p - q, axis=1) + CHORD_PX
        r = 0.5 * style.width
        cover = np.clip(np.minimum(d + r, 0.5) - np.maximum(d - r, -0.5), 0.0, 1.0) * style.opacity
        ink = alpha[pix[:, 1], pix[:, 0]]
        shown += int(visible.sum())
        bad += int((visible & (ink < cover - 0.01)).sum())
    return shown, bad


class ToonStrokes(unittest.TestCase):
    def test_every_centre_pixel_of_the_toon_samples_strokes_is_inked(self):
        shown, bad = under_inked(render_toon())
        print(f"toon strokes: {bad} of {shown} visible centre-line samples under-inked")
        self.assertGreater(shown, 3000)
        self.assertEqual(bad, 0)

    def test_the_measure_finds_joins_broken_as_on_nvidia(self):
        """The line program made to keep the rasterised depth, as a driver that honours
        depth_unchanged does: the joins lose their ink (NVIDIA H200: 444 of the line pass's
        pixels differ by more than 0.1; this variant reproduces its line buffer to 1 pixel)."""
        folder = line_variant(lambda text: text.replace(WRITE, "gl_FragDepth = gl_FragCoord.z;"))
        with variant(folder):
            shown, bad = under_inked(render_toon())
        print(f"toon strokes, rasterised depth kept: {bad} of {shown} visible centre-line samples under-inked")
        self.assertGreater(bad, 100)


class DeclaredDepthWrite(unittest.TestCase):
    def test_line_program_declares_any_depth(self):
        """A line program that itself declares `layout(depth_any)` compiles only where Blender
        declared gl_FragDepth the same way or not at all: 4.x's default depth_unchanged fails it."""
        folder = line_variant(lambda text: text.replace("void main()", "layout(depth_any) out float gl_FragDepth;\nvoid main()", 1))
        scene = helpers.empty_scene(64, 64)
        helpers.only_lines(scene, crease=2.0)
        bpy.ops.mesh.primitive_cube_add(size=2.0)
        helpers.add_camera((4.0, -5.5, 3.5))
        helpers.add_sun()
        with variant(folder):
            rec = helpers.render()
        self.assertGreater(rec["lines"][..., 3].max(), 0.99)


if __name__ == "__main__":
    unittest.main()
