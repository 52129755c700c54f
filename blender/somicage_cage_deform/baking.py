"""Baking the deformation of a frame range to shape keys: one key per frame, keyed on at its frame only."""
import bpy
import numpy as np

from . import binding, shape_keys
from .geometry import write_base_coordinates


def deformed_frames(scene, mesh_object, frames):
    """{frame: the mesh's deformed local coordinates}; the scene is back at its frame afterwards."""
    current, result = scene.frame_current, {}
    try:
        for frame in frames:
            scene.frame_set(frame)
            result[frame] = binding.deformed_local(mesh_object, bpy.context.evaluated_depsgraph_get())
    finally:
        scene.frame_set(current)
    return result


def bake(scene, mesh_object, frame_start, frame_end):
    """One shape key per frame ("SomiCage frame N": value 1 at N, 0 at N - 1 and N + 1) over the rest coordinates
    as the basis. Every frame is deformed before anything changes; then the range's earlier keys are replaced (two
    keys of one frame would add their displacements) and Live is switched off (the keys carry the animation)."""
    if frame_end < frame_start:
        raise ValueError(f"the frame range {frame_start}..{frame_end} is empty: End must not be before Start")
    settings = mesh_object.somicage
    was_live, settings.live = settings.live, False  # Live would deform each frame a second time
    try:
        frames = deformed_frames(scene, mesh_object, range(frame_start, frame_end + 1))
    except BaseException:
        settings.live = was_live  # as it was, at the scene's frame again: nothing baked
        raise

    shape_keys.remove_keys(mesh_object, [name for name, frame in shape_keys.baked_keys(mesh_object).items()
                                         if frame_start <= frame <= frame_end])
    write_base_coordinates(mesh_object.data, binding.rest_points(mesh_object))
    if mesh_object.data.shape_keys is None:
        mesh_object.shape_key_add(name="Basis", from_mix=False)
    for frame, local in frames.items():
        key = mesh_object.shape_key_add(name=shape_keys.KEY_NAME.format(frame), from_mix=False)
        key.data.foreach_set("co", local.astype(np.float32).ravel())
        for at, value in ((frame - 1, 0.0), (frame, 1.0), (frame + 1, 0.0)):
            key.value = value
            key.keyframe_insert("value", frame=at)
