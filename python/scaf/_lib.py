"""scaf._lib: finds libscaf.so and declares the C API to ctypes.

Nothing here computes anything: it loads the shared library, mirrors the
structs of include/scaf/scaf.h, atlas.h, drag.h and volume.h field by field
(same order, same C types; a test compares every ctypes.sizeof and field
offset with the C compiler's), and declares argtypes/restype of every
function the package calls.

Where the library is looked for, first hit wins:
  1. the environment variable SCAF_LIBRARY (a path to libscaf.so*);
  2. the installed layout: the lib directory CMake recorded in
     _install_paths.py when it installed this package next to libscaf;
  3. the build tree of a source checkout: <checkout>/build/libscaf.so
     (this package lives in <checkout>/python/scaf);
  4. ctypes.util.find_library("scaf") (ldconfig, LD_LIBRARY_PATH).
When none loads, ImportError lists every place tried and why it failed.
"""

import ctypes
import ctypes.util
import os

# --- enums (C enums are int-sized here; values as in the headers) ---------

STATUS_NAMES = {
    0: "OK",
    1: "USAGE",
    2: "IO",
    3: "PARSE",
    4: "MESH",
    5: "NUMERIC",
    6: "NOMEM",
    7: "CANCELLED",
    8: "INTERNAL",
}
SCAF_OK = 0
SCAF_ERR_CANCELLED = 7

# Names accepted for the `energy` and `init` options. Any other int is
# passed through to C, which validates it, so a value appended to the C
# enum later (a new init, say) works before this table knows its name.
# ENERGIES (identifier: value) is read from the library when it loads
# (scaf_energy_count / scaf_energy_info), not written here.
ENERGIES = {}
INITS = {"tutte": 0, "harmonic": 1, "mvc": 2}
SOLVERS = {"auto": 0, "slim": 1, "newton": 2}
PHASES = ("assembly", "analysis", "factorization", "solve", "line_search", "scaffold", "other")
PHASE_COUNT = len(PHASES)  # SCAF_PHASE_COUNT
ATLAS_PHASES = ("settle", "compact")  # SCAF_ATLAS_SETTLE, SCAF_ATLAS_COMPACT
DRAG_STARTS = {"layout": 0, "input": 1, "atlas": 2}  # scaf_drag_start
SEAMS = {"default": 0, "input": 1, "auto": 2, "extend": 3}  # scaf_seams

c_enum = ctypes.c_int


class EnergyInfo(ctypes.Structure):
    """scaf_energy_info_t"""

    _fields_ = [
        ("name", ctypes.c_char_p),
        ("aliases", ctypes.c_char_p),
        ("help", ctypes.c_char_p),
        ("scale_offset", ctypes.c_double),
    ]


class Options(ctypes.Structure):
    """scaf_options_t"""

    _fields_ = [
        ("struct_size", ctypes.c_size_t),  # set by the C _default() function
        ("energy", c_enum),
        ("init", c_enum),
        ("max_iterations", ctypes.c_int),
        ("tolerance", ctypes.c_double),
        ("box_scale", ctypes.c_double),
        ("box_square", ctypes.c_int),
        ("box_points_per_side", ctypes.c_int),
        ("lambda_ratio", ctypes.c_double),
        ("min_angle_deg", ctypes.c_double),
        ("step_fraction", ctypes.c_double),
        ("solver", c_enum),
        ("seams", c_enum),
    ]


class IterationInfo(ctypes.Structure):
    """scaf_iteration_info_t"""

    _fields_ = [
        ("iteration", ctypes.c_int),
        ("energy", ctypes.c_double),
        ("energy_before", ctypes.c_double),
        ("total_before", ctypes.c_double),
        ("total_after", ctypes.c_double),
        ("lambda_", ctypes.c_double),  # `lambda` in C
        ("step", ctypes.c_double),
        ("scaffold_triangles", ctypes.c_int),
        ("scaffold_vertices", ctypes.c_int),
        ("seconds", ctypes.c_double),
        ("phase_seconds", ctypes.c_double * PHASE_COUNT),
        ("solver", c_enum),
        ("decrement", ctypes.c_double),
        ("criterion", ctypes.c_double),
    ]


