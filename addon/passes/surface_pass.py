"""Surface pass: each material slot's triangles, shaded (Blinn-Phong, toon ramp, X-Toon or
whiteout), into the surface targets; with ids, which instance and face covers each pixel."""
import gpu
import numpy as np

from ..extract import textures
from ..geometry import closed_surfaces, rounded_outline
from . import frame_data, material_data, pass_state, shader_lib, toon
from .lighting_inputs import NONE
from .targets import surface_outputs
from .texture_variants import SURFACE_MODES, texture_defines, texture_key

# The node program's images, in its order (material_program.glsl).
IMAGE_SAMPLERS = ("base_tex", "base_tex1", "base_tex2", "base_tex3")


def shading_uniforms(shader, s):
    """A material slot's colours (materials.Shading), shared by the surface and edge passes, and
    its MaterialData block (emission)."""
    shader_lib.set_uniform(shader, "base_color", (*s.base_color, s.alpha))
    shader_lib.set_uniform(shader, "spec_color", (*s.spec_color, s.shininess))
    shader_lib.set_block(shader, "material", material_data.buffer(s))


def _surface_mode(s, whiteout, holdout=False):
    """The surface program's shading mode (shaders/surface_modes.json): the material's
    (toon.mode: materials.py), or WHITEOUT, or HOLDOUT for an instance masked out."""
    if holdout:
        return SURFACE_MODES["HOLDOUT"]
    return SURFACE_MODES["WHITEOUT"] if whiteout else int(s.toon.mode)


def _toon_uniforms(shader, s, mode):
    """The toon parameters, and the texture of a ramp or X-Toon mode."""
    t = s.toon
    shader_lib.set_uniform(shader, "toon", (float(mode), t.near, t.far, (1.0 if t.smooth else 0.0) + (2.0 if t.orientation else 0.0)))
    if mode == SURFACE_MODES["RAMP"]:
        shader_lib.set_sampler(shader, "toon_ramp", toon.ramp_texture(t))
    elif mode == SURFACE_MODES["XTOON"]:
        shader_lib.set_sampler(shader, "toon_map", toon.map_texture(t, s.base_color))


def slot_first_ids(extract):
    """slot -> the surface id of its batch's first triangle (scene_sync: ids follow slot order)."""
    out, first = {}, 1
    for slot, tris in extract.slot_triangles.items():
        out[slot] = first
        first += len(tris)
    return out


def cull_modes(scene, camera):
    """Per instance, what its surface culls, once per frame (the samples share the camera):
    'NONE', or its back faces where they cannot show (a closed surface wholly in front of the
    near plane: closed_surfaces.py), which are the faces wound clockwise on screen, or
    counter-clockwise where its transform mirrors it (surface.frag's front and back take the
    mirror into account the same way)."""
    clip_matrix = np.asarray(camera.projection, np.float64) @ np.asarray(camera.view, np.float64)
    out = ['NONE'] * len(scene.instances)
    closed = [i for i, inst in enumerate(scene.instances) if inst.mesh.closed and inst.mesh.box is not None]
    if not closed:
        return out
    matrices = np.stack([np.asarray(scene.instances[i].matrix, np.float64) for i in closed])
    boxes = np.stack([np.asarray(scene.instances[i].mesh.box, np.float64) for i in closed])
    hidden = closed_surfaces.hidden_back_faces(boxes, matrices, clip_matrix)
    mirrored = np.linalg.det(matrices[:, :3, :3]) < 0.0
    for k, i in enumerate(closed):
        if hidden[k]:
            out[i] = 'FRONT' if mirrored[k] else 'BACK'
    return out


def textured_uniforms(shader, s):
    """A textured slot's uniforms: its colours (alpha; the node program in its MaterialData
    block gives the rest: materials.BaseTexture) and its images."""
    shading_uniforms(shader, s)
    images = s.texture.program.images
    for k, name in enumerate(IMAGE_SAMPLERS):
        shader_lib.set_sampler(shader, name, textures.gpu_texture(images[k].image) if k < len(images)
                               else textures.no_image())


