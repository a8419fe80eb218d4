"""scaf_uv.library: finds and imports the scaf Python package.

In this order: the add-on preferences "scaf package folder" (a folder
holding the package `scaf`, e.g. a checkout's python/; put first on
sys.path) and "libscaf library" (exported as SCAF_LIBRARY before the
import); else whatever Blender's Python imports as `scaf` (a
`pip install .` into the Python Blender runs, or PYTHONPATH). Imported
lazily, at the first operator run, so the add-on registers without it;
a change of the preferences applies after a restart of Blender, as
Python imports a module once.
"""

import os
import sys

ADDON = __package__ or "scaf_uv"


class NotFound(Exception):
    pass


def preferences(context):
    addon = context.preferences.addons.get(ADDON)
    return addon.preferences if addon else None


def load(context):
    """The scaf module, or NotFound with what was tried."""
    if "scaf" in sys.modules:
        return sys.modules["scaf"]
    prefs = preferences(context)
    folder = bpy_path(prefs.package_dir) if prefs else ""
    library = bpy_path(prefs.library) if prefs else ""
    if folder and folder not in sys.path:
        sys.path.insert(0, folder)
    if library:
        os.environ["SCAF_LIBRARY"] = library
    try:
        import scaf
    except ImportError as e:
        raise NotFound("cannot import the scaf package (%s). Install it into Blender's Python "
                       "(pip install . in the scaf checkout) or set its folder and libscaf.so in "
                       "Preferences > Add-ons > scaf UV" % e)
    return scaf


def bpy_path(p):
    if not p:
        return ""
    import bpy
    return os.path.abspath(bpy.path.abspath(p))


def program(context):
    prefs = preferences(context)
    return bpy_path(prefs.program) if prefs else ""
