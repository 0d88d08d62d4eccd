"""Viewport (Rendered shading): the final render's passes drawn into the 3D view.

Caches are keyed on what changed (depsgraph updates), so each kind of change costs only its own
work: geometry -> that object's extraction, native classification and GPU batches; transform ->
matrices; material -> shading (and the edge batch of an object whose chosen edges changed); view
-> culling counts and a redraw; nothing -> the last image is drawn again, with no native call,
no upload and no pass.
"""
import dataclasses
import time
from dataclasses import dataclass

import bpy
import numpy as np

from ..extract import scene_sync, world_light
from ..extract.materials import shading_of
from ..geometry import edge_choice
from ..geometry.radius_scale import radius_scale
from ..linework import lines
from ..passes import batches, camera, frame, frame_data, line_pass, shadow_plan, toon, view_lines
from ..passes.targets import Targets
from . import clamp_notes

# Below one 8-bit step an edge cannot change a pixel.
MIN_WEIGHT = 1.0 / 255.0


@dataclass
class Counters:
    updates: int = 0          # view_update calls
    draws: int = 0            # view_draw calls
    native_calls: int = 0     # calls into libedgelight (mesh builds)
    uploads: int = 0          # GPU batches built
    extracts: int = 0         # objects (re)read from Blender
    passes: int = 0           # frames drawn with the passes (not a cached image)
    cache_hits: int = 0       # draws that reused the last image
    view_changes: int = 0
    objects: int = 0
    edges_drawn: int = 0
    edges_culled: int = 0
    view_calls: int = 0       # native view updates (silhouettes, contours) for a new view
    view_uploads: int = 0     # view-dependent line batches built
    lines_drawn: int = 0      # line segments drawn in the last pass

    def as_dict(self):
        return dict(self.__dict__)


# The most recent viewport state, for tests and the benchmark script.
last_state = None


@dataclass
class ObjectCache:
    extract: object                    # scene_sync.MeshExtract
    materials: list                    # the material per slot at extraction
    gpu: object = None                 # batches.GpuMesh, built in view_draw
    edges_stale: bool = False          # the chosen edges changed: rebuild the edge batches only
    lines_stale: bool = False          # the static line sets changed: rebuild their batches only


