"""Upgrades EdgeLight settings saved by older add-on versions when a .blend is opened.

Every settings group stores the layout it was saved with in `settings_version`, stamped on save.
Files written before stamping existed (layout 1) have no stamp. On load each group is brought
from its layout to properties.SETTINGS_VERSION one step at a time.

Values of properties the current layout no longer defines are still in the file, as raw ID
properties of the group: `group.get(name)` reads them (group-level access works 3.4 through
5.x; only `id["edgelight"]` is gone in 5.0).
"""
import bpy
from bpy.app.handlers import persistent

from ..extract import color_ramp, materials
from ..extract.material_defaults import RADIUS_LAYOUT_4
from .properties import K_MAX, SETTINGS_VERSION

STAMP = "settings_version"


def _material_1_to_2(group):
    """Layout 2 renamed `enabled` to `use_rounding` (Blender's `use_` convention for toggles)."""
    if "enabled" in group.keys():
        group.use_rounding = bool(group["enabled"])
        del group["enabled"]


def _material_2_to_3(group):
    """Layout 3 keeps the toon ramp in a colour ramp (color_ramp.py) instead of a list of stops
    (`ramp`: groups of `position` and `color`, unset values at their defaults) with
    `ramp_interpolation` (0 stepped, 1 smooth)."""
    keys = group.keys()
    interpolation = ('CONSTANT', 'LINEAR')[int(group.get("ramp_interpolation", 0))]
    stops = [(float(st.get("position", 0.0)), tuple(st.get("color", (0.8, 0.8, 0.8)))) for st in group.get("ramp") or ()]
    if not stops and interpolation == 'LINEAR' and "ramp_interpolation" in keys:
        # An empty list drew the base colour's two bands, smooth here: keep that look.
        stops = list(materials.default_ramp(materials.base_color_of(group.id_data)))
    if stops and group.shade_ramp is None:
        group.shade_ramp = color_ramp.new_ramp(stops, interpolation)
    for key in ("ramp", "ramp_index", "ramp_interpolation"):
        if key in keys:
            del group[key]


def _material_3_to_4(group):
    """Layout 4 caps Highlight Strength (`K`) at 1 (properties.K_MAX). Above 1 it drew a band
    under a pixel wide as the band of K times the radius, and only undid the anti-aliasing of
    wider ones: so K > 1 becomes K = 1 with the radius times K, the same image where the band is
    under a pixel and a real wider fillet (still clamped to what its faces allow) where it is not.
    The stored values are read raw: Blender does not clamp a stored value to the new maximum."""
    k = group.get("K")
    if k is None or float(k) <= K_MAX:
        return
    radius = float(group.get("radius", RADIUS_LAYOUT_4))  # unstored: the default of its layout
    group.radius = radius * float(k)
    group.K = K_MAX


def _material_4_to_5(group):
    """Layout 5 raised the Radius default from 1 cm to 5 cm (material_defaults.RADIUS). Blender
    stores no value that was left at its default, so a group of an older file without a stored
    radius rendered at 1 cm: store that, and the file keeps its look."""
    if "radius" not in group.keys():
        group.radius = RADIUS_LAYOUT_4


def _scene_5_to_6(group):
    """Layout 6 draws cast shadows (docs/shadows.md), on by default: a scene of an older layout
    drew none, so it keeps Shadows off until the artist turns them on."""
    group.use_shadows = False


# kind -> {layout: step from that layout to the next}
STEPS = {
    "material": {1: _material_1_to_2, 2: _material_2_to_3, 3: _material_3_to_4, 4: _material_4_to_5},
    "scene": {5: _scene_5_to_6},
}


def stored_layout(group):
    """The layout a group was saved with; None if it stores nothing (all defaults)."""
    if not group.keys():
        return None
    return int(group.get(STAMP, 1))


def upgrade(group, kind):
    """Brings one group to the current layout. Returns the layout it had (None: nothing stored)."""
    layout = stored_layout(group)
    if layout is None:
        return None
    for step in range(layout, SETTINGS_VERSION):
        fn = STEPS[kind].get(step)
        if fn:
            fn(group)
    if layout < SETTINGS_VERSION:  # a newer add-on's stamp is kept: its data is not ours to relabel
        group.settings_version = SETTINGS_VERSION
    return layout


def _groups():
    """(kind, group) for every editable ID's settings; linked IDs belong to their library file."""
    for kind, ids in (("material", bpy.data.materials), ("scene", bpy.data.scenes)):
        for id_block in ids:
            if id_block.library is None:
                yield kind, id_block.edgelight