class AtlasOptions(ctypes.Structure):
    """scaf_atlas_options_t"""

    _fields_ = [
        ("struct_size", ctypes.c_size_t),  # set by the C _default() function
        ("padding", ctypes.c_double),
        ("energy", c_enum),
        ("init", c_enum),
        ("init_input", ctypes.c_int),
        ("settle_iterations", ctypes.c_int),
        ("settle_tolerance", ctypes.c_double),
        ("compact_iterations", ctypes.c_int),
        ("distortion_tolerance", ctypes.c_double),
        ("repack", ctypes.c_int),
        ("pack_cells", ctypes.c_int),
        ("box_scale", ctypes.c_double),
        ("lambda_ratio", ctypes.c_double),
        ("compact_lambda_ratio", ctypes.c_double),
        ("seams", c_enum),
    ]


class AtlasIterationInfo(ctypes.Structure):
    """scaf_atlas_iteration_info_t"""

    _fields_ = [
        ("phase", c_enum),
        ("iteration", ctypes.c_int),
        ("phase_iteration", ctypes.c_int),
        ("energy", ctypes.c_double),
        ("efficiency", ctypes.c_double),
        ("gap", ctypes.c_double),
        ("seconds", ctypes.c_double),
        ("loop", IterationInfo),
    ]


class DragOptions(ctypes.Structure):
    """scaf_drag_options_t"""

    _fields_ = [
        ("struct_size", ctypes.c_size_t),  # set by the C _default() function
        ("start", c_enum),
        ("padding", ctypes.c_double),
        ("weight_ratio", ctypes.c_double),
        ("solver", c_enum),
        ("box_scale", ctypes.c_double),
        ("lambda_ratio", ctypes.c_double),
        ("undo_depth", ctypes.c_int),
        ("seams", c_enum),
    ]


class DragChartInfo(ctypes.Structure):
    """scaf_drag_chart_info_t"""

    _fields_ = [
        ("faces", ctypes.c_int),
        ("uvs", ctypes.c_int),
        ("centroid", ctypes.c_double * 2),
        ("uv_area", ctypes.c_double),
        ("energy", ctypes.c_double),
        ("held", ctypes.c_int),
    ]


DRAG_FLIPS = {None: 0, "u": 1, "v": 2}  # scaf_drag_flip


class DragMotion(ctypes.Structure):
    """scaf_drag_motion_t"""

    _fields_ = [
        ("dx", ctypes.c_double),
        ("dy", ctypes.c_double),
        ("angle", ctypes.c_double),
        ("factor", ctypes.c_double),
        ("flip", c_enum),
        ("remirror", ctypes.c_int),
        ("has_pivot", ctypes.c_int),
        ("pivot", ctypes.c_double * 2),
    ]


# --- scaf/volume.h ------------------------------------------------------------

VOLUME_PHASES = ("flow_step", "iteration")  # scaf_volume_phase
SOLVER_NEWTON_OR_SLIM = {"newton": 2, "slim": 1}  # what scaf_inflate accepts
REPORT_MESSAGE_MAX = 512  # SCAF_REPORT_MESSAGE_MAX
SURFACE_FIRST_PAIRS = 16  # SCAF_SURFACE_FIRST_PAIRS
_size_t = ctypes.c_size_t


class InflateOptions(ctypes.Structure):
    """scaf_inflate_options_t"""

    _fields_ = [
        ("struct_size", _size_t),
        ("scale", ctypes.c_double),
        ("iterations", ctypes.c_int),
        ("box_scale", ctypes.c_double),
        ("solver", c_enum),
    ]


class UntangleOptions(ctypes.Structure):
    """scaf_untangle_options_t"""

    _fields_ = [
        ("struct_size", _size_t),
        ("delta", ctypes.c_double),
        ("flow_steps", ctypes.c_int),
        ("iterations", ctypes.c_int),
        ("tolerance", ctypes.c_double),
        ("anchor", ctypes.c_double),
        ("verify", ctypes.c_int),
    ]


