"""SomiCage cage deformation for Blender: bind a mesh to a cage object, deform it live as the cage is edited or
animated, bake frames to shape keys, unbind to the original coordinates.

The engine is the `somicage` Python module (python/ in the SomiCage repository), built for the Python Blender runs
(Debian: /usr/bin/python3 3.11, the same ABI). The add-on finds it on sys.path, else in the folder named by the
SOMICAGE_PYTHON_PATH environment variable or by the add-on preference "somicage module folder" (build/python, or
a site-packages where it was pip-installed).

Coordinates are world space: the mesh's and the cage's object transforms at bind time define the rest pose; the
deformed points go back through the mesh's current transform. The rest coordinates are stored on the mesh (a
point attribute), with its rest transform and the cage's rest vertices (custom properties), so that the deformer
is made again after the file is saved and reopened, and unbind restores the original coordinates.
"""
import importlib
import os
import sys

import bpy
import numpy as np
from bpy.app.handlers import persistent

bl_info = {
    "name": "SomiCage cage deformation",
    "author": "SomiCage",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Sidebar > SomiCage",
    "description": "Cage deformation with Somigliana coordinates and the engine's other methods (somicage module)",
    "category": "Animation",
}

REST_ATTRIBUTE = "somicage_rest"  # the bound mesh's original vertex coordinates (local space)
# The binding's settings that are Deformer.deform keywords; the panel enables those the method reads
# (somicage.method_info(): "parameters"). nu_infinite goes with nu.
PARAMETER_PROPERTIES = (("nu", "nu_infinite"), ("gamma",), ("variant",), ("traction_fix",), ("corotational",),
                        ("bulging",), ("normals",))
VARIANTS = [("global", "Global", "One best-fit rotation for the whole cage (Fig. 4)"),
            ("local", "Local", "Per-face rotations blended to the vertices (Fig. 4)"),
            ("affine", "Affine", "Global with the best-fit affine map: reproduces any affine pose exactly"),
            ("stable", "Stable", "Local without the fold-overs local makes at high Poisson ratio")]
# The engine's choice parameters (somicage.choice_info(), core/deform_choices.h), default first; Blender needs the
# items when the class is defined, before the module may be found, so they are written out here (the add-on's test
# compares them with choice_info()).
BULGING = [("solid-angle", "Solid angle", "The paper's text: gamma times the change of the signed solid angle"),
           ("reference", "Reference", "The authors' code: gamma squared, unsigned solid angle (the paper's figures)"),
           ("swept-volume", "Swept volume", "gamma squared times the volume each face swept / the cage's volume")]
NORMALS = [("area", "Area", "Vertex normals and rotations weighted by face area (the paper's)"),
           ("angle", "Angle", "Weighted by corner angle: flat regions do not depend on their triangulation")]

_deformers = {}  # mesh object name -> (somicage.Deformer, cage object name); rebuilt after a file load
_methods = []  # somicage.method_info(), read once; it also keeps the method menu's strings alive for Blender
_method_items = []


# ---- the engine module ------------------------------------------------------------------------------------------
def somicage_module():
    """Imports somicage, adding the environment's or the preferences' folder to sys.path when needed."""
    try:
        return importlib.import_module("somicage")
    except ImportError:
        pass
    folders = [os.environ.get("SOMICAGE_PYTHON_PATH", "")]
    addon = bpy.context.preferences.addons.get(__name__)
    if addon is not None:
        folders.append(bpy.path.abspath(addon.preferences.module_path))
    for folder in filter(None, folders):
        if folder not in sys.path:
            sys.path.append(folder)
    try:
        return importlib.import_module("somicage")
    except ImportError as error:
        raise RuntimeError("SomiCage: the somicage Python module was not found; build it (cmake --build build) and "
                           "set Edit > Preferences > Add-ons > SomiCage > somicage module folder to build/python, "
                           f"or set SOMICAGE_PYTHON_PATH ({error})") from error


def engine_methods():
    """The engine's methods (somicage.method_info(): its registry, core/methods), or [] while the module is not
    found (binding then says how to find it)."""
    if not _methods:
        try:
            _methods.extend(somicage_module().method_info())
        except RuntimeError:
            return []
    return _methods


def method_items(_binding, _context):
    """The method menu: one item per engine method, numbered by its place in the engine's list (what a .blend file
    stores; a new method takes a new place at the end)."""
    if not _method_items:
        _method_items.extend((m["name"], m["display_name"], m["description"], k)
                             for k, m in enumerate(engine_methods()))
    return _method_items