def made_with_old_defaults():
    """Whether this file was drawn by EdgeLight before layout 5, whose defaults differ.
    Layout 5 stamps every scene EdgeLight draws on save (and in memory when a file is opened);
    before, only groups that stored a value were stamped, and layout 1 stamped nothing. So:
    - a scene stamped 5 or later says the file is current (a scene added since it was saved,
      or an autosave, which runs no save handler, has none yet);
    - else a group stamped older, a group that stores values without a stamp, or a scene set
      to EdgeLight in a saved file says it is older.
    A file never saved (a new one) is not."""
    local = [(kind, group) for kind, group in _groups()]
    if any(kind == "scene" and int(group.get(STAMP, 0)) >= 5 for kind, group in local):
        return False
    for kind, group in local:
        if STAMP in group.keys() and int(group[STAMP]) < 5:
            return True
        if STAMP not in group.keys() and group.keys():
            return True
    return bool(bpy.data.filepath) and any(
        s.library is None and s.render.engine == 'EDGELIGHT' for s in bpy.data.scenes)


def _keep_unstored_defaults():
    """A material that stores no EdgeLight value took every default. In a file made before
    layout 5 that was the 1 cm radius: store it. A scene EdgeLight drew that stores nothing drew
    no shadows then: store Shadows off (layout 6)."""
    count = 0
    for kind, group in _groups():
        if kind == "material" and not group.keys():
            _material_4_to_5(group)
            group.settings_version = SETTINGS_VERSION
            count += 1
        elif kind == "scene" and not group.keys() and _uses_edgelight(group):
            _scene_5_to_6(group)
            group.settings_version = SETTINGS_VERSION
            count += 1
    return count


def upgrade_all():
    """Upgrades every group; returns {old layout: count} of the groups that were older."""
    old_defaults = made_with_old_defaults()
    upgraded = {}
    for kind, group in _groups():
        layout = upgrade(group, kind)
        if layout is not None and layout < SETTINGS_VERSION:
            upgraded[layout] = upgraded.get(layout, 0) + 1
    if old_defaults:
        count = _keep_unstored_defaults()
        if count:
            upgraded[4] = upgraded.get(4, 0) + count
    # The scenes EdgeLight draws say from now on that these defaults are current.
    for kind, group in _groups():
        if kind == "scene" and _uses_edgelight(group) and int(group.get(STAMP, 0)) < SETTINGS_VERSION:
            group.settings_version = SETTINGS_VERSION
    return upgraded


def _uses_edgelight(scene_group):
    """A scene that stores EdgeLight settings or renders with it: the scenes stamped even when
    they store nothing (a scene of another engine gets no EdgeLight data)."""
    return bool(scene_group.keys()) or scene_group.id_data.render.engine == 'EDGELIGHT'


def stamp_all():
    """Records the current layout in every group that stores something, and in every scene, so
    the next load knows which defaults the file was made with (a scene of another engine gets
    nothing). A group stamped older (appended
    or pasted from an older file since it was opened) is upgraded first, not relabelled; an
    unstamped one is this session's."""
    for kind, group in _groups():
        if STAMP in group.keys() and int(group[STAMP]) < SETTINGS_VERSION:
            upgrade(group, kind)
        if (group.keys() or (kind == "scene" and _uses_edgelight(group))) and group.get(STAMP, 0) < SETTINGS_VERSION:
            group.settings_version = SETTINGS_VERSION


@persistent
def _load_post(*_args):
    upgraded = upgrade_all()
    if upgraded:
        print(f"EdgeLight: upgraded settings of {sum(upgraded.values())} data-blocks to layout {SETTINGS_VERSION}")


def _upgrade_open_file():
    # Enabled with a file already open: upgrade it as loaded, not after edits made without the
    # add-on (an unstamped group of this session would read as layout 1).
    if not bpy.data.is_dirty:
        _load_post()
    return None  # once


@persistent
def _save_pre(*_args):
    stamp_all()


def register():
    bpy.app.handlers.load_post.append(_load_post)
    bpy.app.handlers.save_pre.append(_save_pre)
    # Enabled after a file was opened: bpy.data is off limits while add-ons register, so upgrade
    # from the first timer tick. Timers run in the UI only: headless, put --addons before the
    # .blend on the command line (then load_post does it).
    bpy.app.timers.register(_upgrade_open_file, first_interval=0.0)


def unregister():
    if bpy.app.timers.is_registered(_upgrade_open_file):
        bpy.app.timers.unregister(_upgrade_open_file)
    for handlers, fn in ((bpy.app.handlers.load_post, _load_post), (bpy.app.handlers.save_pre, _save_pre)):
        while fn in handlers:
            handlers.remove(fn)
