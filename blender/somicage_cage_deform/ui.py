"""The operators (Bind, Unbind, Bake), the sidebar panel and the add-on's preferences. An operator that fails
reports an error naming the objects and leaves them as they were; the engine's warnings are reported and shown in
the panel."""
import textwrap

import bpy

from . import baking, binding, engine, shape_keys

PANEL_WRAP = 60  # characters per line of a message in the panel (Blender's labels do not wrap)


def is_mesh(context):
    return context.object is not None and context.object.type == "MESH"


def run(operator, context, what, action):
    """action(); an exception becomes an error report that says what failed ("cannot bind 'a' to cage 'b'")."""
    obj = context.object
    try:
        action()
    except Exception as error:  # somicage.InputError, a missing module: the message says what to do
        operator.report({"ERROR"}, engine.error_message(error, what, obj, obj.somicage.cage))
        return {"CANCELLED"}
    return {"FINISHED"}


class SOMICAGE_OT_bind(bpy.types.Operator):
    """Precompute the coordinates of this mesh's vertices in the cage and deform it with the cage"""
    bl_idname = "somicage.bind"
    bl_label = "Bind"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        return is_mesh(context) and context.object.somicage.cage is not None and not context.object.somicage.bound

    def execute(self, context):
        obj = context.object
        warnings = []
        result = run(self, context, f"cannot bind {binding.binding_name(obj)}",
                     lambda: warnings.extend(binding.bind(obj, context.evaluated_depsgraph_get())))
        for message in warnings:
            self.report({"WARNING"}, message)
        return result


class SOMICAGE_OT_unbind(bpy.types.Operator):
    """Restore the mesh's original coordinates and forget the binding"""
    bl_idname = "somicage.unbind"
    bl_label = "Unbind"
    bl_options = {"REGISTER", "UNDO"}

    remove_keys: bpy.props.BoolProperty(name="Remove baked shape keys", default=True,
                                        description="Also remove the SomiCage frame shape keys that Bake made (kept, "
                                                    "they go on animating the mesh)")

    @classmethod
    def poll(cls, context):
        return is_mesh(context) and context.object.somicage.bound

    def invoke(self, context, event):
        if shape_keys.baked_keys(context.object):  # ask: keep the baked animation or not
            return context.window_manager.invoke_props_dialog(self)
        return self.execute(context)

    def execute(self, context):
        obj = context.object
        return run(self, context, f"cannot unbind '{obj.name}'", lambda: binding.unbind(obj, self.remove_keys))


class SOMICAGE_OT_bake(bpy.types.Operator):
    """Bake the deformation of each frame in the range to a shape key, keyed on at its frame only (replacing the
    range's earlier SomiCage keys; Live goes off)"""
    bl_idname = "somicage.bake"
    bl_label = "Bake to shape keys"
    bl_options = {"REGISTER", "UNDO"}

    frame_start: bpy.props.IntProperty(name="Start", default=1)
    frame_end: bpy.props.IntProperty(name="End", default=250)

    @classmethod
    def poll(cls, context):
        return SOMICAGE_OT_unbind.poll(context) and context.object.somicage.cage is not None

    def invoke(self, context, event):
        self.frame_start, self.frame_end = context.scene.frame_start, context.scene.frame_end
        return context.window_manager.invoke_props_dialog(self)

    def execute(self, context):
        obj = context.object
        return run(self, context, f"cannot bake {binding.binding_name(obj)}",
                   lambda: baking.bake(context.scene, obj, self.frame_start, self.frame_end))


class SOMICAGE_PT_panel(bpy.types.Panel):
    bl_label = "SomiCage"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "SomiCage"

    @classmethod
    def poll(cls, context):
        return is_mesh(context)

    def draw(self, context):
        settings = context.object.somicage
        layout = self.layout
        row = layout.row()
        row.enabled = not settings.bound  # the stored rest pose belongs to the bound cage
        row.prop(settings, "cage")
        layout.prop(settings, "method")
        reads = engine.method_parameters(settings.method)
        for properties in binding.PARAMETER_PROPERTIES:
            row = layout.row()
            row.enabled = properties[0] in reads
            for name in properties:
                row.prop(settings, name)
        options = engine.method_options(settings.method)
        for name in binding.OPTION_PROPERTIES:  # read at bind (and when changed: the deformer is made again)
            row = layout.row()
            row.enabled = name in options
            row.prop(settings, name)
        layout.prop(settings, "live")
        row = layout.row()
        row.operator(SOMICAGE_OT_bind.bl_idname)
        row.operator(SOMICAGE_OT_unbind.bl_idname)
        layout.operator(SOMICAGE_OT_bake.bl_idname)
        if settings.messages:
            column = layout.box().column(align=True)
            for message in settings.messages.splitlines():
                for k, line in enumerate(textwrap.wrap(message, PANEL_WRAP)):
                    column.label(text=line, icon="ERROR" if k == 0 else "BLANK1")


class SomicagePreferences(bpy.types.AddonPreferences):
    bl_idname = __package__
    module_path: bpy.props.StringProperty(name="somicage module folder", subtype="DIR_PATH",
                                          description="Only for an add-on installed without its zip: the folder "
                                                      "that contains the somicage package (SomiCage's build/python, "
                                                      "or the site-packages it was pip-installed into)")

    def draw(self, context):
        self.layout.prop(self, "module_path")


CLASSES = (SOMICAGE_OT_bind, SOMICAGE_OT_unbind, SOMICAGE_OT_bake, SOMICAGE_PT_panel, SomicagePreferences)
