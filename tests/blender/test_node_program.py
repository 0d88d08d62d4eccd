"""Node chains into the Principled BSDF (node_program.py, material_program.glsl): Mix (each
blend, 3.4's Mix RGB too), Math (each operation), ColorRamp, Invert, Separate and Combine, Clamp
and Blender's conversions, from an image or a colour attribute per pixel and folded without
either. Each chain is drawn
on a strip of a quad seen from above under a white world with no light and Specular 0, so the
pixel is the albedo, base colour x (1 - metallic). Held two ways at each texel's centre: to the
add-on's own ops (node_program.run: the GLSL to the Python) within 1e-3 (the targets hold half floats), and to Cycles rendering
the same chain into an Emission shader (Blender's node semantics) within 0.01."""
import unittest

import bpy
import numpy as np

import helpers
from test_textures import band_cube
from test_world_light import cycles_pixels

# Opaque: Blender holds a float image's pixels premultiplied, which Cycles and EEVEE read by the
# image's alpha mode, and EdgeLight does not yet (docs/addon.md, "Node chains").
TEXELS = np.array([[0.1, 0.5, 0.9, 1.0], [0.8, 0.2, 0.05, 1.0], [1.5, 0.0, 0.4, 1.0], [0.45, 0.7, 0.25, 1.0]],
                  np.float32)
STRIP_PX, WIDTH = 12, 128


def warnings(rec):
    """The render's warning lines."""
    return [m for level, m in rec.get("messages", []) if level == 'WARNING']
B_COLOR = (0.3, 0.6, 0.9, 1.0)


def _mix(tree, tex, blend, legacy=False):
    n = tree.nodes
    if legacy:
        m = n.new('ShaderNodeMixRGB')
        m.blend_type = blend
        m.inputs["Fac"].default_value = 0.6
        tree.links.new(tex.outputs["Color"], m.inputs["Color1"])
        m.inputs["Color2"].default_value = B_COLOR
        return m.outputs["Color"]
    m = n.new('ShaderNodeMix')
    m.data_type, m.blend_type, m.clamp_factor = 'RGBA', blend, True
    sock = {s.identifier: s for s in m.inputs}
    sock["Factor_Float"].default_value = 0.6
    tree.links.new(tex.outputs["Color"], sock["A_Color"])
    sock["B_Color"].default_value = B_COLOR
    return next(s for s in m.outputs if s.identifier == "Result_Color")


def _math(tree, tex, op, clamp=False):
    m = tree.nodes.new('ShaderNodeMath')
    m.operation, m.use_clamp = op, clamp
    sep = tree.nodes.new('ShaderNodeSeparateColor' if bpy.app.version >= (3, 3, 0) else 'ShaderNodeSeparateRGB')
    tree.links.new(tex.outputs["Color"], sep.inputs[0])
    tree.links.new(tex.outputs["Color"], m.inputs[0])   # a colour into a float: its luminance
    tree.links.new(sep.outputs[1], m.inputs[1])         # the green
    m.inputs[2].default_value = 0.25
    return m.outputs[0]


def _ramp(tree, tex, interpolation):
    r = tree.nodes.new('ShaderNodeValToRGB')
    r.color_ramp.interpolation = interpolation
    e = r.color_ramp.elements
    e[0].position, e[0].color = 0.2, (0.9, 0.1, 0.2, 1.0)
    e[1].position, e[1].color = 0.8, (0.1, 0.3, 1.0, 1.0)
    mid = e.new(0.5)
    mid.color = (0.2, 0.9, 0.3, 1.0)
    tree.links.new(tex.outputs["Color"], r.inputs["Fac"])
    return r.outputs["Color"]


def _misc(tree, tex):
    """Combine XYZ of: Separate Color's blue; an Invert's luminance; a Clamp (range) of the
    luminance."""
    n, link = tree.nodes, tree.links.new
    sep = n.new('ShaderNodeSeparateXYZ')
    link(tex.outputs["Color"], sep.inputs[0])
    inv = n.new('ShaderNodeInvert')
    inv.inputs["Fac"].default_value = 0.8
    link(tex.outputs["Color"], inv.inputs["Color"])
    clamp = n.new('ShaderNodeClamp')
    clamp.clamp_type = 'RANGE'
    clamp.inputs["Min"].default_value, clamp.inputs["Max"].default_value = 0.5, 0.2
    link(tex.outputs["Color"], clamp.inputs["Value"])
    comb = n.new('ShaderNodeCombineXYZ')
    link(sep.outputs["Z"], comb.inputs[0])
    link(inv.outputs["Color"], comb.inputs[1])
    link(clamp.outputs[0], comb.inputs[2])
    return comb.outputs[0]


