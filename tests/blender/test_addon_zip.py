"""Headless test of the add-on's zip (build/blender/somicage_cage_deform.zip, CMake target somicage_blender_addon) as
an artist installs it: Preferences > Add-ons > Install into a clean user profile, enable, bind, deform.

    BLENDER_USER_CONFIG=build/blender-zip-profile/config BLENDER_USER_SCRIPTS=build/blender-zip-profile/scripts \
    SOMICAGE_ADDON_ZIP=build/blender/somicage_cage_deform.zip \
    blender -b --factory-startup --python-exit-code 1 --python tests/blender/test_addon_zip.py

The profile folder (whose name must be blender-zip-profile) is emptied first. No module path is given: the add-on
must import the somicage module it carries. A UV sphere is bound to a box; the box moved by d moves the sphere by d
(every method reproduces a translation; 1e-6 cage diameters: Blender stores float32); unbind restores it exactly.
"""
import os
import pathlib
import shutil
import sys

import addon_utils
import bmesh
import bpy
import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import scene_helpers  # noqa: E402

ADDON = "somicage_cage_deform"
TOLERANCE = 1e-6  # cage diameters

zip_path = pathlib.Path(os.environ.get("SOMICAGE_ADDON_ZIP", ""))
scripts = pathlib.Path(os.environ.get("BLENDER_USER_SCRIPTS", ""))
assert zip_path.is_file(), f"no add-on zip at '{zip_path}': build the CMake target somicage_blender_addon"
assert scripts.parent.name == "blender-zip-profile", f"BLENDER_USER_SCRIPTS={scripts}: not a test profile folder"
os.environ.pop("SOMICAGE_PYTHON_PATH", None)  # the add-on must find the module it carries
assert "somicage" not in sys.modules

if scripts.parent.exists():
    shutil.rmtree(scripts.parent)  # a clean profile: no add-on installed, no preferences
scripts.mkdir(parents=True)

assert bpy.ops.preferences.addon_install(filepath=str(zip_path)) == {"FINISHED"}
installed = scripts / "addons" / ADDON
assert (installed / "__init__.py").is_file(), f"the zip did not install into {installed}"
assert bpy.ops.preferences.addon_enable(module=ADDON) == {"FINISHED"}
assert addon_utils.check(ADDON) == (True, True), addon_utils.check(ADDON)

engine = sys.modules[f"{ADDON}.engine"]
somicage = engine.somicage_module()
assert pathlib.Path(somicage.__file__).is_relative_to(installed / "bundled"), somicage.__file__
print(f"somicage {somicage.__version__} from {somicage.__file__}")


for obj in list(bpy.data.objects):  # the factory scene's cube, camera and light
    bpy.data.objects.remove(obj)
ball = scene_helpers.ball()
box = scene_helpers.add_mesh("Box", lambda bm: bmesh.ops.create_cube(bm, size=2.0))
original = scene_helpers.shown(ball)
bpy.context.view_layer.objects.active = ball
ball.somicage.cage = box
assert [item[0] for item in engine.method_items(ball.somicage, bpy.context)] == somicage.methods()

assert bpy.ops.somicage.bind() == {"FINISHED"}
d = np.array([0.1, -0.05, 0.02])
box.location = d
bpy.context.view_layer.update()
error = np.abs(scene_helpers.shown(ball) - (original + d)).max() / 2.0
print(f"box moved by d: the ball is {error:.1e} cage diameters from ball + d")
assert error <= TOLERANCE, f"{error:.2e} cage diameters > {TOLERANCE}"
assert bpy.ops.somicage.unbind() == {"FINISHED"}
assert np.array_equal(scene_helpers.shown(ball), original), "unbind did not restore the original coordinates"
print("blender add-on zip test: OK")