def draw_surface(targets, scene, gpu_meshes, ubo, whiteout=False, ids=False, rounded=False, culls=None,
                 lighting=NONE):
    """One program per shading mode in use (EL_SURFACE_MODE is fixed when it is built: a uniform
    branch would make every fragment pay for every mode on llvmpipe). With `ids`, the variant
    that also writes which instance and face covers each pixel (the line pass's visibility,
    docs/lines.md). With `rounded` (the edge pass draws the bands), the triangles a rounded
    convex edge's strip or a corner's zone may cross leave out the strip between a sharp
    silhouette and its fillet's outline (rounded_outline.glsl), in their own variant and batch
    (batches.GpuMesh.outline), and those that list more edges than its vertex shader judges in
    a variant that judges the rest per pixel (EL_OUTLINE_MORE). `culls` (cull_modes), per instance: a closed surface's back
    faces culled where they cannot show (closed_surfaces.py), since the strips would show its
    inside. `lighting`: the frame's shadow maps and environment atlas (lighting_inputs.py)."""
    draws, firsts = {}, {}
    for index, inst in enumerate(scene.instances):
        gm = gpu_meshes[id(inst.mesh)]
        cull = culls[index] if culls else 'NONE'
        if ids and id(gm.extract) not in firsts:  # once per geometry, not per instance
            firsts[id(gm.extract)] = slot_first_ids(gm.extract)
        first = firsts.get(id(gm.extract), {})
        for slot, batch in gm.surface.items():
            s = gm.extract.slot_shading[slot]
            mode = _surface_mode(s, whiteout, inst.holdout)
            ids_of = (float(index + 1), float(first.get(slot, 0)))
            # A holdout has no bands, so nothing fills the strips the rounded outline leaves out.
            outline = gm.outline.get(slot) if rounded and not inst.holdout else None
            tex = texture_key(s, mode)
            if outline is None:
                draws.setdefault((mode, 0, tex), []).append((inst.matrix, s, batch, ids_of, None, cull))
                continue
            sides, listed, rest, more = outline
            for kind, part in ((0, rest), (1, listed), (2, more)):
                if part is not None:
                    draws.setdefault((mode, kind, tex), []).append((inst.matrix, s, part, ids_of, sides if kind else None, cull))
    outputs = surface_outputs(targets, ids)
    with pass_state.drawing("surface", targets.surface_ids_fb if ids else targets.surface_fb):
        for (mode, outline, tex), items in sorted(draws.items(), key=lambda kv: (kv[0][0], kv[0][1], kv[0][2] or ())):
            defines = {"EL_SURFACE_MODE": mode, **outputs, **texture_defines(tex)}
            if mode not in (SURFACE_MODES["HOLDOUT"], SURFACE_MODES["WHITEOUT"]):
                defines.update(lighting.defines())
            if outline:
                defines.update(EL_ROUNDED_OUTLINE=1, **rounded_outline.layout_defines())
            if outline == 2:
                defines.update(EL_OUTLINE_MORE=1)
            shader = shader_lib.get("surface", defines)
            shader.bind()
            shader.uniform_block("frame", ubo)
            if mode not in (SURFACE_MODES["HOLDOUT"], SURFACE_MODES["WHITEOUT"]):
                lighting.bind(shader)
            for matrix, s, batch, surface_ids, sides, cull in items:
                gpu.state.face_culling_set(cull)
                shader_lib.set_uniform(shader, "model", frame_data.mat4(matrix))
                shader_lib.set_uniform(shader, "surface_ids", surface_ids)
                if tex is None:
                    shading_uniforms(shader, s)
                else:
                    textured_uniforms(shader, s)
                _toon_uniforms(shader, s, mode)
                if sides is not None:
                    shader_lib.set_sampler(shader, "outline_edges", sides[0])
                    shader_lib.set_sampler(shader, "outline_corners", sides[1])
                    shader_lib.set_sampler(shader, "outline_triangles", sides[2])
                batch.draw(shader)
        gpu.state.face_culling_set('NONE')