# A second image (4 x 1, float, Closest) on the same UV map.
TEXELS2 = np.array([[0.5, 0.9, 0.2, 1.0], [0.3, 0.3, 0.9, 1.0], [1.0, 0.6, 0.1, 1.0], [0.05, 0.4, 0.7, 1.0]],
                   np.float32)


def _second_image(tree):
    img = bpy.data.images.get("Texels2")
    if img is None:
        img = bpy.data.images.new("Texels2", 4, 1, alpha=True, float_buffer=True)
        img.pixels.foreach_set(TEXELS2.reshape(-1))
    node = tree.nodes.new('ShaderNodeTexImage')
    node.image, node.interpolation = img, 'Closest'
    return node


def _two_images(tree, tex):
    """The first image screened over the second, by the second's green."""
    second = _second_image(tree)
    m = tree.nodes.new('ShaderNodeMixRGB')
    m.blend_type = 'SCREEN'
    sep = tree.nodes.new('ShaderNodeSeparateXYZ')
    tree.links.new(second.outputs["Color"], sep.inputs[0])
    tree.links.new(sep.outputs["Y"], m.inputs["Fac"])
    tree.links.new(second.outputs["Color"], m.inputs["Color1"])
    tree.links.new(tex.outputs["Color"], m.inputs["Color2"])
    return m.outputs["Color"]


def _map_range(tree, tex, clamp=True, interpolation='LINEAR'):
    """The image's luminance mapped from [0.2, 0.7] to [0.9, 0.1] (reversed), clamped or not, by
    `interpolation` (Stepped: 3 steps)."""
    m = tree.nodes.new('ShaderNodeMapRange')
    m.clamp, m.interpolation_type = clamp, interpolation
    if interpolation == 'STEPPED':
        m.inputs["Steps"].default_value = 3.0
    m.inputs["From Min"].default_value, m.inputs["From Max"].default_value = 0.2, 0.7
    m.inputs["To Min"].default_value, m.inputs["To Max"].default_value = 0.9, 0.1
    tree.links.new(tex.outputs["Color"], m.inputs["Value"])
    return m.outputs[0]


def _gamma(tree, tex):
    g = tree.nodes.new('ShaderNodeGamma')
    g.inputs["Gamma"].default_value = 2.2
    tree.links.new(tex.outputs["Color"], g.inputs["Color"])
    return g.outputs["Color"]


def _hue_sat(tree, tex):
    """The image's hue turned by a tenth, its saturation x 1.5, its value x 0.8, mixed in at 0.9."""
    h = tree.nodes.new('ShaderNodeHueSaturation')
    h.inputs["Hue"].default_value, h.inputs["Saturation"].default_value = 0.6, 1.5
    h.inputs["Value"].default_value, h.inputs["Fac"].default_value = 0.8, 0.9
    tree.links.new(tex.outputs["Color"], h.inputs["Color"])
    return h.outputs["Color"]


def _folded(tree, tex):
    """No image: an RGB times a Value's square (Mix Multiply), folded on the CPU."""
    n, link = tree.nodes, tree.links.new
    rgb, val, sq = n.new('ShaderNodeRGB'), n.new('ShaderNodeValue'), n.new('ShaderNodeMath')
    rgb.outputs[0].default_value = (0.7, 0.4, 0.2, 1.0)
    val.outputs[0].default_value = 0.8
    sq.operation = 'POWER'
    sq.inputs[1].default_value = 2.0
    link(val.outputs[0], sq.inputs[0])
    m = n.new('ShaderNodeMixRGB')
    m.blend_type, m.inputs["Fac"].default_value = 'MULTIPLY', 1.0
    link(rgb.outputs[0], m.inputs["Color1"])
    link(sq.outputs[0], m.inputs["Color2"])
    return m.outputs["Color"]


MIX_BLENDS = ('MIX', 'DARKEN', 'MULTIPLY', 'LIGHTEN', 'SCREEN', 'ADD', 'SUBTRACT', 'DIVIDE', 'DIFFERENCE',
              'OVERLAY', 'LINEAR_LIGHT')
MATH_OPS = ('ADD', 'SUBTRACT', 'MULTIPLY', 'DIVIDE', 'MULTIPLY_ADD', 'POWER', 'SQRT', 'ABSOLUTE', 'MINIMUM',
            'MAXIMUM', 'LESS_THAN', 'GREATER_THAN', 'ROUND', 'FLOOR', 'CEIL', 'FRACT', 'SINE', 'COSINE',
            'EXPONENT', 'SIGN', 'TRUNC')
