"""Cage deformation with Somigliana, Green and mean value coordinates (SomiCage's engine).

    cage = somicage.Cage.from_obj("rest.obj")
    deformer = somicage.Deformer(cage, points, method="somigliana")
    moved = deformer.deform(somicage.load_posed("posed.obj", cage), nu=0.3, variant="local")
"""
from ._somicage import (Cage, Cancelled, Deformer, InputError, SomiCageWarning, __version__, check, choice_info,
                        cpu_kernels, load_mesh, load_posed, load_session, method_info, methods, parameter_ranges,
                        parameter_schema, save_obj)

__all__ = ["Cage", "Cancelled", "Deformer", "InputError", "SomiCageWarning", "__version__", "check", "choice_info",
           "cpu_kernels", "load_mesh", "load_posed", "load_session", "method_info", "methods", "parameter_ranges",
           "parameter_schema", "save_obj"]