def method_parameters(name):
    """The Deformer.deform keywords that method reads."""
    return next((set(m["parameters"]) for m in engine_methods() if m["name"] == name), set())


# ---- geometry between Blender and NumPy --------------------------------------------------------------------------
def local_coordinates(mesh):
    co = np.empty(len(mesh.vertices) * 3, dtype=np.float32)
    mesh.vertices.foreach_get("co", co)
    return co.reshape(-1, 3).astype(np.float64)


def to_world(matrix, points):
    """points (n, 3) through a 4 x 4 affine matrix (a mathutils.Matrix or 16 numbers, row by row)."""
    m = np.array(matrix, dtype=np.float64).reshape(4, 4)
    return points @ m[:3, :3].T + m[:3, 3]


def to_local(matrix, points):
    return to_world(np.linalg.inv(np.array(matrix, dtype=np.float64)), points)


def cage_triangles(mesh):
    mesh.calc_loop_triangles()
    triangles = np.empty(len(mesh.loop_triangles) * 3, dtype=np.int32)
    mesh.loop_triangles.foreach_get("vertices", triangles)
    return triangles.reshape(-1, 3)


def posed_cage(cage_object, depsgraph):
    """The cage's evaluated vertices in world space: edits, shape keys, modifiers and animation included."""
    evaluated = cage_object.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    try:
        return to_world(evaluated.matrix_world, local_coordinates(mesh))
    finally:
        evaluated.to_mesh_clear()


def rest_points(mesh_object):
    attribute = mesh_object.data.attributes.get(REST_ATTRIBUTE)
    co = np.empty(len(mesh_object.data.vertices) * 3, dtype=np.float32)
    attribute.data.foreach_get("vector", co)
    return co.reshape(-1, 3).astype(np.float64)


def write_coordinates(mesh, local):
    mesh.vertices.foreach_set("co", local.astype(np.float32).ravel())
    mesh.update()


# ---- binding ----------------------------------------------------------------------------------------------------
class SomicageBinding(bpy.types.PropertyGroup):
    cage: bpy.props.PointerProperty(name="Cage", type=bpy.types.Object,
                                    poll=lambda self, obj: obj.type == "MESH" and obj != self.id_data)
    method: bpy.props.EnumProperty(name="Method", items=method_items, update=lambda s, c: s.refresh(c))
    nu: bpy.props.FloatProperty(name="Poisson ratio", default=0.0, min=-0.99, max=0.49, update=lambda s, c: s.refresh(c))
    nu_infinite: bpy.props.BoolProperty(name="Infinite", description="The limit nu = inf", default=False,
                                        update=lambda s, c: s.refresh(c))
    gamma: bpy.props.FloatProperty(name="Bulging", default=0.0, min=0.0, max=10.0, update=lambda s, c: s.refresh(c))
    variant: bpy.props.EnumProperty(name="Variant", items=VARIANTS, default="global", update=lambda s, c: s.refresh(c))
    traction_fix: bpy.props.BoolProperty(name="Traction fix", description="Eq. 15", default=True,
                                         update=lambda s, c: s.refresh(c))
    corotational: bpy.props.BoolProperty(name="Corotational", description="Remove the cage's best-fit rotation "
                                         "before the linear-elastic solve", default=False,
                                         update=lambda s, c: s.refresh(c))
    bulging: bpy.props.EnumProperty(name="Bulging", items=BULGING, default="solid-angle",
                                    update=lambda s, c: s.refresh(c))
    normals: bpy.props.EnumProperty(name="Normals", items=NORMALS, default="area", update=lambda s, c: s.refresh(c))
    live: bpy.props.BoolProperty(name="Live", description="Re-deform when the cage changes or the frame changes",
                                 default=True, update=lambda s, c: s.refresh(c))
    bound: bpy.props.BoolProperty(name="Bound", default=False)
    bound_method: bpy.props.StringProperty()  # what the stored deformer was made with

    def deform_settings(self):
        return dict(nu=float("inf") if self.nu_infinite else self.nu, gamma=self.gamma, variant=self.variant,
                    traction_fix=self.traction_fix, corotational=self.corotational, bulging=self.bulging,
                    normals=self.normals)

    def refresh(self, context):
        owner = self.id_data
        if self.bound and self.live and owner is not None:
            if self.method != self.bound_method:
                _deformers.pop(owner.name, None)  # another method: precompute again
            deform(owner, context.evaluated_depsgraph_get())


