"""Edge highlight pass: one quad per rounded edge (batches.edge_batches), shaded with EdgeLight's
method (shaders/edge_highlight.*), premultiplied into the highlight target, once per frame; then
the corner patches over them (batches.corner_batches, shaders/edge_corner.*)."""
from . import frame_data, pass_state, shader_lib, table
from .lighting_inputs import NONE
from .surface_pass import shading_uniforms, textured_uniforms
from .texture_variants import SURFACE_MODES, texture_defines, texture_key


def draw_highlights(targets, scene, gpu_meshes, ubo, stats, lighting=NONE):
    """Each instance's rounded edges into targets.highlight (the first sample's: the band's
    coverage is filtered across the edge analytically, docs/addon.md); counted in
    stats.edges_drawn. `lighting`: surface_pass.draw_surface's."""
    tex, info = table.table()
    # The table layout is fixed in the program (highlight_arc.glsl); the surface pass wrote ids:
    # visibility by face (docs/lines.md).
    defines = {**pass_state.table_defines("edge_highlight", info), "EL_EDGE_IDS": 1, **lighting.defines()}
    with pass_state.drawing("edge_highlight", targets.highlight_fb):
        # A Blinn-Phong material's bands replace the sharp faces under them (el_faces_under_band);
        # a toon material's faces are shaded otherwise, so its bands blend over the pixel.
        # A slot drawing an image in Base Color has its own variant, the texel along the edge
        # (texture_variants.texture_key).
        keys = {(_is_phong(s), texture_key(s, _mode(s), alpha=False)) for inst in scene.instances
                for k, s in enumerate(gpu_meshes[id(inst.mesh)].extract.slot_shading)
                if k in gpu_meshes[id(inst.mesh)].edges}
        for phong, image in sorted(keys, key=lambda k: (not k[0], k[1] or ())):
            def slots(gm, phong=phong, image=image):
                return {k: b for k, b in gm.edges.items()
                        if (_is_phong(gm.extract.slot_shading[k]), texture_key(gm.extract.slot_shading[k],
                                                                                 _mode(gm.extract.slot_shading[k]), alpha=False)) == (phong, image)}
            if not any(slots(gpu_meshes[id(inst.mesh)]) for inst in scene.instances):
                continue
            variant = {**defines, **({"EL_FACES_UNDER": 1} if phong else {}), **texture_defines(image)}
            shader = shader_lib.get("edge_highlight", variant)
            shader.bind()
            shader.uniform_block("frame", ubo)
            pass_state.bind_table(shader, "edge_highlight", tex, info)
            pass_state.bind_inputs(shader, "edge_highlight", targets)
            lighting.bind(shader)
            for gm, slot in _draw_per_slot(shader, scene, gpu_meshes, slots, textured=image is not None):
                stats.edges_drawn += len(gm.extract.edges[slot])
    draw_corners(targets, scene, gpu_meshes, ubo, lighting)


def _is_phong(shading):
    return int(shading.toon.mode) == SURFACE_MODES["PHONG"]


def _mode(shading):
    return int(shading.toon.mode)


def draw_corners(targets, scene, gpu_meshes, ubo, lighting=NONE):
    """Each instance's corner patches into targets.highlight, replacing the bands' mitres under
    them: the target scaled by 1 - each patch's coverage, then the patches added (a slot drawing
    an image in its own variant, the texel at the corner's vertex)."""
    if not any(gpu_meshes[id(inst.mesh)].corners for inst in scene.instances):
        return

    def key_of(gm, k):
        s = gm.extract.slot_shading[k]
        return texture_key(s, _mode(s), alpha=False) or ()  # a toon slot's corners take the mean, as its bands

    keys = sorted({key_of(gm, k) for gm in (gpu_meshes[id(inst.mesh)] for inst in scene.instances) for k in gm.corners})
    for pass_name, defines in (("edge_corner_cover", {"EL_CORNER_COVER": 1}), ("edge_corner", lighting.defines())):
        cover = pass_name != "edge_corner"
        with pass_state.drawing(pass_name, targets.highlight_fb):
            for key in [()] if cover else keys:
                image = key or None
                shader = shader_lib.get("edge_corner", {**defines, **texture_defines(image)})
                shader.bind()
                shader.uniform_block("frame", ubo)
                if not cover:
                    lighting.bind(shader)
                pass_state.bind_inputs(shader, pass_name, targets)

                def slots(gm, key=key, cover=cover):
                    return {k: b for k, b in gm.corners.items() if cover or key_of(gm, k) == key}
                _draw_per_slot(shader, scene, gpu_meshes, slots, textured=image is not None)


def _draw_per_slot(shader, scene, gpu_meshes, batches_of, textured=False):
    """Draws each instance's batches (batches_of(gpu mesh): slot -> batch) with its model
    matrix, its id and each slot's shading (`textured`: its image's, textured_uniforms);
    returns the (gpu mesh, slot) pairs drawn."""
    drawn = []
    for index, inst in enumerate(scene.instances):
        gm = gpu_meshes[id(inst.mesh)]
        batches = batches_of(gm)
        if not batches or inst.holdout:  # a hole in the image is not rounded
            continue
        shader_lib.set_uniform(shader, "model", frame_data.mat4(inst.matrix))
        shader_lib.set_uniform(shader, "instance_id", float(index + 1))
        for slot, batch in batches.items():
            s = gm.extract.slot_shading[slot]
            if textured:
                textured_uniforms(shader, s)
            else:
                shading_uniforms(shader, s)
            shader_lib.set_uniform(shader, "tint", (*s.tint, s.K))
            batch.draw(shader)
            drawn.append((gm, slot))
    return drawn
