"""Headless test of the Blender add-on (blender/somicage_cage_deform) on FIREHYDRANT:

    blender -b --factory-startup --python-exit-code 1 --python tests/blender/test_firehydrant_binding.py

checks the method menu and the panel's enabled settings against somicage.method_info(); binds the mesh to its
triangulated cage, moves the cage to the paper's pose (in edit mode, then by an animated shape
key) and checks the mesh against `somicage deform` to 1e-6 cage diameters; saves and reopens the file; bakes
three frames to shape keys and unbinds. Environment: SOMICAGE_PYTHON_PATH (build/python), SOMICAGE_CLI (the somicage executable),
SOMICAGE_MODELS_DIR. Exits 77 (skipped) when the models or the executable are absent.
"""
import os
import pathlib
import subprocess
import sys
import tempfile

import bmesh
import bpy
import numpy as np

REPO = pathlib.Path(__file__).resolve().parents[2]
MODELS = pathlib.Path(os.environ.get("SOMICAGE_MODELS_DIR", REPO.parent / "shared/models")) / "firehydrant"
CLI = os.environ.get("SOMICAGE_CLI", "")
TOLERANCE = 1e-6  # cage diameters: Blender stores coordinates in float32 (about 1e-7 of these)


def skip(reason):
    print(f"SKIPPED: {reason}")
    sys.exit(77)


if not (MODELS / "fireHydrant.obj").exists():
    skip(f"shared model FIREHYDRANT not found in {MODELS}")
if not os.access(CLI, os.X_OK):
    skip("the somicage executable is not given (SOMICAGE_CLI)")

sys.path.insert(0, str(REPO / "blender"))
import somicage_cage_deform as addon  # noqa: E402
from somicage_cage_deform import binding as addon_binding, engine, geometry, ui  # noqa: E402

bpy.ops.wm.read_factory_settings(use_empty=True)  # an empty scene
addon.register()
somicage = engine.somicage_module()

REST, POSED, MESH = (str(MODELS / name) for name in ("fireHydrant_cages_triangulated.obj",
                                                     "fireHydrant_cages_triangulated_deformed.obj", "fireHydrant.obj"))
SETTINGS = dict(nu=0.3, gamma=1.0, variant="local")


def reference():
    """`somicage deform` with the same settings: the mesh in the paper's pose."""
    with tempfile.TemporaryDirectory() as folder:
        out = os.path.join(folder, "out.obj")
        subprocess.run([CLI, "deform", "--cage", REST, "--posed", POSED, "--mesh", MESH, "--out", out, "--nu", "0.3",
                        "--gamma", "1", "--variant", "local"], check=True, capture_output=True)
        return somicage.load_mesh(out)[0]


def add_object(name, path):
    vertices, faces = somicage.load_mesh(path)
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(vertices.tolist(), [], faces)
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    return obj


def coordinates(obj):
    return geometry.local_coordinates(obj.data)


def check_close(what, actual, expected, diameter):
    error = np.abs(actual - expected).max() / diameter
    print(f"{what}: max error {error:.2e} cage diameters")
    assert error <= TOLERANCE, f"{what}: {error:.2e} cage diameters > {TOLERANCE}"


scene = bpy.context.scene
hydrant, cage = add_object("hydrant", MESH), add_object("cage", REST)
original = coordinates(hydrant)
rest_cage, posed_vertices = coordinates(cage), somicage.load_mesh(POSED)[0]
diameter = np.linalg.norm(rest_cage.max(axis=0) - rest_cage.min(axis=0))
expected = reference()

binding = hydrant.somicage
# The method menu is the engine's registry: every method of somicage.method_info(), named and described as there.
info = somicage.method_info()
assert engine.method_items(binding, bpy.context) == [(m["name"], m["display_name"], m["description"], k)
                                                    for k, m in enumerate(info)]
for m in info:  # through Blender's RNA: each is a value of the property, with its name and tooltip
    binding.method = m["name"]
    assert binding.method == m["name"]
    assert bpy.types.UILayout.enum_item_name(binding, "method", m["name"]) == m["display_name"], m
    assert bpy.types.UILayout.enum_item_description(binding, "method", m["name"]) == m["description"], m
    assert engine.method_parameters(m["name"]) == set(m["parameters"]), m


class LayoutRecorder:
    """Stands in for the panel's UILayout: which properties it draws, and whether their row is enabled."""
    def __init__(self, enabled=True):
        self.enabled, self.drawn, self.rows = enabled, [], []

    def prop(self, _data, name):
        self.drawn.append(name)

    def row(self):
        self.rows.append(LayoutRecorder())
        return self.rows[-1]

    column = row

    def operator(self, *_args, **_kwargs):
        pass

    def enabled_properties(self):
        names = set(self.drawn) if self.enabled else set()
        return names.union(*(row.enabled_properties() for row in self.rows))