def deformer_for(mesh_object):
    """The precomputed deformer, made again from the stored rest pose after a file load or a method change."""
    binding = mesh_object.somicage
    entry = _deformers.get(mesh_object.name)
    if entry is not None and entry[1] == binding.cage.name:
        return entry[0]
    somicage = somicage_module()
    cage_object = binding.cage
    rest_cage = np.array(mesh_object["somicage_cage_rest"], dtype=np.float64).reshape(-1, 3)
    cage = somicage.Cage(rest_cage, cage_triangles(cage_object.data))
    points = to_world(mesh_object["somicage_rest_matrix"], rest_points(mesh_object))
    wm = bpy.context.window_manager
    wm.progress_begin(0, 100)
    try:
        deformer = somicage.Deformer(cage, points, method=binding.method,
                                     progress=lambda fraction: wm.progress_update(100 * fraction))
    finally:
        wm.progress_end()
    binding.bound_method = binding.method
    _deformers[mesh_object.name] = (deformer, cage_object.name)
    return deformer


def deformed_local(mesh_object, depsgraph):
    binding = mesh_object.somicage
    moved = deformer_for(mesh_object).deform(posed_cage(binding.cage, depsgraph), **binding.deform_settings())
    return to_local(mesh_object.matrix_world, moved)


def deform(mesh_object, depsgraph):
    write_coordinates(mesh_object.data, deformed_local(mesh_object, depsgraph))


def bind(mesh_object, depsgraph):
    binding = mesh_object.somicage
    cage_object = binding.cage
    mesh = mesh_object.data
    if REST_ATTRIBUTE not in mesh.attributes:
        mesh.attributes.new(REST_ATTRIBUTE, "FLOAT_VECTOR", "POINT")
    mesh.attributes[REST_ATTRIBUTE].data.foreach_set("vector", local_coordinates(mesh).astype(np.float32).ravel())
    mesh_object["somicage_rest_matrix"] = np.array(mesh_object.matrix_world).ravel().tolist()
    mesh_object["somicage_cage_rest"] = posed_cage(cage_object, depsgraph).ravel().tolist()
    _deformers.pop(mesh_object.name, None)
    binding.bound = True
    deformer_for(mesh_object)  # precompute now, so that errors show at bind time
    deform(mesh_object, depsgraph)


def unbind(mesh_object):
    mesh = mesh_object.data
    if REST_ATTRIBUTE in mesh.attributes:
        write_coordinates(mesh, rest_points(mesh_object))
        mesh.attributes.remove(mesh.attributes[REST_ATTRIBUTE])
    for key in ("somicage_rest_matrix", "somicage_cage_rest"):
        if key in mesh_object:
            del mesh_object[key]
    _deformers.pop(mesh_object.name, None)
    mesh_object.somicage.bound = False


def bound_objects(scene):
    return [obj for obj in scene.objects if obj.type == "MESH" and obj.somicage.bound and obj.somicage.cage]


def deform_live(obj, depsgraph):
    """A handler's deform: a failure (a cage whose vertex count changed, say) is printed once and stops Live."""
    try:
        deform(obj, depsgraph)
    except Exception as error:  # noqa: BLE001 - a handler must not raise on every update
        print(f"SomiCage: {obj.name}: {error}; Live is now off")
        obj.somicage.live = False


@persistent
def on_depsgraph_update(scene, depsgraph):
    changed = {update.id.original.name for update in depsgraph.updates
               if isinstance(update.id, bpy.types.Object) and (update.is_updated_geometry or update.is_updated_transform)}
    for obj in bound_objects(scene):
        if obj.somicage.live and obj.somicage.cage.name in changed:
            deform_live(obj, depsgraph)


@persistent
def on_frame_change(scene, depsgraph):
    for obj in bound_objects(scene):
        if obj.somicage.live:
            deform_live(obj, depsgraph)


@persistent
def on_load(_):
    _deformers.clear()


# ---- operators and panel ----------------------------------------------------------------------------------------
def report_errors(operator, action):
    try:
        action()
    except Exception as error:  # somicage.InputError, a missing module: the message says what to do
        operator.report({"ERROR"}, str(error))
        return {"CANCELLED"}
    return {"FINISHED"}


class SOMICAGE_OT_bind(bpy.types.Operator):
    """Precompute the coordinates of this mesh's vertices in the cage and deform it with the cage"""
    bl_idname = "somicage.bind"
    bl_label = "Bind"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        obj = context.object
        return obj is not None and obj.type == "MESH" and obj.somicage.cage is not None and not obj.somicage.bound

    def execute(self, context):
        return report_errors(self, lambda: bind(context.object, context.evaluated_depsgraph_get()))


