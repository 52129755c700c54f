"""Small procedural meshes and what Blender shows of them, for the headless add-on tests (not a test itself)."""
import bmesh
import bpy
import numpy as np


def add_mesh(name, make):
    """A mesh object linked to the scene, its mesh made by make(bmesh)."""
    bm = bmesh.new()
    make(bm)
    mesh = bpy.data.meshes.new(name)
    bm.to_mesh(mesh)
    bm.free()
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    return obj


def ball(name="Ball", radius=0.5):
    return add_mesh(name, lambda bm: bmesh.ops.create_uvsphere(bm, u_segments=12, v_segments=6, radius=radius))


def local(mesh):
    """The mesh's vertex coordinates (local space), float64."""
    co = np.empty(len(mesh.vertices) * 3, dtype=np.float32)
    mesh.vertices.foreach_get("co", co)
    return co.reshape(-1, 3).astype(np.float64)


def shown(obj):
    """What Blender shows of the mesh (shape keys and all), in its local coordinates."""
    evaluated = obj.evaluated_get(bpy.context.evaluated_depsgraph_get())
    try:
        return local(evaluated.to_mesh())
    finally:
        evaluated.to_mesh_clear()