CHAINS = ([(f"mix {b}", lambda t, x, b=b: _mix(t, x, b)) for b in MIX_BLENDS]
          + [("mix rgb OVERLAY", lambda t, x: _mix(t, x, 'OVERLAY', legacy=True)),
             ("mix rgb DIVIDE", lambda t, x: _mix(t, x, 'DIVIDE', legacy=True))]
          + [(f"math {op}", lambda t, x, op=op: _math(t, x, op)) for op in MATH_OPS]
          + [("math POWER clamped", lambda t, x: _math(t, x, 'POWER', clamp=True)),
             ("ramp LINEAR", lambda t, x: _ramp(t, x, 'LINEAR')), ("ramp CONSTANT", lambda t, x: _ramp(t, x, 'CONSTANT')),
             ("ramp EASE", lambda t, x: _ramp(t, x, 'EASE')),
             ("separate, invert, clamp, combine", _misc), ("two images", _two_images),
             ("map range clamped", _map_range), ("map range", lambda t, x: _map_range(t, x, clamp=False)),
             ("map range stepped", lambda t, x: _map_range(t, x, clamp=False, interpolation='STEPPED')),
             ("map range stepped clamped", lambda t, x: _map_range(t, x, interpolation='STEPPED')),
             ("map range smooth step", lambda t, x: _map_range(t, x, interpolation='SMOOTHSTEP')),
             ("map range smoother step", lambda t, x: _map_range(t, x, interpolation='SMOOTHERSTEP')),
             ("gamma", _gamma), ("hue saturation value", _hue_sat), ("folded", _folded)])


# The colour attribute's value on each of a strip's four faces (a corner attribute, one colour
# a face): the texels' places.
COLORS = np.array([[0.9, 0.3, 0.1, 1.0], [0.2, 0.6, 0.4, 0.5], [0.05, 0.1, 0.8, 0.25], [0.7, 0.7, 0.2, 1.0]],
                  np.float32)


def four_face_strip(name):
    """A 2 x 2 quad of four faces side by side (one per texel), its UVs spanning the image, and a
    corner colour attribute 'Col' of one colour a face (COLORS), the render one."""
    xs = np.linspace(-1.0, 1.0, 5)
    verts = [(x, y, 0.0) for y in (-1.0, 1.0) for x in xs]
    faces = [(i, i + 1, 6 + i, 5 + i) for i in range(4)]
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(verts, [], faces)
    uv = mesh.uv_layers.new(name="UVMap")
    loop_vert = [v for f in faces for v in f]
    uv.data.foreach_set("uv", np.array([((verts[v][0] + 1.0) / 2.0, (verts[v][1] + 1.0) / 2.0) for v in loop_vert],
                                       np.float32).reshape(-1))
    col = mesh.color_attributes.new("Col", 'FLOAT_COLOR', 'CORNER')
    col.data.foreach_set("color", np.repeat(COLORS, 4, axis=0).reshape(-1))
    mesh.color_attributes.render_color_index = 0
    return mesh


def strips_scene(chains, metallic_strip=False, colored=False):
    """One strip per chain (top to bottom), each a plane with the chain into its Base Color (for
    EdgeLight) and into an Emission (for Cycles), read from a 4 x 1 float image, Closest. With
    `metallic_strip`, a last strip whose Metallic is the image's red; with `colored`, each strip
    is four faces with a colour attribute (four_face_strip)."""
    count = len(chains) + int(metallic_strip)
    scene = helpers.empty_scene(WIDTH, STRIP_PX * count, highlights=False)
    helpers.set_world_color(scene, (1.0, 1.0, 1.0))
    height = 2.0 * STRIP_PX * count / WIDTH
    cam = helpers.add_camera((0.0, 0.0, 20.0), (0.0, 0.0, 0.0))
    cam.rotation_euler = (0.0, 0.0, 0.0)
    cam.data.type, cam.data.ortho_scale, cam.data.clip_end = 'ORTHO', max(2.0, height), 40.0
    img = bpy.data.images.new("Texels", 4, 1, alpha=True, float_buffer=True)
    img.pixels.foreach_set(TEXELS.reshape(-1))
    pairs = []
    for k in range(count):
        bpy.ops.mesh.primitive_plane_add(size=2.0, location=(0.0, height / 2.0 - (k + 0.5) * height / count, 0.0))
        ob = bpy.context.object
        ob.scale = (1.0, 1.0 / count * height / 2.0, 1.0)
        if colored:
            ob.data = four_face_strip(f"strip {k}")
        build = chains[k][1] if k < len(chains) else (lambda t, x: x.outputs["Color"])
        setup = chains[k][2] if k < len(chains) and len(chains[k]) > 2 else None
        mats = []
        for kind in ("principled", "emission"):
            mat = bpy.data.materials.new(f"{kind} {k}")
            mat.use_nodes = True
            tree = mat.node_tree
            out = next(n for n in tree.nodes if n.type == 'OUTPUT_MATERIAL')
            bsdf = next(n for n in tree.nodes if n.type == 'BSDF_PRINCIPLED')
            tex = tree.nodes.new('ShaderNodeTexImage')
            tex.image, tex.interpolation = img, 'Closest'
            sock = build(tree, tex)
            if kind == "principled":
                for name in ("Specular", "Specular IOR Level"):
                    if name in bsdf.inputs:
                        bsdf.inputs[name].default_value = 0.0
                tree.links.new(sock, bsdf.inputs["Base Color"])
                if setup is not None:
                    setup(tree, tex, bsdf)
                if k == len(chains):
                    sep = tree.nodes.new('ShaderNodeSeparateXYZ')
                    tree.links.new(tex.outputs["Color"], sep.inputs[0])
                    tree.links.new(sep.outputs["X"], bsdf.inputs["Metallic"])
            else:
                tree.nodes.remove(bsdf)
                em = tree.nodes.new('ShaderNodeEmission')
                tree.links.new(sock, em.inputs["Color"])
                tree.links.new(em.outputs[0], out.inputs["Surface"])
            mats.append(mat)
        ob.data.materials.append(mats[0])
        pairs.append((ob, mats))
    return scene, pairs