class FlowOptions(ctypes.Structure):
    """scaf_flow_options_t"""

    _fields_ = [
        ("struct_size", _size_t),
        ("steps", ctypes.c_int),
        ("delta", ctypes.c_double),
        ("until_free", ctypes.c_int),
    ]


class VolumeStepInfo(ctypes.Structure):
    """scaf_volume_step_info_t"""

    _fields_ = [
        ("phase", c_enum),
        ("step", ctypes.c_int),
        ("seconds", ctypes.c_double),
        ("check_seconds", ctypes.c_double),
        ("defects", ctypes.c_longlong),
        ("pairs", ctypes.c_longlong),
        ("degenerate_faces", ctypes.c_int),
        ("energy", ctypes.c_double),
        ("arap", ctypes.c_double),
        ("step_length", ctypes.c_double),
        ("rms", ctypes.c_double),
        ("max", ctypes.c_double),
        ("tets", ctypes.c_int),
        ("scaffold_vertices", ctypes.c_int),
        ("quality_min", ctypes.c_double),
        ("quality_p5", ctypes.c_double),
        ("X", ctypes.POINTER(ctypes.c_double)),
    ]


class VolumeSummary(ctypes.Structure):
    """scaf_volume_summary_t"""

    _fields_ = [
        ("struct_size", _size_t),
        ("steps", ctypes.c_int),
        ("iterations", ctypes.c_int),
        ("input_defects", ctypes.c_longlong),
        ("defects", ctypes.c_longlong),
        ("box_lo", ctypes.c_double * 3),
        ("box_hi", ctypes.c_double * 3),
        ("diagonal_before", ctypes.c_double),
        ("diagonal_after", ctypes.c_double),
        ("best_iteration", ctypes.c_int),
        ("stop", c_enum),
        ("flowed_rms", ctypes.c_double),
        ("flowed_max", ctypes.c_double),
        ("rms", ctypes.c_double),
        ("max", ctypes.c_double),
        ("box_vertices", ctypes.c_int),
        ("tets_inside", ctypes.c_int),
    ]


class TetOptions(ctypes.Structure):
    """scaf_tet_options_t"""

    _fields_ = [
        ("struct_size", _size_t),
        ("box_scale", ctypes.c_double),
        ("box_cells", ctypes.c_int),
    ]


class SurfaceReport(ctypes.Structure):
    """scaf_surface_report_t"""

    _fields_ = [
        ("struct_size", _size_t),
        ("message", ctypes.c_char * REPORT_MESSAGE_MAX),
        ("faces", ctypes.c_int),
        ("vertices", ctypes.c_int),
        ("boundary_edges", ctypes.c_int),
        ("closed", ctypes.c_int),
        ("manifold", ctypes.c_int),
        ("degenerate_faces", ctypes.c_int),
        ("first_degenerate", ctypes.c_int),
        ("pairs", ctypes.c_longlong),
        ("crossing_pairs", ctypes.c_longlong),
        ("vertex_pairs", ctypes.c_longlong),
        ("edge_pairs", ctypes.c_longlong),
        ("duplicate_pairs", ctypes.c_longlong),
        ("nfirst", ctypes.c_int),
        ("first", (ctypes.c_int * 2) * SURFACE_FIRST_PAIRS),
        ("intersection_free", ctypes.c_int),
    ]


class TetsReport(ctypes.Structure):
    """scaf_tets_report_t"""

    _fields_ = [
        ("struct_size", _size_t),
        ("message", ctypes.c_char * REPORT_MESSAGE_MAX),
        ("tets", ctypes.c_int),
        ("positive", ctypes.c_int),
        ("inverted", ctypes.c_int),
        ("degenerate", ctypes.c_int),
        ("first_bad", ctypes.c_int),
        ("valid", ctypes.c_int),
    ]


