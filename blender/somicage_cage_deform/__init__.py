# SPDX-License-Identifier: GPL-3.0-or-later
"""SomiCage cage deformation for Blender: bind a mesh to a cage object, deform it live as the cage is edited or
animated, bake frames to shape keys, unbind to the original coordinates.

The engine is the `somicage` Python module (python/ in the SomiCage repository), built for the Python Blender runs
(Debian: /usr/bin/python3 3.11, the same ABI). The zip that SomiCage's build makes (build/blender/
somicage_cage_deform.zip) carries it in bundled/; without it, the add-on finds the module on sys.path, else in the
folder named by the SOMICAGE_PYTHON_PATH environment variable or by the add-on preference "somicage module folder"
(engine.py). binding.py binds, deforms and unbinds; baking.py and shape_keys.py make and remove the baked shape
keys; ui.py holds the operators and the panel.
"""
import bpy

from . import binding, ui

bl_info = {
    "name": "SomiCage cage deformation",
    "author": "SomiCage",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Sidebar > SomiCage",
    "description": "Cage deformation with Somigliana coordinates and the engine's other methods (somicage module)",
    "category": "Animation",
    "license": "SPDX:GPL-3.0-or-later",  # Blender 3.4 ignores it; the notation of Blender's extension manifests
}

CLASSES = (binding.SomicageBinding,) + ui.CLASSES


def register():
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    bpy.types.Object.somicage = bpy.props.PointerProperty(type=binding.SomicageBinding)
    for handlers, handler in binding.HANDLERS:
        handlers.append(handler)


def unregister():
    for handlers, handler in binding.HANDLERS:
        if handler in handlers:
            handlers.remove(handler)
    del bpy.types.Object.somicage
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