def centres(px, count):
    """(strip, texel) -> the pixel at the texel's centre (rows top-down in the strips' order)."""
    out = np.zeros((count, 4, 3))
    for k in range(count):
        row = px.shape[0] - 1 - (k * STRIP_PX + STRIP_PX // 2)  # rows bottom-up
        for t in range(4):
            out[k, t] = px[row, (2 * t + 1) * WIDTH // 8, :3]
    return out


class NodeChains(unittest.TestCase):
    def setUp(self):
        helpers.needs_gpu()

    def test_chains_as_the_ops_and_as_cycles_draw_them(self):
        scene, pairs = strips_scene(CHAINS, metallic_strip=True)
        el = helpers.addon()
        rec = helpers.render()
        self.assertEqual(warnings(rec), [])
        ours = centres(rec["pixels"], len(pairs))
        # The GLSL against the add-on's Python ops, at each texel.
        # The lobe's albedo under the white world (helpers.env_specular): Specular 0 still
        # reflects at grazing angles, nearly nothing seen from above.
        n = el.extract.materials.shininess_from_roughness(0.5)
        worst, albedo, negative = 0.0, np.zeros_like(ours), np.zeros(ours.shape[:2], bool)
        for k, (_ob, mats) in enumerate(pairs):
            s = el.extract.materials.shading_of(mats[0])
            for t in range(4):
                if s.texture is None:  # folded: the Shading's own albedo
                    albedo[k, t], f0 = s.base_color, np.array(s.spec_color)
                else:
                    by_name = {"Texels": tuple(TEXELS[t]), "Texels2": tuple(TEXELS2[t])}
                    got = el.extract.node_program.run(s.texture.program, [by_name[i.image.name] for i in s.texture.program.images])
                    m = min(max(got["Metallic"][0], 0.0), 1.0)
                    base = np.array(got["Base Color"][:3])
                    negative[k, t] = base.min() < 0.0
                    base = np.maximum(base, 0.0)  # no negative albedo
                    albedo[k, t], f0 = base * (1.0 - m), base * m
                want = albedo[k, t] + helpers.env_specular(f0, n, 1.0)
                # Relative: the colour target holds half floats (11 bits).
                err = float((np.abs(ours[k, t] - want) / np.maximum(np.abs(want), 1.0)).max())
                worst = max(worst, err)
                self.assertLess(err, 1e-3, f"{pairs[k][1][0].name} texel {t}: drawn {ours[k, t]}, ops {want}")
        print(f"node program against node_program.run: worst relative {worst:.2e} over {len(pairs)} strips x 4 texels")
        # The metallic strip: the image's red as Metallic takes that share of the albedo.
        red = TEXELS[:, 0].clip(0.0, 1.0)
        np.testing.assert_allclose(albedo[-1], TEXELS[:, :3] * (1.0 - red)[:, None], atol=1e-6)
        # The chains against Cycles' Emission of the same chain.
        for _ob, mats in pairs[:len(CHAINS)]:
            _ob.data.materials[0] = mats[1]
        theirs = centres(cycles_pixels(scene, samples=1), len(pairs))
        rows = []
        for k, (name, _build) in enumerate(CHAINS):
            for t in range(4):
                if negative[k, t]:
                    continue  # Cycles' Emission keeps a negative colour; the albedo does not
                err = float(np.abs(albedo[k, t] - theirs[k, t]).max())
                rows.append(err)
                self.assertLess(err, 0.01, f"{name} texel {t}: EdgeLight {ours[k, t]}, Cycles {theirs[k, t]}")
        print(f"node chains against Cycles: worst {max(rows):.4f}, mean {np.mean(rows):.5f} "
              f"over {len(rows)} of {len(CHAINS)} chains x 4 texels (the others negative)")
        self.assertGreater(len(rows), 3 * len(CHAINS))

    def test_an_image_on_another_uv_map_and_an_unknown_node_are_said(self):
        scene, pairs = strips_scene([("image", lambda t, x: x.outputs["Color"])])
        mat = pairs[0][1][0]
        tree = mat.node_tree
        bsdf = next(n for n in tree.nodes if n.type == 'BSDF_PRINCIPLED')
        other = tree.nodes.new('ShaderNodeTexImage')
        other.image = bpy.data.images.new("Other", 2, 2)
        uv = tree.nodes.new('ShaderNodeUVMap')
        uv.uv_map = "Second"
        tree.links.new(uv.outputs["UV"], other.inputs["Vector"])
        tree.links.new(other.outputs["Color"], bsdf.inputs["Roughness"])
        unknown = tree.nodes.new('ShaderNodeRGBCurve')
        tree.links.new(unknown.outputs[0], bsdf.inputs["Metallic"])
        lines = warnings(helpers.render())
        self.assertEqual(len(lines), 1, lines)
        self.assertIn("Roughness from Image Texture 'Image Texture.001': another UV map than its first image's "
                      "('Texels')", lines[0])
        self.assertIn("Metallic from RGB Curves (its value", lines[0])


def _color_attribute(tree, tex):
    node = tree.nodes.new('ShaderNodeVertexColor')  # its name empty: the render colour attribute
    return node.outputs["Color"]


def _attribute_fac_ramp(tree, tex):
    """An Attribute node naming 'Col', its Fac (the colour's mean) through a ColorRamp."""
    attr = tree.nodes.new('ShaderNodeAttribute')
    attr.attribute_name = "Col"
    ramp = tree.nodes.new('ShaderNodeValToRGB')
    ramp.color_ramp.elements[0].color = (0.1, 0.2, 0.9, 1.0)
    ramp.color_ramp.elements[1].color = (1.0, 0.8, 0.1, 1.0)
    tree.links.new(attr.outputs["Fac"], ramp.inputs["Fac"])
    return ramp.outputs["Color"]


def _attribute_times_image(tree, tex):
    """The colour attribute times the image (Mix Multiply), plus its alpha through Math."""
    n, link = tree.nodes, tree.links.new
    col = n.new('ShaderNodeVertexColor')
    col.layer_name = "Col"
    m = n.new('ShaderNodeMixRGB')
    m.blend_type = 'MULTIPLY'
    link(col.outputs["Alpha"], m.inputs["Fac"])
    link(col.outputs["Color"], m.inputs["Color1"])
    link(tex.outputs["Color"], m.inputs["Color2"])
    return m.outputs["Color"]


ATTRIBUTE_CHAINS = [("color attribute", _color_attribute), ("attribute fac ramp", _attribute_fac_ramp),
                    ("attribute x image", _attribute_times_image)]


class ColorAttributes(unittest.TestCase):
    def setUp(self):
        helpers.needs_gpu()

    def test_chains_from_a_colour_attribute(self):
        """Color Attribute (the render one), an Attribute node's Fac, and the attribute times the
        image by its alpha: per face as node_program.run gives it, and as Cycles draws it."""
        scene, pairs = strips_scene(ATTRIBUTE_CHAINS, colored=True)
        el = helpers.addon()
        rec = helpers.render()
        self.assertEqual(warnings(rec), [])
        ours = centres(rec["pixels"], len(pairs))
        n = el.extract.materials.shininess_from_roughness(0.5)
        albedo = np.zeros_like(ours)
        for k, (_ob, mats) in enumerate(pairs):
            program = el.extract.materials.shading_of(mats[0]).texture.program
            for t in range(4):
                albedo[k, t] = np.maximum(el.extract.node_program.run(program, tuple(TEXELS[t]), tuple(COLORS[t]))["Base Color"][:3], 0)
                want = albedo[k, t] + helpers.env_specular(np.zeros(3), n, 1.0)
                np.testing.assert_allclose(ours[k, t], want, rtol=1e-3, atol=1e-4, err_msg=f"{ATTRIBUTE_CHAINS[k][0]} face {t}")
        np.testing.assert_allclose(albedo[0], COLORS[:, :3], atol=1e-6)  # the attribute itself
        for _ob, mats in pairs:
            _ob.data.materials[0] = mats[1]
        theirs = centres(cycles_pixels(scene, samples=1), len(pairs))
        err = np.abs(albedo - theirs).max(axis=-1)
        print(f"colour attribute chains against Cycles: worst {err.max():.4f}")
        for k, (name, _b) in enumerate(ATTRIBUTE_CHAINS):
            for t in range(4):
                self.assertLess(err[k, t], 0.01, f"{name} face {t}: EdgeLight {albedo[k, t]}, Cycles {theirs[k, t]}")

    def test_bands_and_corners_take_the_attribute(self):
        """A cube whose vertices are all red in a point colour attribute, through Color
        Attribute into Base Color: its bands and corner patches are red, as a bevel would be;
        white (the program's constant for no attribute) or zero would not be."""
        def painted(ob, tree):
            col = ob.data.color_attributes.new("Paint", 'BYTE_COLOR', 'POINT')
            col.data.foreach_set("color", np.tile([1.0, 0.0, 0.0, 1.0], len(col.data)).astype(np.float32))
            return _color_attribute(tree, None)
        rec, count, (red, green, _blue) = band_cube("Painted", painted)
        print(f"{count} band pixels: red {red:.2f}, green {green:.2f}")
        self.assertGreater(count, 100)
        self.assertGreater(red, 20.0 * green)
        self.assertEqual(warnings(rec), [])

    def test_a_missing_attribute_reads_black_and_is_said(self):
        _scene, pairs = strips_scene([("color attribute", _color_attribute)])  # planes without one
        rec = helpers.render()
        said = warnings(rec)
        self.assertTrue(any("reads a colour attribute the mesh does not have; it reads black" in m for m in said), said)
        ours = centres(rec["pixels"], 1)
        self.assertLess(float(ours.max()), 0.01)


class PastWhatItCanDraw(unittest.TestCase):
    def setUp(self):
        helpers.needs_gpu()

    def test_chains_past_the_blocks_room_are_said_and_the_render_goes_on(self):
        """Two 8-stop ramps of the image into Base Color (through an Invert and a Mix) and
        Roughness fill the 24 constants; Metallic's own value then has no room: no program,
        each chain said."""
        def two_ramps(tree, tex, bsdf):
            for name in ("Base Color", "Roughness"):
                ramp = tree.nodes.new('ShaderNodeValToRGB')
                for k in range(6):
                    ramp.color_ramp.elements.new(0.1 + 0.13 * k).color = (0.1 * k, 0.5, 0.2, 1.0)
                tree.links.new(tex.outputs["Color"], ramp.inputs["Fac"])
                if name == "Base Color":
                    inv = tree.nodes.new('ShaderNodeInvert')
                    inv.inputs["Fac"].default_value = 0.6
                    tree.links.new(ramp.outputs["Color"], inv.inputs["Color"])
                    mix = tree.nodes.new('ShaderNodeMixRGB')
                    mix.inputs["Color2"].default_value = (0.25, 0.5, 0.75, 1.0)
                    mix.inputs["Fac"].default_value = 0.3
                    tree.links.new(inv.outputs["Color"], mix.inputs["Color1"])
                    tree.links.new(mix.outputs["Color"], bsdf.inputs[name])
                else:
                    tree.links.new(ramp.outputs["Color"], bsdf.inputs[name])
            bsdf.inputs["Metallic"].default_value = 0.35
        _scene, pairs = strips_scene([("full", lambda t, x: x.outputs["Color"], two_ramps)])
        mat = pairs[0][1][0]
        bsdf = next(n for n in mat.node_tree.nodes if n.type == 'BSDF_PRINCIPLED')
        mat.node_tree.links.remove(bsdf.inputs["Base Color"].links[0])  # the strip's own image link
        mix = next(n for n in mat.node_tree.nodes if n.type == 'MIX_RGB')
        mat.node_tree.links.new(mix.outputs["Color"], bsdf.inputs["Base Color"])
        rec = helpers.render()
        said = warnings(rec)
        self.assertEqual(len(said), 1, said)
        self.assertIn("more than 24 constants", said[0])
        self.assertIn("Base Color from", said[0])
        self.assertIn("Roughness from", said[0])
        self.assertGreater(float(np.asarray(rec["pixels"])[..., 3].max()), 0.5)

    def test_a_chain_that_computes_no_number_gives_the_default(self):
        """1e38 to the power 10 into Roughness: an overflow folds to the socket's default (0.5),
        and the render goes on."""
        def overflow(tree, tex, bsdf):
            val, power = tree.nodes.new('ShaderNodeValue'), tree.nodes.new('ShaderNodeMath')
            val.outputs[0].default_value = 1e38
            power.operation = 'POWER'
            power.inputs[1].default_value = 10.0
            tree.links.new(val.outputs[0], power.inputs[0])
            tree.links.new(power.outputs[0], bsdf.inputs["Roughness"])
        _scene, pairs = strips_scene([("overflow", lambda t, x: x.outputs["Color"], overflow)])
        rec = helpers.render()
        self.assertNotIn("ERROR", [level for level, _ in rec.get("messages", [])])
        s = helpers.addon().extract.materials.shading_of(pairs[0][1][0])
        self.assertEqual(s.shininess, helpers.addon().extract.materials.shininess_from_roughness(0.5))


class NormalMaps(unittest.TestCase):
    """A Normal Map (tangent space) of a 4 x 1 Non-Color image on a flat quad seen from above,
    its UVs along x and y (tangent +X, bitangent +Y), lit by a sun and nothing else: each
    texel's brightness is the albedo x E / pi x N.L of its own normal, the normal the image
    encodes (2c - 1), held to the closed form and to Cycles."""
    # Tilted at most 30 degrees: past 45, seen from above, Cycles bends a normal whose mirror
    # direction would graze the surface (its valid-reflection correction), which EEVEE does not.
    NORMALS = np.array([[0.0, 0.0, 1.0], [0.5, 0.0, 0.75 ** 0.5], [-0.4, -0.2, 0.8 ** 0.5], [0.0, 0.5, 0.75 ** 0.5]])
    LIGHT = np.array([0.5, 0.3, 1.0]) / np.linalg.norm([0.5, 0.3, 1.0])

    def setUp(self):
        helpers.needs_gpu()

    def scene(self, strength=1.0, mirrored=False):
        scene = helpers.empty_scene(128, 32, highlights=False)
        helpers.set_world_color(scene, (0.0, 0.0, 0.0))
        bpy.ops.mesh.primitive_plane_add(size=2.0)
        ob = bpy.context.object
        if mirrored:  # mirrored across x: u runs along -x, and the bitangent's sign flips with the transform
            ob.scale = (-1.0, 1.0, 1.0)
        cam = helpers.add_camera((0.0, 0.0, 20.0), (0.0, 0.0, 0.0))
        cam.rotation_euler = (0.0, 0.0, 0.0)
        cam.data.type, cam.data.ortho_scale, cam.data.clip_end = 'ORTHO', 2.0, 40.0
        sun = helpers.add_sun(tuple(self.LIGHT), 3.0)
        sun.data.angle = 0.0
        img = bpy.data.images.new("Normals", 4, 1, float_buffer=True)
        img.colorspace_settings.name = 'Non-Color'
        px = np.concatenate([(self.NORMALS + 1.0) / 2.0, np.ones((4, 1))], axis=1).astype(np.float32)
        img.pixels.foreach_set(px.reshape(-1))
        mat = bpy.data.materials.new("Bumpy")
        mat.use_nodes = True
        tree = mat.node_tree
        bsdf = next(n for n in tree.nodes if n.type == 'BSDF_PRINCIPLED')
        bsdf.inputs["Base Color"].default_value = (0.8, 0.8, 0.8, 1.0)
        for name in ("Specular", "Specular IOR Level"):
            if name in bsdf.inputs:
                bsdf.inputs[name].default_value = 0.0
        tex = tree.nodes.new('ShaderNodeTexImage')
        tex.image, tex.interpolation = img, 'Closest'
        nmap = tree.nodes.new('ShaderNodeNormalMap')
        nmap.inputs["Strength"].default_value = strength
        tree.links.new(tex.outputs["Color"], nmap.inputs["Color"])
        tree.links.new(nmap.outputs["Normal"], bsdf.inputs["Normal"])
        ob.data.materials.append(mat)
        return scene

    def texels(self, px):
        return np.array([px[16, 16 + 32 * t, :3] for t in range(4)])

    def expected(self, strength=1.0, flip_x=False):
        n = self.NORMALS * ([-1.0, 1.0, 1.0] if flip_x else 1.0)
        n = (1.0 - strength) * np.array([0.0, 0.0, 1.0]) + strength * n
        n /= np.linalg.norm(n, axis=1, keepdims=True)
        return 0.8 * 3.0 / np.pi * np.maximum(n @ self.LIGHT, 0.0)

    def test_normals_from_the_image(self):
        scene = self.scene()
        rec = helpers.render()
        self.assertEqual(warnings(rec), [])
        ours = self.texels(np.asarray(rec["pixels"]))
        want = self.expected()
        theirs = self.texels(cycles_pixels(scene, samples=4))
        print(f"normal map: drawn {ours[:, 0]}, closed form {want}, Cycles {theirs[:, 0]}")
        np.testing.assert_allclose(ours, np.repeat(want[:, None], 3, axis=1), rtol=2e-3)
        np.testing.assert_allclose(theirs, np.repeat(want[:, None], 3, axis=1), rtol=1e-2)

    def test_an_ngon_takes_its_triangles_tangents(self):
        """A pentagon (Blender computes no tangents for n-gons): its triangles' own tangents
        from their UVs (scene_sync.triangle_tangents), here +X, under a constant tilted colour."""
        scene = self.scene()
        ob = next(o for o in scene.objects if o.type == 'MESH')
        angles = np.radians(90.0 + 72.0 * np.arange(5))
        verts = [(2.0 * np.cos(a), 2.0 * np.sin(a), 0.0) for a in angles]
        mesh = bpy.data.meshes.new("Pentagon")
        mesh.from_pydata(verts, [], [tuple(range(5))])
        uv = mesh.uv_layers.new(name="UVMap")
        uv.data.foreach_set("uv", np.array([((x + 2.0) / 4.0, (y + 2.0) / 4.0) for x, y, _ in verts], np.float32).reshape(-1))
        mesh.materials.append(ob.data.materials[0])
        ob.data = mesh
        tree = mesh.materials[0].node_tree
        nmap = next(n for n in tree.nodes if n.type == 'NORMAL_MAP')
        tree.links.remove(nmap.inputs["Color"].links[0])
        n = self.NORMALS[1]
        nmap.inputs["Color"].default_value = (*((n + 1.0) / 2.0), 1.0)
        rec = helpers.render()
        self.assertEqual(warnings(rec), [])
        got = np.asarray(rec["pixels"])[16, 64, :3]
        np.testing.assert_allclose(got, self.expected()[1], rtol=2e-3)

    def test_faces_seen_from_behind_as_cycles_draws_them(self):
        """The quad with its normal flipped (seen from behind: the frame turned round, as EEVEE
        turns it), and a closed box turned inside out, whose top the library winds back
        (batches.slot_tangents negates its tangent with its normal): each texel as Cycles
        draws it."""
        scene = self.scene()
        quad = next(o for o in scene.objects if o.type == 'MESH')
        quad.data.flip_normals()
        ours = self.texels(np.asarray(helpers.render()["pixels"]))
        theirs = self.texels(cycles_pixels(scene, samples=4))
        print(f"seen from behind: drawn {ours[:, 0]}, Cycles {theirs[:, 0]}")
        np.testing.assert_allclose(ours, theirs, rtol=1e-2, atol=2e-3)
        mat = quad.data.materials[0]
        bpy.data.objects.remove(quad)
        bpy.ops.mesh.primitive_cube_add(size=2.0, location=(0.0, 0.0, -1.0))  # its top at z = 0, filling the frame
        box = bpy.context.object
        box.data.flip_normals()
        uv = box.data.uv_layers.active
        # Every face's UVs as the quad's: u along its first edge, v along its second.
        uv.data.foreach_set("uv", np.tile([0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0], 6).astype(np.float32))
        box.data.materials.append(mat)
        ours = self.texels(np.asarray(helpers.render()["pixels"]))
        theirs = self.texels(cycles_pixels(scene, samples=4))
        print(f"inside-out box: drawn {ours[:, 0]}, Cycles {theirs[:, 0]}")
        np.testing.assert_allclose(ours, theirs, rtol=1e-2, atol=2e-3)

    def test_strength_and_a_mirrored_object(self):
        """Strength 0.5 mixes the mapped normal halfway back to the mesh's (then normalised); a
        mirrored object (scale x -1) maps its u along -x: the tangent turns with it."""
        self.scene(strength=0.5)
        ours = self.texels(np.asarray(helpers.render()["pixels"]))
        np.testing.assert_allclose(ours, np.repeat(self.expected(0.5)[:, None], 3, axis=1), rtol=2e-3)
        self.scene(mirrored=True)
        ours = self.texels(np.asarray(helpers.render()["pixels"]))[::-1]  # the image runs right to left
        np.testing.assert_allclose(ours, np.repeat(self.expected(flip_x=True)[:, None], 3, axis=1), rtol=2e-3)


def _rough_metal(tree, tex, bsdf):
    """Metallic 1, Roughness the image's green."""
    bsdf.inputs["Metallic"].default_value = 1.0
    sep = tree.nodes.new('ShaderNodeSeparateXYZ')
    tree.links.new(tex.outputs["Color"], sep.inputs[0])
    tree.links.new(sep.outputs["Y"], bsdf.inputs["Roughness"])


class RoughnessPerPixel(unittest.TestCase):
    def setUp(self):
        helpers.needs_gpu()

    def test_a_roughness_map_on_a_metal(self):
        """A metal whose roughness is the image's green, under the white world: each texel's
        colour is the lobe's albedo at its own exponent (helpers.env_specular), not at the
        image's mean roughness."""
        _scene, pairs = strips_scene([("rough metal", lambda t, x: x.outputs["Color"], _rough_metal)])
        el = helpers.addon()
        ours = centres(helpers.render()["pixels"], 1)[0]
        for t in range(4):
            base = np.clip(TEXELS[t, :3], 0.0, None)
            n = el.extract.materials.shininess_from_roughness(float(TEXELS[t, 1]))
            want = helpers.env_specular(base, n, 1.0)
            at_mean = helpers.env_specular(base, el.extract.materials.shininess_from_roughness(float(TEXELS[:, 1].mean())), 1.0)
            print(f"texel {t}: drawn {ours[t]}, at its roughness {want}, at the mean roughness {at_mean}")
            np.testing.assert_allclose(ours[t], want, rtol=1e-3, atol=1e-4)


if __name__ == "__main__":
    unittest.main()