# The C names of the mirrored structs, for the layout test.
STRUCTS = {
    "scaf_energy_info_t": EnergyInfo,
    "scaf_options_t": Options,
    "scaf_iteration_info_t": IterationInfo,
    "scaf_atlas_options_t": AtlasOptions,
    "scaf_atlas_iteration_info_t": AtlasIterationInfo,
    "scaf_drag_options_t": DragOptions,
    "scaf_drag_chart_info_t": DragChartInfo,
    "scaf_drag_motion_t": DragMotion,
    "scaf_inflate_options_t": InflateOptions,
    "scaf_untangle_options_t": UntangleOptions,
    "scaf_flow_options_t": FlowOptions,
    "scaf_tet_options_t": TetOptions,
    "scaf_volume_step_info_t": VolumeStepInfo,
    "scaf_volume_summary_t": VolumeSummary,
    "scaf_surface_report_t": SurfaceReport,
    "scaf_tets_report_t": TetsReport,
}

PARAM_PROGRESS = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.POINTER(IterationInfo), ctypes.c_void_p)
ATLAS_PROGRESS = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.POINTER(AtlasIterationInfo), ctypes.c_void_p)
VOLUME_PROGRESS = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.POINTER(VolumeStepInfo), ctypes.c_void_p)

_P = ctypes.c_void_p  # opaque scaf_param_t * / scaf_atlas_t *
_D = ctypes.POINTER(ctypes.c_double)
_I = ctypes.POINTER(ctypes.c_int)
_int = ctypes.c_int

