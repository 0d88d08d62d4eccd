"""Rounded edges of n-gons as imports make them: a side cut by extra collinear vertices (whose
loop triangles have zero area) and a near-planar polygon whose triangles are slivers. Each edge
classifies by its polygons' own normals, so every segment keeps its band and none lands astray."""
import unittest

import bmesh
import bpy
import numpy as np

import helpers
import scene_zoo as zoo


def box_with_cut_edge(lift=0.0, cuts=3):
    """A 2 m box whose top-back edge (y = 1, z = 1) carries `cuts` extra collinear vertices;
    `lift` raises the middle one out of the top's plane (making slivers)."""
    bm = bmesh.new()
    bmesh.ops.create_cube(bm, size=2.0)
    edge = next(e for e in bm.edges if all(abs(v.co.y - 1) < 1e-6 and abs(v.co.z - 1) < 1e-6 for v in e.verts))
    if cuts:
        bmesh.ops.subdivide_edges(bm, edges=[edge], cuts=cuts)
    if lift:
        middle = next(v for v in bm.verts if abs(v.co.x) < 1e-6 and abs(v.co.y - 1) < 1e-6)
        middle.co.z += lift
    return zoo.rounded_part("Box", bm, (0.5, 0.5, 0.55), 0.04)


class CutEdges(unittest.TestCase):
    def setUp(self):
        helpers.needs_gpu()
        helpers.empty_scene(480, 360)
        helpers.add_camera((3.5, 4.5, 4.5))  # the cut edge faces the camera, both its faces seen
        helpers.add_sun((0.2, 0.8, 0.6), 4.0)

    def band_along(self, rec, a, b, ts):
        """Largest highlight weight across the edge a-b at each t (within 4 px of it)."""
        prof = helpers.edge_profile(rec, np.asarray(rec["highlight"])[..., 3:], a, b, ts, np.arange(-4, 4.5, 0.5))
        return prof[..., 0].max(axis=1)

    def test_every_segment_of_a_cut_edge_keeps_its_band(self):
        ts = np.linspace(0.05, 0.95, 19)  # along all 4 segments, away from the joins
        box = box_with_cut_edge(cuts=0)
        whole = self.band_along(helpers.render(), (-1, 1, 1), (1, 1, 1), ts)
        bpy.data.objects.remove(box)
        box_with_cut_edge()
        rec = helpers.render()
        cut = self.band_along(rec, (-1, 1, 1), (1, 1, 1), ts)
        self.assertTrue((whole > 0.05).all(), whole)
        self.assertLess(np.abs(cut - whole).max(), 0.1, f"cut edge bands {cut.round(3)}, uncut {whole.round(3)}")

    def test_slivers_put_no_band_astray(self):
        box_with_cut_edge(lift=2e-4)
        rec = helpers.render()
        hl = helpers.highlight_change(rec)
        cov = np.asarray(rec["surface"])[..., 3] > 0.5
        # Pixels more than 3 px away from the box's coverage: a band there is astray.
        near = cov.copy()
        for _ in range(3):
            near = near | np.roll(near, 1, 0) | np.roll(near, -1, 0) | np.roll(near, 1, 1) | np.roll(near, -1, 1)
        astray = int((hl[~near] > 1.0 / 255.0).sum())
        self.assertEqual(astray, 0, f"{astray} highlight pixels away from the box")
        ts = np.array([0.125, 0.375, 0.625, 0.875])
        self.assertTrue((self.band_along(rec, (-1, 1, 1), (1, 1, 1), ts) > 0.05).all())