class ViewportState:
    def __init__(self):
        self.objects = {}              # scene_sync.geometry_key -> ObjectCache (None: skipped)
        self.owners = {}               # the same keys -> names whose geometry update makes it stale
        self.instances = []
        self.lights = []
        self.ambient = (0.0, 0.0, 0.0)
        self.environment = None
        self.world = None  # world_light.WorldLight, read again when the world may have changed
        self.world_pointer = 0
        self.reports = []              # what the status bar says: the notes below, once each
        self.status_text = ""          # what it last said (the viewport tests read it)
        self.notes = {}                # geometry key -> its extraction's notes (or why it was skipped)
        self.scene_notes = []          # of the last sync: objects not drawn, lights past the limit
        self.view_notes = []           # of the last view lines: instances the library refused
        self.draw_notes = []           # of the last pass: what it skipped
        self.targets = None
        self.view_key = None
        self.image_valid = False
        self.signature = None
        self.counted_at = -1e9
        self.count_cost = 0.0
        self.counts_stale = True
        self.counters = Counters()
        self.line_settings = None
        self.view_batches = []
        self.view_lines_key = None

    # ---- view_update -------------------------------------------------------------------
    def sync(self, depsgraph, lib, space=None):
        """`space`: the 3D view (its local view hides what is not in it)."""
        self.counters.updates += 1
        geometry, shading = set(), False
        # The world is read again when it (its node tree included), its image or which world the
        # scene has changed: reading an Environment Texture's image costs all its pixels.
        world = depsgraph.scene.world
        world_stale = self.world is None or self.world_pointer != (world.as_pointer() if world else 0)
        env_image = self.world.environment.key[1] if self.world is not None and self.world.environment else None
        for update in depsgraph.updates:
            idb = update.id
            world_stale = world_stale or isinstance(idb, bpy.types.World) or (
                isinstance(idb, bpy.types.Image) and idb.name_full == env_image)
            if isinstance(idb, bpy.types.Object) and update.is_updated_geometry:
                geometry.add(idb.name)
            elif isinstance(idb, bpy.types.Material) or (isinstance(idb, bpy.types.Object) and update.is_updated_shading):
                shading = True  # a material's settings, or which material a slot holds
            elif isinstance(idb, bpy.types.Image):
                toon.forget_images()  # an X-Toon image was edited
                shading = True
        self.line_settings = lines.settings_of(depsgraph.scene.edgelight)
        # Geometry updates make stale every extraction an updated object owns (its own mesh, or
        # the instances it makes): the keys are pointers, which a re-evaluation may reuse.
        stale = {k for k, owners in self.owners.items() if geometry.intersection(owners)}
        seen, reshaded = set(), set()

        def lookup(cache_key, ob, inst, materials):
            if cache_key not in seen:
                seen.add(cache_key)
                cache = self.objects.get(cache_key, False)
                if cache is False or cache_key in stale:
                    self.objects[cache_key], self.notes[cache_key] = self._extract(ob, inst, materials, lib)
                    self.owners[cache_key] = scene_sync.instance_owners(inst)
                elif shading and cache is not None and cache_key not in reshaded:
                    reshaded.add(cache_key)
                    if self._reshade(cache, materials):
                        self.notes[cache_key] = cache.extract.notes()
                    else:  # its images read other UV maps: the corners' UVs are read again
                        self.objects[cache_key], self.notes[cache_key] = self._extract(ob, inst, materials, lib)
            cache = self.objects[cache_key]
            if cache is None:
                return None
            if cache.extract.update_lines(self.line_settings):
                cache.lines_stale = True  # crease angle, marks or tapering changed
            return cache.extract

        instances, lights, not_drawn = scene_sync.walk_instances(
            depsgraph, lookup, scene_sync.viewport_shown(depsgraph.view_layer, space))
        removed = [k for k in self.objects if k not in seen]
        for key in removed:
            del self.objects[key]  # deleted objects and instances: their batches go with them
            self.owners.pop(key, None)
            self.notes.pop(key, None)  # and what was said of them
        note = scene_sync.not_drawn_note(not_drawn)
        self.scene_notes = [note] if note else []
        if len(lights) > frame_data.MAX_LIGHTS:
            self.scene_notes.append(f"{len(lights)} lights; the {frame_data.MAX_LIGHTS} first are used")
        if world_stale:
            self.world = world_light.read(depsgraph.scene.world)
            self.world_pointer = depsgraph.scene.world.as_pointer() if depsgraph.scene.world else 0
        world = self.world
        if world.note:
            self.scene_notes.append(world.note)
        self._gather_reports()
        self.instances, self.lights = instances, lights
        self.ambient, self.environment = world.ambient, world.environment
        # Updates that change nothing drawn (selection, UI, colour management, which the display
        # shader applies) keep the last image.
        signature = scene_signature(self, depsgraph.scene)
        if geometry or shading or removed or signature != self.signature:
            self.image_valid = False
            self.counts_stale = True  # the status bar's edge counts follow the scene, not only the view
        self.signature = signature

    def _extract(self, ob, inst, materials, lib):
        self.counters.extracts += 1
        try:
            extract = scene_sync.read_object(ob, scene_sync.instance_label(inst), materials, lib=lib,
                                             line_settings=self.line_settings)
            self.counters.native_calls += extract is not None  # an empty host builds nothing
        except scene_sync.SkipObject as e:
            extract, notes = None, [str(e)]
        else:
            notes = extract.notes() if extract is not None else []
            if extract is not None:
                clamp_notes.NOTES.hold(extract)  # the material panel's note counts what this view draws
        return (ObjectCache(extract, materials) if extract is not None else None), notes

    def _gather_reports(self):
        """The status bar's notes, once each: of the objects drawn now, of the scene, of the view
        lines. A note goes once what it was about is deleted or mended."""
        notes = ([n for k in self.objects for n in self.notes.get(k, ())] + self.scene_notes + self.view_notes
                 + self.draw_notes)
        self.reports = list(dict.fromkeys(notes))

    def _reshade(self, cache, materials):
        """Material settings changed: new uniforms; new edge batches only where the chosen edges
        changed. No native call: the classification is kept in the extract. The extract is
        replaced by a copy with the new shading and edges, never changed in place: what still
        holds the old one (the last instances, a render's scene) keeps a consistent one.
        Returns False, changing nothing, when a slot's image now reads another UV map or its
        program another colour attribute (or a slot gained or lost one): the object is then
        extracted again."""
        ex = cache.extract
        shading = [shading_of(m) for m in materials] or [shading_of(None)]
        if batches.slot_corner_inputs(shading, ex.missing_uv) != batches.slot_corner_inputs(ex.slot_shading):
            return False  # the batches hold each slot's UVs and colours (batches.slot_uv, slot_colors)
        chosen = edge_choice.choose(ex.edge_data, shading)
        same = edge_choice.same_edges(chosen.edges, ex.edges)
        cache.materials = list(materials)
        cache.extract = dataclasses.replace(ex, slot_shading=shading, edges=ex.edges if same else chosen.edges,
                                            clamps=chosen.clamps)
        clamp_notes.NOTES.hold(cache.extract)
        if cache.gpu is not None:
            cache.gpu.extract = cache.extract  # its batches draw the new extract's shading
        cache.edges_stale = cache.edges_stale or not same
        return True

    # ---- view_draw ---------------------------------------------------------------------
    def draw(self, engine, context, depsgraph):
        self.counters.draws += 1
        region, rv3d = context.region, context.region_data
        width, height = region.width, region.height
        camera = viewport_camera(rv3d, width, height)
        key = (width, height, tuple(np.asarray(camera.view).ravel()), tuple(np.asarray(camera.projection).ravel()))
        settings = depsgraph.scene.edgelight
        fresh = False
        if self.targets is None or self.targets.size != (width, height):
            self.targets = Targets(width, height)
            self.image_valid = False
        gpu_meshes = {}
        for cache in self._caches():
            if cache.gpu is None:
                cache.gpu = batches.GpuMesh(cache.extract)
                self.counters.uploads += (len(cache.gpu.surface) + len(cache.gpu.edges) + len(cache.gpu.corners)
                                          + len(cache.gpu.lines))
                cache.edges_stale = cache.lines_stale = False
                fresh = True
            if cache.edges_stale:
                cache.gpu.rebuild_edges()
                self.counters.uploads += len(cache.gpu.edges) + len(cache.gpu.corners)
                cache.edges_stale, fresh = False, True
            if cache.lines_stale:
                cache.gpu.rebuild_lines()
                self.counters.uploads += len(cache.gpu.lines)
                cache.lines_stale, fresh = False, True
            gpu_meshes[id(cache.extract)] = cache.gpu
        if key != self.view_key:
            self.counters.view_changes += 1
            self.view_key = key
            self.image_valid = False
            self.counts_stale = True
        if self.counts_stale:
            self._maybe_count_culled(camera, settings.highlights)
        if self.image_valid and not fresh:
            self.counters.cache_hits += 1
        else:
            scene = scene_sync.SceneData(self.instances, self.lights, self.ambient, [], environment=self.environment)
            s = frame.Settings(samples=settings.viewport_samples, highlights=settings.highlights,
                               transparent=depsgraph.scene.render.film_transparent, lines=self.line_settings,
                               shadows=shadow_plan.settings_of(settings))
            if self._update_view_lines(scene, camera, key, settings.highlights):
                self.view_notes = list(scene.reports)  # said again only when the view lines are
            made = len(scene.reports)
            stats = frame.draw(scene, camera, s, self.targets, gpu_meshes, view_batches=self.view_batches)
            self.draw_notes = scene.reports[made:]
            self._gather_reports()
            self.counters.lines_drawn = stats.lines_drawn
            self.counters.passes += 1
            self.image_valid = True
        self.counters.objects = len(self.instances)
        blit(engine, depsgraph.scene, self.targets.result)
        # The engine's counters only with Debug's Developer Counters: an artist's status bar shows
        # what concerns the scene (the last note), nothing else.
        summary = self.summary(debug=depsgraph.scene.edgelight.show_debug_stats)
        self.status_text = " | ".join(t for t in (summary, self.reports[-1] if self.reports else "") if t)
        engine.update_stats("EdgeLight", self.status_text)

    def _update_view_lines(self, scene, camera, view_key, highlights):
        """Silhouettes and contours for this view: native view calls and new batches only when
        the view, an instance or the view-dependent line settings changed (with the highlights
        on, silhouettes of rounded edges lie on the fillets' outline: lines.view_lines). True
        when they were made again."""
        ls = self.line_settings
        rounded = bool(highlights) and not (ls is not None and ls.whiteout)
        view_styles = tuple((t, st.taper > 0.0) for t, st in ls.styles if t in lines.VIEW_TYPES) if ls else ()
        # Per instance its geometry (the native mesh: a material change copies the extract but
        # keeps it; with rounded silhouettes the extract too, whose radii they follow) and its
        # transform.
        key = (view_key, view_styles, rounded,
               tuple((id(i.mesh.native), id(i.mesh) if rounded else 0, i.matrix.tobytes(), i.holdout)
                     for i in self.instances)) if view_styles else None
        if key == self.view_lines_key:
            return False
        self.view_lines_key = key
        if key is None:
            self.view_batches = []
            return True
        segments = view_lines.view_line_segments(scene, camera, ls, self.counters, rounded)
        self.view_batches = line_pass.view_line_batches(segments)
        self.counters.view_uploads += sum(len(b) for b in self.view_batches)
        return True

    def _caches(self):
        """The caches of the drawn meshes, each once (instances share one)."""
        by_extract = {id(c.extract): c for c in self.objects.values() if c is not None}
        seen = set()
        for inst in self.instances:
            if id(inst.mesh) not in seen:
                seen.add(id(inst.mesh))
                yield by_extract[id(inst.mesh)]

    def _maybe_count_culled(self, camera, highlights):
        """The counts are statistics and cost a numpy pass over every edge (about 1 s for 750k
        edges here): while the view or the scene keeps changing they are refreshed only after
        20x their own cost has passed (at least 0.5 s), so they take at most ~5% of the time
        (a later draw, a cached one too, takes them once that has passed); not at all when no
        edge is drawn."""
        now = time.monotonic()
        if not highlights:
            self.counters.edges_drawn = self.counters.edges_culled = 0
            self.counts_stale = False
        elif now - self.counted_at >= max(0.5, 20.0 * self.count_cost):
            self._count_culled(camera)
            self.counted_at = time.monotonic()
            self.count_cost = self.counted_at - now
            self.counts_stale = False

    def _count_culled(self, camera):
        """What the edge shader culls (both faces turned away, outside the view, W below one
        8-bit step), counted on the CPU once per view for the statistics."""
        drawn = culled = 0
        for inst in self.instances:
            if inst.holdout:
                continue  # a hole in the image has no bands
            for slot, edges in inst.mesh.edges.items():
                keep = visible_edges(edges, inst.matrix, camera, inst.mesh.slot_shading[slot].K)
                drawn += int(keep.sum())
                culled += int(len(keep) - keep.sum())
        self.counters.edges_drawn, self.counters.edges_culled = drawn, culled

    def summary(self, debug=False):
        """The engine's counters for the status bar: only with the Debug panel's Developer
        Counters ("" otherwise)."""
        if not debug:
            return ""
        c = self.counters
        return (f"{c.objects} objects | edges {c.edges_drawn} drawn, {c.edges_culled} culled | lines {c.lines_drawn}"
                f" | cache hits {c.cache_hits} | native calls {c.native_calls} | uploads {c.uploads}")


