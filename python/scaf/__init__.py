"""scaf: bijective UV maps with SCAF, from Python.

A thin ctypes binding of the C library libscaf.so (no compiled extension:
every computation happens in C). numpy is optional: with it, inputs are
any array-likes of float/int dtype and outputs are numpy arrays; without
it, inputs and outputs are nested lists (one list per row).

    import scaf
    V, F, UV, FT = scaf.read_obj("cube.obj")      # or your own arrays
    r = scaf.atlas(V, F, UV, FT, resolution=1024, padding_texels=4)
    r.uv, r.ft, r.chart, r.efficiency, r.min_gap   # UVs in [0,1]^2
    p = scaf.param(V, F, iterations=20, progress=lambda i: print(i.energy))

One-call functions: param, atlas; in 3D inflate, untangle, flow,
tet_mesh, check_surface, check_tets (scaf/volume.h); split_seams turns a per-corner UV map
into one vertex per UV (vmapping, indices, uvs) for glTF or trimesh. Handles mirroring the C contexts
(context managers that free the C object on exit): Param, Atlas, and
Drag (interactive: handles pulled by SCAF iterations, undo, certified
output).
Exceptions: Error and its subclasses UsageError (also a ValueError),
InputError, MeshError, NumericError, OutOfMemory, Cancelled,
InternalError. The library is found through SCAF_LIBRARY, the install
layout, the build tree or the system (see scaf._lib); library_path says
which file was loaded, __version__ is the C library's version.
"""

from ._errors import (Cancelled, Error, InputError, InternalError, MeshError, NumericError,
                      OutOfMemory, UsageError)
from ._core import (Atlas, AtlasIterationInfo, AtlasResult, IterationInfo, Param, ParamResult,
                    __version__, atlas, default_atlas_options, default_options, library_path,
                    area_matched_energy, param, set_threads, set_deterministic)
from ._drag import Drag, DragChartInfo, DragOutput, default_drag_options
from . import _lib
from .obj import read_obj
from .seam_split import split_seams
from ._volume import (FlowResult, InflateResult, SurfaceReport, TetsReport, UntangleResult,
                      VolumeStepInfo, check_surface, check_tets, flow, inflate, tet_mesh,
                      untangle)

ENERGIES = tuple(_lib.ENERGIES)  # names accepted for energy= (or the C int), read from the library
INITS = tuple(_lib.INITS)  # names accepted for init= (or the C int)

__all__ = [
    "param", "atlas", "Param", "Atlas", "ParamResult", "AtlasResult", "IterationInfo",
    "AtlasIterationInfo", "default_options", "default_atlas_options", "read_obj", "Error",
    "UsageError", "InputError", "MeshError", "NumericError", "OutOfMemory", "Cancelled",
    "InternalError", "library_path", "__version__", "ENERGIES", "INITS", "set_threads",
    "set_deterministic", "Drag", "DragChartInfo", "DragOutput", "default_drag_options",
    "split_seams", "area_matched_energy", "inflate", "untangle", "flow", "tet_mesh", "check_surface", "check_tets",
    "InflateResult", "UntangleResult", "FlowResult", "SurfaceReport", "TetsReport",
    "VolumeStepInfo",
]

# Show the public names as scaf.X (in tracebacks and reprs), not scaf._core.X.
for _name in __all__:
    _obj = globals()[_name]
    if isinstance(_obj, type):
        _obj.__module__ = __name__
del _name, _obj
