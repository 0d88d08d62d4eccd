"""Whether a change moved any pixel: renders the samples (fandisk, prop, cube: lines on, 4
samples), six separate boxes with silhouettes, creases and contours, and a smooth cylinder, and
saves each image; `compare` says how far two builds' images are apart. What a port of the
add-on's numpy into the library must leave bit for bit as it was (issue 41: "nothing in the
images changes").

    BLENDER_USER_SCRIPTS=<one build's add-on> blender -b --factory-startup --addons edgelight \\
        --python bench/image_regression.py -- render OUT_DIR
    python3 bench/image_regression.py compare OLD_DIR NEW_DIR

(scripts/install_addon.sh with BUILD_DIR set installs a build's package; a git worktree of the
earlier commit gives the other build.)
"""
import os
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def render(out):
    sys.path.insert(0, os.path.join(ROOT, "tests", "blender"))
    import bpy

    import helpers
    import scene_zoo as zoo
    os.makedirs(out, exist_ok=True)

    def save(name):
        np.save(os.path.join(out, name + ".npy"), np.asarray(helpers.render()["pixels"], np.float32))

    for sample in ("fandisk", "prop", "cube"):
        helpers.open_sample(sample)
        s = bpy.context.scene
        s.render.resolution_x, s.render.resolution_y, s.render.resolution_percentage = 480, 360, 100
        s.edgelight.use_lines, s.edgelight.samples = True, 4
        save(sample)
    helpers.empty_scene(360, 360)
    helpers.add_sun()
    helpers.add_camera((3.0, -6.0, 5.0), lens=35.0)
    for i in range(6):
        zoo.box(f"Box{i}", 1.0, location=((i % 3) * 1.8 - 1.8, (i // 3) * 1.8 - 0.9, 0.0))
    helpers.only_lines(bpy.context.scene, silhouette=3.0, crease=1.5, contour=1.0)
    save("boxes")
    helpers.empty_scene(360, 360)
    helpers.add_sun()
    helpers.add_camera((2.2, -3.0, 2.6))
    zoo.cylinder("Cylinder")
    bpy.context.scene.edgelight.use_lines = True
    save("cylinder")


def compare(old, new):
    """Per image: the largest difference of any channel, and the pixels past 1e-3 and 1e-2."""
    worst = 0.0
    for name in sorted(f for f in os.listdir(old) if f.endswith(".npy")):
        d = np.abs(np.load(os.path.join(old, name)) - np.load(os.path.join(new, name))).max(axis=2)
        worst = max(worst, float(d.max()))
        print(f"{name[:-4]:10s} largest difference {d.max():.2e}, pixels past 1e-3: {(d > 1e-3).sum()}, "
              f"past 1e-2: {(d > 1e-2).sum()} of {d.size}")
    return worst


if __name__ == "__main__":
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else sys.argv[1:]
    if args[:1] == ["render"] and len(args) == 2:
        render(args[1])
    elif args[:1] == ["compare"] and len(args) == 3:
        sys.exit(1 if compare(args[1], args[2]) > 0.0 else 0)
    else:
        sys.exit(__doc__)