class SOMICAGE_OT_unbind(bpy.types.Operator):
    """Restore the mesh's original coordinates and forget the binding"""
    bl_idname = "somicage.unbind"
    bl_label = "Unbind"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        return context.object is not None and context.object.type == "MESH" and context.object.somicage.bound

    def execute(self, context):
        return report_errors(self, lambda: unbind(context.object))


class SOMICAGE_OT_bake(bpy.types.Operator):
    """Bake the deformation of each frame in the range to a shape key, keyed on at its frame only"""
    bl_idname = "somicage.bake"
    bl_label = "Bake to shape keys"
    bl_options = {"REGISTER", "UNDO"}

    frame_start: bpy.props.IntProperty(name="Start", default=1)
    frame_end: bpy.props.IntProperty(name="End", default=250)

    @classmethod
    def poll(cls, context):
        return SOMICAGE_OT_unbind.poll(context)

    def invoke(self, context, event):
        self.frame_start, self.frame_end = context.scene.frame_start, context.scene.frame_end
        return context.window_manager.invoke_props_dialog(self)

    def execute(self, context):
        return report_errors(self, lambda: bake(context.scene, context.object, self.frame_start, self.frame_end))


def bake(scene, mesh_object, frame_start, frame_end):
    """One shape key per frame ("SomiCage frame N", value 1 at N and 0 at N - 1 and N + 1) over the rest coordinates
    as the basis; live deformation is switched off, since the keys now carry the animation."""
    binding, mesh = mesh_object.somicage, mesh_object.data
    binding.live = False
    rest = rest_points(mesh_object)
    write_coordinates(mesh, rest)
    if mesh.shape_keys is None:
        mesh_object.shape_key_add(name="Basis", from_mix=False)
    current = scene.frame_current
    try:
        for frame in range(frame_start, frame_end + 1):
            scene.frame_set(frame)
            key = mesh_object.shape_key_add(name=f"SomiCage frame {frame}", from_mix=False)
            key.data.foreach_set("co", deformed_local(mesh_object, bpy.context.evaluated_depsgraph_get())
                                 .astype(np.float32).ravel())
            for at, value in ((frame - 1, 0.0), (frame, 1.0), (frame + 1, 0.0)):
                key.value = value
                key.keyframe_insert("value", frame=at)
    finally:
        scene.frame_set(current)


class SOMICAGE_PT_panel(bpy.types.Panel):
    bl_label = "SomiCage"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "SomiCage"

    @classmethod
    def poll(cls, context):
        return context.object is not None and context.object.type == "MESH"

    def draw(self, context):
        binding = context.object.somicage
        layout = self.layout
        layout.prop(binding, "cage")
        layout.prop(binding, "method")
        reads = method_parameters(binding.method)
        for properties in PARAMETER_PROPERTIES:
            row = layout.row()
            row.enabled = properties[0] in reads
            for name in properties:
                row.prop(binding, name)
        layout.prop(binding, "live")
        row = layout.row()
        row.operator(SOMICAGE_OT_bind.bl_idname)
        row.operator(SOMICAGE_OT_unbind.bl_idname)
        layout.operator(SOMICAGE_OT_bake.bl_idname)


class SomicagePreferences(bpy.types.AddonPreferences):
    bl_idname = __name__
    module_path: bpy.props.StringProperty(name="somicage module folder", subtype="DIR_PATH",
                                          description="The folder that contains the somicage package: SomiCage's "
                                                      "build/python, or the site-packages it was pip-installed into")

    def draw(self, context):
        self.layout.prop(self, "module_path")


CLASSES = (SomicageBinding, SOMICAGE_OT_bind, SOMICAGE_OT_unbind, SOMICAGE_OT_bake, SOMICAGE_PT_panel,
           SomicagePreferences)
HANDLERS = ((bpy.app.handlers.depsgraph_update_post, on_depsgraph_update),
            (bpy.app.handlers.frame_change_post, on_frame_change), (bpy.app.handlers.load_post, on_load))


def register():
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    bpy.types.Object.somicage = bpy.props.PointerProperty(type=SomicageBinding)
    for handlers, handler in HANDLERS:
        handlers.append(handler)


def unregister():
    for handlers, handler in HANDLERS:
        if handler in handlers:
            handlers.remove(handler)
    del bpy.types.Object.somicage
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
