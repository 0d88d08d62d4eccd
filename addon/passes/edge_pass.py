"""Edge highlight pass: one quad per rounded edge (batches.edge_batches), shaded with EdgeLight's
method (shaders/edge_highlight.*), premultiplied into the highlight target, once per frame; then
the corner patches over them (batches.corner_batches, shaders/edge_corner.*)."""
from . import frame_data, pass_state, shader_lib, table
from .surface_pass import SURFACE_MODES, shading_uniforms, shadow_defines


def draw_highlights(targets, scene, gpu_meshes, ubo, stats, shadow_maps=None):
    """Each instance's rounded edges into targets.highlight (the first sample's: the band's
    coverage is filtered across the edge analytically, docs/addon.md); counted in
    stats.edges_drawn. `shadow_maps`: surface_pass.draw_surface's."""
    tex, info = table.table()
    # The table layout is fixed in the program (highlight_arc.glsl); the surface pass wrote ids:
    # visibility by face (docs/lines.md).
    defines = {**pass_state.table_defines("edge_highlight", info), "EL_EDGE_IDS": 1, **shadow_defines(shadow_maps)}
    with pass_state.drawing("edge_highlight", targets.highlight_fb):
        # A Blinn-Phong material's bands replace the sharp faces under them (el_faces_under_band);
        # a toon material's faces are shaded otherwise, so its bands blend over the pixel.
        for phong in (True, False):
            def slots(gm, phong=phong):
                return {k: b for k, b in gm.edges.items() if _is_phong(gm.extract.slot_shading[k]) == phong}
            if not any(slots(gpu_meshes[id(inst.mesh)]) for inst in scene.instances):
                continue
            shader = shader_lib.get("edge_highlight", {**defines, "EL_FACES_UNDER": 1} if phong else defines)
            shader.bind()
            shader.uniform_block("frame", ubo)
            pass_state.bind_table(shader, "edge_highlight", tex, info)
            pass_state.bind_inputs(shader, "edge_highlight", targets)
            if shadow_maps is not None:
                shader_lib.set_sampler(shader, "shadow_maps", shadow_maps)
            for gm, slot in _draw_per_slot(shader, scene, gpu_meshes, slots):
                stats.edges_drawn += len(gm.extract.edges[slot])
    draw_corners(targets, scene, gpu_meshes, ubo, shadow_maps)


def _is_phong(shading):
    return int(shading.toon.mode) == SURFACE_MODES["PHONG"]


def draw_corners(targets, scene, gpu_meshes, ubo, shadow_maps=None):
    """Each instance's corner patches into targets.highlight, replacing the bands' mitres under
    them: the target scaled by 1 - each patch's coverage, then the patches added."""
    if not any(gpu_meshes[id(inst.mesh)].corners for inst in scene.instances):
        return
    for pass_name, defines in (("edge_corner_cover", {"EL_CORNER_COVER": 1}), ("edge_corner", shadow_defines(shadow_maps))):
        shader = shader_lib.get("edge_corner", defines)
        with pass_state.drawing(pass_name, targets.highlight_fb):
            shader.bind()
            shader.uniform_block("frame", ubo)
            if defines and "EL_SHADOWS" in defines:
                shader_lib.set_sampler(shader, "shadow_maps", shadow_maps)
            pass_state.bind_inputs(shader, pass_name, targets)
            _draw_per_slot(shader, scene, gpu_meshes, lambda gm: gm.corners)


def _draw_per_slot(shader, scene, gpu_meshes, batches_of):
    """Draws each instance's batches (batches_of(gpu mesh): slot -> batch) with its model
    matrix, its id and each slot's shading; returns the (gpu mesh, slot) pairs drawn."""
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
            shading_uniforms(shader, s)
            shader_lib.set_uniform(shader, "tint", (*s.tint, s.K))
            batch.draw(shader)
            drawn.append((gm, slot))
    return drawn
