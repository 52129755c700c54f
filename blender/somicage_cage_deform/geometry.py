"""Geometry between Blender and NumPy: coordinates in float64, world space through 4 x 4 matrices, the cage as its
modifiers make it."""
import numpy as np


def local_coordinates(mesh):
    co = np.empty(len(mesh.vertices) * 3, dtype=np.float32)
    mesh.vertices.foreach_get("co", co)
    return co.reshape(-1, 3).astype(np.float64)


def base_coordinates(mesh):
    """What the mesh shows before its shape keys: the reference key's coordinates when it has shape keys (Blender
    then ignores the vertices' own), else the vertices'."""
    if mesh.shape_keys is None:
        return local_coordinates(mesh)
    co = np.empty(len(mesh.vertices) * 3, dtype=np.float32)
    mesh.shape_keys.reference_key.data.foreach_get("co", co)
    return co.reshape(-1, 3).astype(np.float64)


def write_base_coordinates(mesh, local):
    """Sets the coordinates shape keys are relative to: the vertices' and, when there are shape keys, the reference
    key's (what Blender shows; writing the vertices alone would change nothing on screen)."""
    co = local.astype(np.float32).ravel()
    mesh.vertices.foreach_set("co", co)
    if mesh.shape_keys is not None:
        mesh.shape_keys.reference_key.data.foreach_set("co", co)
    mesh.update()


def to_world(matrix, points):
    """points (n, 3) through a 4 x 4 affine matrix (a mathutils.Matrix or 16 numbers, row by row)."""
    m = np.array(matrix, dtype=np.float64).reshape(4, 4)
    return points @ m[:3, :3].T + m[:3, 3]


def to_local(matrix, points):
    return to_world(np.linalg.inv(np.array(matrix, dtype=np.float64).reshape(4, 4)), points)


def triangles(mesh):
    mesh.calc_loop_triangles()
    result = np.empty(len(mesh.loop_triangles) * 3, dtype=np.int64)
    mesh.loop_triangles.foreach_get("vertices", result)
    return result.reshape(-1, 3)


def evaluated_cage(cage_object, depsgraph, with_triangles=False):
    """The cage as Blender shows it, in world space: edits, shape keys, modifiers and animation included. Its
    vertices, and with_triangles its own triangles (a Subdivision or Mirror modifier makes new vertices and faces:
    both must come from the same mesh)."""
    evaluated = cage_object.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    try:
        vertices = to_world(evaluated.matrix_world, local_coordinates(mesh))
        return (vertices, triangles(mesh)) if with_triangles else vertices
    finally:
        evaluated.to_mesh_clear()


def modifier_names(obj):
    """The modifiers that change what the object shows (enabled in the viewport), in stack order."""
    return [m.name for m in obj.modifiers if m.show_viewport]