def scene_signature(state, scene):
    """Everything besides geometry and materials that the image depends on."""
    s = scene.edgelight
    return (tuple((id(i.mesh), i.matrix.tobytes(), i.holdout, i.casts_shadow) for i in state.instances),
            state.line_settings,
            tuple((lt.kind, lt.color, lt.position, lt.direction, lt.spot_cos, lt.spot_blend, lt.shadow, lt.radius)
                  for lt in state.lights),
            state.ambient, state.environment and state.environment.signature(), s.viewport_samples, s.highlights, scene.render.film_transparent,
            shadow_plan.settings_of(s))


def viewport_camera(rv3d, width, height):
    """The 3D view's camera (its region 3D's view and window matrices)."""
    return camera.from_view(np.array(rv3d.view_matrix, np.float64), np.array(rv3d.window_matrix, np.float64),
                            not rv3d.is_perspective, width, height)


def visible_edges(edges, matrix, camera, K):
    """Boolean per edge: the edge shader would draw it (same tests as edge_highlight.vert)."""
    m = np.asarray(matrix, np.float64)
    p0 = edges.p0 @ m[:3, :3].T + m[:3, 3]
    p1 = edges.p1 @ m[:3, :3].T + m[:3, 3]
    # Normals by the cofactor matrix (det x inverse transpose), as el_transform_normal does:
    # defined for a singular transform too (an object scaled to zero).
    c0, c1, c2 = m[:3, 0], m[:3, 1], m[:3, 2]
    cof = np.stack([np.cross(c1, c2), np.cross(c2, c0), np.cross(c0, c1)], axis=1)
    cof *= -1.0 if np.dot(c0, np.cross(c1, c2)) < 0.0 else 1.0
    n1, n2 = edges.n1 @ cof.T, edges.n2 @ cof.T
    mid = 0.5 * (p0 + p1)
    to_eye = (np.asarray(camera.eye) - mid) if not camera.orthographic else np.repeat(-np.asarray(camera.view_dir)[None], len(mid), 0)
    front = (np.einsum("ij,ij->i", n1, to_eye) > 0) | (np.einsum("ij,ij->i", n2, to_eye) > 0)
    clip_m = camera.projection @ camera.view
    c0 = np.c_[p0, np.ones(len(p0))] @ clip_m.T
    c1 = np.c_[p1, np.ones(len(p1))] @ clip_m.T
    outside = np.zeros(len(p0), bool)
    for axis in range(3):
        outside |= (c0[:, axis] > c0[:, 3]) & (c1[:, axis] > c1[:, 3])
        outside |= (c0[:, axis] < -c0[:, 3]) & (c1[:, axis] < -c1[:, 3])
    dist = np.linalg.norm(to_eye, axis=1) if not camera.orthographic else 1.0
    scale = radius_scale(m, edges.n1, edges.n2, edges.p1 - edges.p0)
    n1u = n1 / np.maximum(np.linalg.norm(n1, axis=1, keepdims=True), 1e-30)
    n2u = n2 / np.maximum(np.linalg.norm(n2, axis=1, keepdims=True), 1e-30)
    width_px = edges.radius * scale * np.linalg.norm(n1u - n2u, axis=1) * camera.px_per_unit / dist
    return front & ~outside & (K * np.minimum(width_px, 1.0) >= MIN_WEIGHT)


def blit(engine, scene, texture):
    """Draws the scene-linear result through Blender's display transform (view transform,
    look, exposure), premultiplied over the viewport, as Blender's RenderEngine example does."""
    import gpu
    from gpu_extras.presets import draw_texture_2d
    gpu.state.blend_set('ALPHA_PREMULT')
    engine.bind_display_space_shader(scene)
    draw_texture_2d(texture, (0, 0), texture.width, texture.height)
    engine.unbind_display_space_shader()
    gpu.state.blend_set('NONE')
