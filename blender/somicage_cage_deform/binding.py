"""A mesh bound to a cage object: its settings, what the binding stores on the mesh, the precomputed deformers,
bind / deform / unbind, and the handlers that deform live.

Coordinates are world space: the mesh's and the cage's object transforms at bind time define the rest pose; the
deformed points go back through the mesh's current transform. The cage is what Blender shows (modifiers included),
with its own triangles. The binding stores on the mesh its rest coordinates (a point attribute), its rest transform
and the cage's rest vertices and triangles (custom properties), so that the deformer is made again after the file
is saved and reopened, and unbind restores the original coordinates.
"""
import uuid

import bpy
import numpy as np
from bpy.app.handlers import persistent

from . import engine, shape_keys
from .geometry import (base_coordinates, evaluated_cage, modifier_names, to_local, to_world,
                       write_base_coordinates)

REST_ATTRIBUTE = "somicage_rest"  # the bound mesh's original vertex coordinates (local space)
STORED = ("somicage_rest_matrix", "somicage_cage_rest", "somicage_cage_triangles")  # the object's custom properties
# The binding's settings that are Deformer.deform keywords; the panel enables those the method reads
# (somicage.method_info(): "parameters"). nu_infinite goes with nu.
# The binding's settings that are Deformer keywords (somicage.method_info(): "options"), read at bind: a change
# makes the deformer again. The tetrahedral mesh's detail of method phong (the CLI's --tet-level).
OPTION_PROPERTIES = ("tet_level",)
PARAMETER_PROPERTIES = (("nu", "nu_infinite"), ("gamma",), ("variant",), ("traction_fix",), ("corotational",),
                        ("bulging",), ("normals",))
VARIANTS = [("global", "Global", "One best-fit rotation for the whole cage (Fig. 4)"),
            ("local", "Local", "Per-face rotations blended to the vertices (Fig. 4)"),
            ("affine", "Affine", "Global with the best-fit affine map: reproduces any affine pose exactly"),
            ("stable", "Stable", "Local without the fold-overs local makes at high Poisson ratio")]
# The engine's choice parameters (somicage.choice_info(), core/deform/deform_choices.h), default first; Blender needs
# the items when the class is defined, before the module may be found, so they are written out here (the add-on's test
# compares them with choice_info()).
BULGING = [("solid-angle", "Solid angle", "The paper's text: gamma times the change of the signed solid angle"),
           ("reference", "Reference", "The authors' code: gamma squared, unsigned solid angle (the paper's figures)"),
           ("swept-volume", "Swept volume", "gamma squared times the volume each face swept / the cage's volume"),
           ("polygon", "Polygon", "Solid angle per flat polygon: coplanar neighbours share one stretch, whatever their split")]
NORMALS = [("area", "Area", "Vertex normals and rotations weighted by face area (the paper's)"),
           ("angle", "Angle", "Weighted by corner angle: flat regions do not depend on their triangulation")]

# (the binding's bind_id, method) -> somicage.Deformer. bind_id is stored with the binding, new at each bind: a
# rename keeps it (a name key would leak a deformer of hundreds of MB), and a duplicate of a bound object, which
# stores the same rest pose, shares the deformer. Entries no bound object uses are dropped (unbind, deletion, undo,
# another method: prune); a file load clears them all, since they are made again from what the mesh stores.
# (Blender 3.4 has no session_uid in Python.)
_deformers = {}


def _refresh(binding, context):
    binding.refresh(context)


def _live_changed(binding, context):
    shape_keys.sync_mute(binding.id_data)
    binding.refresh(context)