# The panel enables a setting exactly when the method reads it (method_info's parameters and options; nu_infinite
# goes with nu).
SETTINGS_DRAWN = {"nu", "nu_infinite", "gamma", "variant", "traction_fix", "corotational", "bulging", "normals",
                  "tet_level"}
# The choice menus are the engine's table (somicage.choice_info()), names and order.
for choice in somicage.choice_info():
    items = getattr(addon_binding, choice["name"].upper())
    assert [item[0] for item in items] == [value[0] for value in choice["values"]], choice["name"]
bpy.context.view_layer.objects.active = hydrant
for m in info:
    binding.method = m["name"]
    panel = type("Panel", (), {"layout": LayoutRecorder()})()
    ui.SOMICAGE_PT_panel.draw(panel, bpy.context)
    # Deformer's own keywords (method_info's options: phong's tet_level) too.
    reads = set(m["parameters"]) | set(m["options"]) | ({"nu_infinite"} if "nu" in m["parameters"] else set())
    assert panel.layout.enabled_properties() & SETTINGS_DRAWN == reads & SETTINGS_DRAWN, m
binding.method = "somigliana"
print(f"method menu: {', '.join(m['name'] for m in info)}")

# Bind: the mesh stays where it is at rest.
bpy.context.view_layer.objects.active = hydrant
binding.cage = cage
binding.nu, binding.gamma, binding.variant = SETTINGS["nu"], SETTINGS["gamma"], SETTINGS["variant"]
assert bpy.ops.somicage.bind() == {"FINISHED"}
check_close("bound at rest", coordinates(hydrant), original, diameter)

# Edit the cage in edit mode, as an artist does: the depsgraph handler re-deforms the mesh.
bpy.context.view_layer.objects.active = cage
bpy.ops.object.mode_set(mode="EDIT")
edit = bmesh.from_edit_mesh(cage.data)
for vertex, position in zip(edit.verts, posed_vertices):  # edit-mode order is the mesh's vertex order
    vertex.co = position
bmesh.update_edit_mesh(cage.data)
bpy.context.view_layer.update()
check_close("cage edited (edit mode) to the paper's pose", coordinates(hydrant), expected, diameter)
bpy.ops.object.mode_set(mode="OBJECT")
bpy.context.view_layer.objects.active = hydrant

# Animate the cage (a shape key from rest at frame 1 to the pose at frame 3): the frame handler follows it.
cage.data.vertices.foreach_set("co", rest_cage.astype(np.float32).ravel())
cage.data.update()
cage.shape_key_add(name="Basis", from_mix=False)
pose_key = cage.shape_key_add(name="pose", from_mix=False)
pose_key.data.foreach_set("co", posed_vertices.astype(np.float32).ravel())
for frame, value in ((1, 0.0), (3, 1.0)):
    pose_key.value = value
    pose_key.keyframe_insert("value", frame=frame)
scene.frame_set(3)
check_close("animated cage at frame 3", coordinates(hydrant), expected, diameter)
scene.frame_set(1)
check_close("animated cage at frame 1 (rest)", coordinates(hydrant), original, diameter)

# Save and reopen: the binding comes back from what the file stores (the deformer is precomputed again).
with tempfile.TemporaryDirectory() as folder:
    saved = os.path.join(folder, "bound.blend")
    bpy.ops.wm.save_as_mainfile(filepath=saved)
    bpy.ops.wm.open_mainfile(filepath=saved)
scene, hydrant, cage = bpy.context.scene, bpy.data.objects["hydrant"], bpy.data.objects["cage"]
binding = hydrant.somicage
assert binding.bound and not addon_binding._deformers
bpy.context.view_layer.objects.active = hydrant
scene.frame_set(3)
check_close("reopened file, frame 3", coordinates(hydrant), expected, diameter)
scene.frame_set(1)

# Live off: the cage moves, the mesh does not.
binding.live = False
scene.frame_set(3)
check_close("live off", coordinates(hydrant), original, diameter)

# Bake frames 1..3 to shape keys.
assert bpy.ops.somicage.bake(frame_start=1, frame_end=3) == {"FINISHED"}
keys = hydrant.data.shape_keys.key_blocks
assert [k.name for k in keys] == ["Basis", "SomiCage frame 1", "SomiCage frame 2", "SomiCage frame 3"], keys.keys()
baked = np.empty(len(original) * 3, dtype=np.float32)
keys["SomiCage frame 3"].data.foreach_get("co", baked)
check_close("baked frame 3", baked.reshape(-1, 3).astype(float), expected, diameter)
keys["SomiCage frame 1"].data.foreach_get("co", baked)
check_close("baked frame 1", baked.reshape(-1, 3).astype(float), original, diameter)

# Unbind: the original coordinates, exactly, and nothing of the binding left.
assert bpy.ops.somicage.unbind() == {"FINISHED"}
assert np.array_equal(coordinates(hydrant), original), "unbind did not restore the original coordinates"
assert addon_binding.REST_ATTRIBUTE not in hydrant.data.attributes and "somicage_rest_matrix" not in hydrant
assert not binding.bound
print("blender add-on test: OK")