# name: (restype, argtypes)
SIGNATURES = {
    "scaf_status_name": (ctypes.c_char_p, [c_enum]),
    "scaf_version": (ctypes.c_char_p, []),
    "scaf_set_threads": (_int, [_int]),
    "scaf_set_deterministic": (None, [_int]),
    "scaf_stop_reason_name": (ctypes.c_char_p, [c_enum]),
    "scaf_area_matched_energy": (c_enum, [_D, _int, _I, _int, _D, _int, _I, _D]),
    "scaf_energy_count": (_int, []),
    "scaf_energy_info": (c_enum, [_int, ctypes.POINTER(EnergyInfo)]),
    "scaf_options_default": (Options, []),
    "scaf_param_new": (_P, [ctypes.POINTER(Options)]),
    "scaf_param_set_options": (c_enum, [_P, ctypes.POINTER(Options)]),
    "scaf_param_set_mesh": (c_enum, [_P, _D, _int, _I, _int, _D, _int, _I]),
    "scaf_param_run": (c_enum, [_P, _int, PARAM_PROGRESS, ctypes.c_void_p]),
    "scaf_param_energy": (ctypes.c_double, [_P]),
    "scaf_param_chart_count": (_int, [_P]),
    "scaf_param_seams_used": (_int, [_P]),
    "scaf_param_iterations": (_int, [_P]),
    "scaf_param_stop_reason": (c_enum, [_P]),
    "scaf_param_uv_count": (_int, [_P]),
    "scaf_param_get_uv": (c_enum, [_P, _D, _I]),
    "scaf_param_set_handles": (c_enum, [_P, _int, _I, _D, ctypes.c_double]),
    "scaf_param_error": (ctypes.c_char_p, [_P]),
    "scaf_param_destroy": (None, [_P]),
    "scaf_atlas_options_default": (AtlasOptions, []),
    "scaf_atlas_new": (_P, [ctypes.POINTER(AtlasOptions)]),
    "scaf_atlas_set_options": (c_enum, [_P, ctypes.POINTER(AtlasOptions)]),
    "scaf_atlas_set_mesh": (c_enum, [_P, _D, _int, _I, _int, _D, _int, _I]),
    "scaf_atlas_run": (c_enum, [_P, ATLAS_PROGRESS, ctypes.c_void_p]),
    "scaf_atlas_chart_count": (_int, [_P]),
    "scaf_atlas_seams_used": (_int, [_P]),
    "scaf_atlas_uv_count": (_int, [_P]),
    "scaf_atlas_iterations": (_int, [_P, c_enum]),
    "scaf_atlas_stop_reason": (c_enum, [_P, c_enum]),
    "scaf_atlas_get_uv": (c_enum, [_P, _D, _I, _I]),
    "scaf_atlas_packing_efficiency": (ctypes.c_double, [_P]),
    "scaf_atlas_min_chart_gap": (ctypes.c_double, [_P]),
    "scaf_atlas_energy": (ctypes.c_double, [_P]),
    "scaf_atlas_chart_distortion": (c_enum, [_P, _D]),
    "scaf_atlas_error": (ctypes.c_char_p, [_P]),
    "scaf_atlas_destroy": (None, [_P]),
    "scaf_drag_options_default": (DragOptions, []),
    "scaf_drag_new": (_P, [ctypes.POINTER(DragOptions)]),
    "scaf_drag_set_options": (c_enum, [_P, ctypes.POINTER(DragOptions)]),
    "scaf_drag_set_mesh": (c_enum, [_P, _D, _int, _I, _int, _D, _int, _I]),
    "scaf_drag_chart_count": (_int, [_P]),
    "scaf_drag_uv_count": (_int, [_P]),
    "scaf_drag_face_count": (_int, [_P]),
    "scaf_drag_get_uv": (c_enum, [_P, _D, _I, _I]),
    "scaf_drag_uv_charts": (c_enum, [_P, _I]),
    "scaf_drag_move_vertex": (c_enum, [_P, _int, ctypes.c_double, ctypes.c_double]),
    "scaf_drag_move_chart": (c_enum, [_P, _int, ctypes.c_double, ctypes.c_double, ctypes.c_double]),
    "scaf_drag_clear_vertex": (c_enum, [_P, _int]),
    "scaf_drag_clear_chart": (c_enum, [_P, _int]),
    "scaf_drag_clear_handles": (c_enum, [_P]),
    "scaf_drag_handle_count": (_int, [_P]),
    "scaf_drag_pin_vertex": (c_enum, [_P, _int, _int]),
    "scaf_drag_is_pinned": (_int, [_P, _int]),
    "scaf_drag_pinned_count": (_int, [_P]),
    "scaf_drag_max_handle_error": (ctypes.c_double, [_P]),
    "scaf_drag_set_padding": (c_enum, [_P, ctypes.c_double]),
    "scaf_drag_padding": (ctypes.c_double, [_P]),
    "scaf_drag_step": (c_enum, [_P, _int, PARAM_PROGRESS, ctypes.c_void_p]),
    "scaf_drag_compact": (c_enum, [_P, _int, PARAM_PROGRESS, ctypes.c_void_p]),
    "scaf_drag_iterations": (_int, [_P]),
    "scaf_drag_cancel": (c_enum, [_P]),
    "scaf_drag_checkpoint": (c_enum, [_P]),
    "scaf_drag_undo": (c_enum, [_P]),
    "scaf_drag_undo_count": (_int, [_P]),
    "scaf_drag_redo": (c_enum, [_P]),
    "scaf_drag_redo_count": (_int, [_P]),
    "scaf_drag_motion_identity": (DragMotion, []),
    "scaf_drag_rigid_begin": (c_enum, [_P, _I, _int]),
    "scaf_drag_rigid_move": (c_enum, [_P, ctypes.POINTER(DragMotion), _D]),
    "scaf_drag_rigid_end": (c_enum, [_P]),
    "scaf_drag_transform": (c_enum, [_P, _I, _int, ctypes.POINTER(DragMotion), _D]),
    "scaf_drag_set_energy_cap": (c_enum, [_P, ctypes.c_double]),
    "scaf_drag_energy_cap": (ctypes.c_double, [_P]),
    "scaf_drag_capped_count": (ctypes.c_long, [_P]),
    "scaf_drag_energy": (ctypes.c_double, [_P]),
    "scaf_drag_packing_efficiency": (ctypes.c_double, [_P]),
    "scaf_drag_face_energy": (c_enum, [_P, _D]),
    "scaf_drag_chart_info": (c_enum, [_P, _int, ctypes.POINTER(DragChartInfo)]),
    "scaf_drag_get_output": (c_enum, [_P, _D, _I, _I, _D, _D]),
    "scaf_drag_error": (ctypes.c_char_p, [_P]),
    "scaf_drag_destroy": (None, [_P]),
    "scaf_volume_new": (_P, []),
    "scaf_volume_destroy": (None, [_P]),
    "scaf_volume_error": (ctypes.c_char_p, [_P]),
    "scaf_volume_vertex_count": (_int, [_P]),
    "scaf_volume_get_positions": (c_enum, [_P, _D]),
    "scaf_volume_get_flowed": (c_enum, [_P, _D]),
    "scaf_volume_tet_vertex_count": (_int, [_P]),
    "scaf_volume_tet_count": (_int, [_P]),
    "scaf_volume_get_tets": (c_enum, [_P, _D, _I, _I]),
    "scaf_volume_get_summary": (c_enum, [_P, ctypes.POINTER(VolumeSummary)]),
    "scaf_inflate_options_default": (InflateOptions, []),
    "scaf_untangle_options_default": (UntangleOptions, []),
    "scaf_flow_options_default": (FlowOptions, []),
    "scaf_tet_options_default": (TetOptions, []),
    "scaf_tet_mesh": (c_enum, [_P, _D, _int, _I, _int, ctypes.POINTER(TetOptions)]),
    "scaf_inflate": (c_enum, [_P, _D, _int, _I, _int, ctypes.POINTER(InflateOptions),
                              VOLUME_PROGRESS, ctypes.c_void_p]),
    "scaf_untangle": (c_enum, [_P, _D, _int, _I, _int, ctypes.POINTER(UntangleOptions),
                               VOLUME_PROGRESS, ctypes.c_void_p]),
    "scaf_flow": (c_enum, [_P, _D, _int, _I, _int, ctypes.POINTER(FlowOptions), VOLUME_PROGRESS,
                           ctypes.c_void_p]),
    "scaf_untangle_stop_name": (ctypes.c_char_p, [c_enum]),
    "scaf_check_surface": (c_enum, [_D, _int, _I, _int, ctypes.POINTER(SurfaceReport)]),
    "scaf_check_tets": (c_enum, [_D, _int, _I, _int, ctypes.POINTER(TetsReport)]),
}