class SomicageBinding(bpy.types.PropertyGroup):
    cage: bpy.props.PointerProperty(name="Cage", type=bpy.types.Object,
                                    poll=lambda self, obj: obj.type == "MESH" and obj != self.id_data)
    method: bpy.props.EnumProperty(name="Method", items=engine.method_items, update=_refresh)
    nu: bpy.props.FloatProperty(name="Poisson ratio", default=0.0, min=-0.99, max=0.49, update=_refresh)
    nu_infinite: bpy.props.BoolProperty(name="Infinite", description="The limit nu = inf", default=False,
                                        update=_refresh)
    gamma: bpy.props.FloatProperty(name="Bulging", default=0.0, min=0.0, max=10.0, update=_refresh)
    variant: bpy.props.EnumProperty(name="Variant", items=VARIANTS, default="global", update=_refresh)
    traction_fix: bpy.props.BoolProperty(name="Traction fix", description="Eq. 15", default=True, update=_refresh)
    corotational: bpy.props.BoolProperty(name="Corotational", description="Remove the cage's best-fit rotation "
                                         "before the linear-elastic solve", default=False, update=_refresh)
    bulging: bpy.props.EnumProperty(name="Bulging", items=BULGING, default="solid-angle", update=_refresh)
    normals: bpy.props.EnumProperty(name="Normals", items=NORMALS, default="area", update=_refresh)
    tet_level: bpy.props.IntProperty(name="Tet level", description="Detail of the cage's tetrahedral mesh (Phong): "
                                     "0 TetGen, about the cage's vertices, to 4 CGAL Mesh_3, finer",
                                     default=1, min=0, max=4, update=_refresh)
    live: bpy.props.BoolProperty(name="Live", description="Re-deform when the cage changes or the frame changes; "
                                 "baked SomiCage shape keys are muted meanwhile", default=True, update=_live_changed)
    bound: bpy.props.BoolProperty(name="Bound", default=False)
    bind_id: bpy.props.StringProperty()  # new at each bind: with the method, the key of its deformer in _deformers
    messages: bpy.props.StringProperty()  # the engine's warnings at bind, or why Live stopped: shown in the panel

    def deform_settings(self):
        return dict(nu=float("inf") if self.nu_infinite else self.nu, gamma=self.gamma, variant=self.variant,
                    traction_fix=self.traction_fix, corotational=self.corotational, bulging=self.bulging,
                    normals=self.normals)

    def refresh(self, context):
        owner = self.id_data
        if self.bound and self.live and owner is not None and self.cage is not None:
            deform_live(owner, context.evaluated_depsgraph_get())


def binding_name(mesh_object):
    """'hydrant' to cage 'cage' (as its modifier Mirror makes it): the objects a message is about."""
    cage = mesh_object.somicage.cage
    modifiers = modifier_names(cage) if cage is not None else []
    made = (f" (as its modifier {modifiers[0]} makes it)" if len(modifiers) == 1 else
            f" (as its modifiers {', '.join(modifiers)} make it)" if modifiers else "")
    return f"'{mesh_object.name}' to cage '{cage.name if cage is not None else ''}'{made}"


def deformer_options(binding):
    """The binding's Deformer keywords its method reads (OPTION_PROPERTIES)."""
    reads = engine.method_options(binding.method)
    return {name: getattr(binding, name) for name in OPTION_PROPERTIES if name in reads}


def make_deformer(cage_vertices, cage_triangles, points, method, options=None):
    somicage = engine.somicage_module()
    wm = bpy.context.window_manager
    wm.progress_begin(0, 100)
    try:
        return somicage.Deformer(somicage.Cage(cage_vertices, cage_triangles), points, method=method,
                                 progress=lambda fraction: wm.progress_update(100 * fraction), **(options or {}))
    finally:
        wm.progress_end()


def cache_key(binding):
    return (binding.bind_id, binding.method, *sorted(deformer_options(binding).items()))


def rest_points(mesh_object):
    attribute = mesh_object.data.attributes.get(REST_ATTRIBUTE)
    co = np.empty(len(mesh_object.data.vertices) * 3, dtype=np.float32)
    attribute.data.foreach_get("vector", co)
    return co.reshape(-1, 3).astype(np.float64)


def deformer_for(mesh_object):
    """The precomputed deformer, made again from what the mesh stores after a file load or a method change (its
    warnings were reported at bind and are in the panel)."""
    binding = mesh_object.somicage
    deformer = _deformers.get(cache_key(binding))
    if deformer is not None:
        return deformer
    if any(key not in mesh_object for key in STORED):
        raise RuntimeError("the binding lacks what this version of the add-on stores (the cage's triangles): "
                           "Unbind and Bind again")
    prune()  # another method's deformer first, before a second one takes its memory
    cage_vertices = np.array(mesh_object["somicage_cage_rest"], dtype=np.float64).reshape(-1, 3)
    cage_triangles = np.array(mesh_object["somicage_cage_triangles"], dtype=np.int64).reshape(-1, 3)
    points = to_world(mesh_object["somicage_rest_matrix"], rest_points(mesh_object))
    with engine.engine_warnings():
        deformer = make_deformer(cage_vertices, cage_triangles, points, binding.method, deformer_options(binding))
    _deformers[cache_key(binding)] = deformer
    return deformer


