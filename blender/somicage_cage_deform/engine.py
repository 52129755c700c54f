"""The engine, the somicage Python module: where the add-on finds it, its methods, and its messages in a Blender
user's words (the objects' names where the module names its arguments)."""
import contextlib
import importlib
import os
import sys
import warnings

import bpy

# The copy of the module that the add-on's zip carries (blender/CMakeLists.txt); absent in a source checkout.
BUNDLED = os.path.join(os.path.dirname(__file__), "bundled")
# How the module names what the add-on hands it: Cage(vertices, triangles) and Deformer(cage, points)
# (python/module.cpp, python/python_deformer.cpp).
CAGE_ARGUMENT, POINTS_ARGUMENT = "Cage(vertices, faces)", "points"
# The engine's hint for a cage it refuses runs the command line on a file; in Blender the object is at hand.
CAGE_HINT = ("a cage must be one closed surface as Blender shows it, modifiers included (in Edit Mode, Select > "
             "Select All by Trait finds non-manifold and loose parts)")

_methods = []  # somicage.method_info(), read once; it also keeps the method menu's strings alive for Blender
_method_items = []


def somicage_module():
    """Imports somicage: the copy bundled in the add-on first, then sys.path, then the folder named by the
    SOMICAGE_PYTHON_PATH environment variable or by the add-on preference."""
    if os.path.isdir(BUNDLED) and BUNDLED not in sys.path:
        sys.path.insert(0, BUNDLED)
    try:
        return importlib.import_module("somicage")
    except ImportError as error:
        first = error
    if BUNDLED in sys.path:  # a bundled module built for another Python: let the others be found
        sys.path.remove(BUNDLED)
    folders = [os.environ.get("SOMICAGE_PYTHON_PATH", "")]
    addon = bpy.context.preferences.addons.get(__package__)
    if addon is not None:
        folders.append(bpy.path.abspath(addon.preferences.module_path))
    for folder in filter(None, folders):
        if folder not in sys.path:
            sys.path.append(folder)
    try:
        return importlib.import_module("somicage")
    except ImportError as error:
        why = str(error) if str(error) == str(first) else f"{first}; {error}"
        raise RuntimeError(f"the somicage Python module was not found ({why}): install the add-on from "
                           "the zip that SomiCage's build makes (build/blender/somicage_cage_deform.zip, which "
                           "carries it), or set Edit > Preferences > Add-ons > SomiCage > somicage module folder "
                           "to SomiCage's build/python") from error


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


def method_options(name):
    """The Deformer keywords that method reads (somicage.method_info()'s options: phong's tets, tet_level)."""
    return next((set(m.get("options", [])) for m in engine_methods() if m["name"] == name), set())


@contextlib.contextmanager
def engine_warnings():
    """Collects the engine's warnings (somicage.SomiCageWarning, and any other) as messages instead of letting
    them go to the console, where an artist never sees them."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        messages = []
        yield messages
        messages.extend(str(w.message) for w in caught)


def in_blender_words(message, mesh_object, cage_object):
    """An engine message with the objects' names for the module's argument names, and without its "warning: "
    (the report's icon says it)."""
    mesh, cage = f"mesh '{mesh_object.name}'", f"cage '{cage_object.name}'"
    for kind in ("warning: ", "note: "):
        message = message.removeprefix(kind)
    for argument, name in ((POINTS_ARGUMENT, mesh), (CAGE_ARGUMENT, cage)):
        if message.startswith(argument + ": "):  # describeNotice's "source: text"
            message = name + message[len(argument):]
    # describeMeshPlacement's "the mesh MESH and the cage CAGE do not fit: ... are the two files in different units?"
    return (message.replace(f"mesh {POINTS_ARGUMENT} ", f"{mesh} ").replace(f"cage {CAGE_ARGUMENT}", cage)
            .replace("the two files", "the two objects"))


def error_message(error, what, mesh_object, cage_object):
    """An exception as one line: what failed (naming the objects), what is wrong and what to do."""
    problem = getattr(error, "problem", None)  # somicage.InputError's parts
    if problem is None:
        return f"{what}: {in_blender_words(str(error), mesh_object, cage_object)}"
    hint = CAGE_HINT if "somicage check" in error.hint else error.hint
    return f"{what}: {in_blender_words(problem, mesh_object, cage_object)}" + (f"; {hint}" if hint else "")
