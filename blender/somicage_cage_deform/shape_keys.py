"""The shape keys that Bake makes ("SomiCage frame N"): finding them, muting them while Live drives the mesh, and
removing them with their animation curves."""
import re

import bpy

KEY_NAME = "SomiCage frame {}"
# ".001": Blender's suffix for a name given twice (files baked twice by the add-on's first version have them).
_KEY_PATTERN = re.compile(r"SomiCage frame (-?\d+)(\.\d+)?")


def baked_keys(mesh_object):
    """{key name: frame} of the add-on's shape keys on the object."""
    keys = mesh_object.data.shape_keys
    if keys is None:
        return {}
    return {k.name: int(m.group(1)) for k in keys.key_blocks if (m := _KEY_PATTERN.fullmatch(k.name))}


def sync_mute(mesh_object):
    """Live and baked keys never both drive the mesh: the keys are muted while the binding is live."""
    binding = mesh_object.somicage
    muted = binding.bound and binding.live
    for name in baked_keys(mesh_object):
        mesh_object.data.shape_keys.key_blocks[name].mute = muted


def remove_keys(mesh_object, names):
    """Removes the named shape keys and their animation curves; then the shape keys altogether if only the
    reference key is left (a lone reference key changes nothing)."""
    shape_keys = mesh_object.data.shape_keys
    if shape_keys is None or not names:
        return
    action = shape_keys.animation_data.action if shape_keys.animation_data is not None else None
    for name in names:
        if action is not None:
            path = f'key_blocks["{bpy.utils.escape_identifier(name)}"].value'
            for curve in [c for c in action.fcurves if c.data_path == path]:
                action.fcurves.remove(curve)
        mesh_object.shape_key_remove(shape_keys.key_blocks[name])
    if action is not None and not action.fcurves:
        shape_keys.animation_data.action = None
        if action.users == 0:
            bpy.data.actions.remove(action)
    if len(shape_keys.key_blocks) == 1:
        mesh_object.shape_key_clear()