def _candidates():
    """(description, path or name) pairs in lookup order."""
    out = []
    env = os.environ.get("SCAF_LIBRARY")
    if env:
        out.append(("$SCAF_LIBRARY", env))
    here = os.path.dirname(os.path.abspath(__file__))
    try:
        from . import _install_paths  # written by `cmake --install`
    except ImportError:
        _install_paths = None
    if _install_paths is not None:
        libdir = os.path.normpath(os.path.join(here, _install_paths.LIBDIR))
        for name in ("libscaf.so." + _install_paths.SOVERSION, "libscaf.so"):
            out.append(("installed next to the package", os.path.join(libdir, name)))
    checkout = os.path.dirname(os.path.dirname(here))
    out.append(("build tree of the checkout", os.path.join(checkout, "build", "libscaf.so")))
    found = ctypes.util.find_library("scaf")
    out.append(('ctypes.util.find_library("scaf")', found))
    return out


def _declare(lib):
    for name, (restype, argtypes) in SIGNATURES.items():
        fn = getattr(lib, name)
        fn.restype = restype
        fn.argtypes = argtypes
    _read_energies(lib)
    return lib


def _read_energies(lib):
    """ENERGIES from the library's table of energies."""
    ENERGIES.clear()
    for e in range(lib.scaf_energy_count()):
        info = EnergyInfo()
        if lib.scaf_energy_info(e, ctypes.byref(info)) == SCAF_OK:
            ENERGIES[info.name.decode()] = e


def load():
    """(CDLL with every signature declared, the path it was loaded from)."""
    tried = []
    for what, path in _candidates():
        if not path:
            tried.append("%s: nothing found" % what)
        elif os.path.sep in path and not os.path.exists(path):
            tried.append("%s: %s does not exist" % (what, path))
        else:
            try:
                return _declare(ctypes.CDLL(path)), path
            except OSError as e:
                tried.append("%s: %s: %s" % (what, path, e))
            except AttributeError as e:
                tried.append("%s: %s is not a matching libscaf (%s)" % (what, path, e))
        if what == "$SCAF_LIBRARY":
            break  # an explicit choice that fails is not silently replaced
    raise ImportError(
        "scaf: cannot load the C library libscaf.so; tried, in order:\n  "
        + "\n  ".join(tried)
        + "\nSet SCAF_LIBRARY to the path of libscaf.so (build/libscaf.so after "
        "`cmake --build build`, or <prefix>/lib/libscaf.so after `cmake --install`)."
    )