def deformed_local(mesh_object, depsgraph):
    binding = mesh_object.somicage
    moved = deformer_for(mesh_object).deform(evaluated_cage(binding.cage, depsgraph), **binding.deform_settings())
    return to_local(mesh_object.matrix_world, moved)


def deform(mesh_object, depsgraph):
    write_base_coordinates(mesh_object.data, deformed_local(mesh_object, depsgraph))


def bind(mesh_object, depsgraph):
    """Precomputes, and only once that has succeeded stores the binding on the object. Returns the engine's
    warnings (points outside the cage, a mesh in other units, a repaired cage) naming the objects."""
    binding, mesh = mesh_object.somicage, mesh_object.data
    cage_vertices, cage_triangles = evaluated_cage(binding.cage, depsgraph, with_triangles=True)
    rest_local, rest_matrix = base_coordinates(mesh), np.array(mesh_object.matrix_world, dtype=np.float64)
    # The deformer sees the rest coordinates as the mesh stores them (float32), so that the one made again after a
    # file load is the same.
    rest_local = rest_local.astype(np.float32)
    with engine.engine_warnings() as messages:
        deformer = make_deformer(cage_vertices, cage_triangles, to_world(rest_matrix, rest_local.astype(np.float64)),
                                 binding.method, deformer_options(binding))
    warnings = [engine.in_blender_words(m, mesh_object, binding.cage) for m in messages]
    # Nothing can fail from here on.
    if REST_ATTRIBUTE not in mesh.attributes:
        mesh.attributes.new(REST_ATTRIBUTE, "FLOAT_VECTOR", "POINT")
    mesh.attributes[REST_ATTRIBUTE].data.foreach_set("vector", rest_local.ravel())
    mesh_object["somicage_rest_matrix"] = rest_matrix.ravel().tolist()
    mesh_object["somicage_cage_rest"] = cage_vertices.ravel().tolist()
    mesh_object["somicage_cage_triangles"] = cage_triangles.ravel().tolist()
    binding.bind_id = uuid.uuid4().hex
    binding.messages = "\n".join(warnings)
    binding.bound = True
    _deformers[cache_key(binding)] = deformer
    shape_keys.sync_mute(mesh_object)
    return warnings


def unbind(mesh_object, remove_keys):
    """Restores the original coordinates and forgets the binding; remove_keys: also the shape keys Bake made."""
    mesh = mesh_object.data
    if remove_keys:
        shape_keys.remove_keys(mesh_object, list(shape_keys.baked_keys(mesh_object)))
    if REST_ATTRIBUTE in mesh.attributes:
        write_base_coordinates(mesh, rest_points(mesh_object))
        mesh.attributes.remove(mesh.attributes[REST_ATTRIBUTE])
    for key in STORED:
        if key in mesh_object:
            del mesh_object[key]
    binding = mesh_object.somicage
    binding.bound, binding.bind_id, binding.messages = False, "", ""
    prune()
    shape_keys.sync_mute(mesh_object)  # kept keys drive the mesh again


def bound_objects(scene):
    return [obj for obj in scene.objects if obj.type == "MESH" and obj.somicage.bound and obj.somicage.cage]


def prune():
    """Drops the deformers no bound object uses (deleted, undone, unbound, bound with another method)."""
    used = {cache_key(obj.somicage) for obj in bpy.data.objects if obj.type == "MESH" and obj.somicage.bound}
    for key in [key for key in _deformers if key not in used]:
        del _deformers[key]


def deform_live(obj, depsgraph):
    """A handler's deform: a failure (a cage whose vertex count changed, say) stops Live, and the panel says why."""
    try:
        deform(obj, depsgraph)
    except Exception as error:  # noqa: BLE001 - a handler must not raise on every update
        binding = obj.somicage
        binding.messages = engine.error_message(error, f"Live stopped for {binding_name(obj)}", obj, binding.cage)
        print(f"SomiCage: {binding.messages}")
        binding.live = False


@persistent
def on_depsgraph_update(scene, depsgraph):
    if _deformers:
        prune()
    changed = {update.id.original.name for update in depsgraph.updates if isinstance(update.id, bpy.types.Object)
               and (update.is_updated_geometry or update.is_updated_transform)}
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


HANDLERS = ((bpy.app.handlers.depsgraph_update_post, on_depsgraph_update),
            (bpy.app.handlers.frame_change_post, on_frame_change), (bpy.app.handlers.load_post, on_load))
