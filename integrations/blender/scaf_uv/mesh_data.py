"""scaf_uv.mesh_data: a Blender mesh's triangles and UVs as numpy arrays,
and the UVs written back to the active UV map only.

Read from the Mesh datablock (in edit mode after update_from_editmode, so
the arrays follow the edit mesh): per corner (loop) its vertex, edge and
next corner, the seams, the active UV map, and the triangulation Blender
itself uses (loop_triangles), so n-gons are computed as triangles and
written back per corner. Writing touches nothing but the active UV map's
coordinates (edit mode: the BMesh's UV layer; object mode: foreach_set),
so every other attribute stays as it was.
"""

import bmesh
import numpy as np


class MeshArrays:
    """What scaf needs of one object's mesh (see the module doc)."""

    def __init__(self, obj):
        if obj.mode == "EDIT":
            obj.update_from_editmode()
        me = obj.data
        self.name = obj.name
        if not me.uv_layers.active:
            raise ValueError("%s has no UV map: add one in Object Data > UV Maps" % obj.name)
        nv, nl, ne, np_ = len(me.vertices), len(me.loops), len(me.edges), len(me.polygons)
        self.V = np.empty(nv * 3)
        me.vertices.foreach_get("co", self.V)
        self.V = self.V.reshape(-1, 3)
        self.loop_vert = np.empty(nl, np.int32)
        me.loops.foreach_get("vertex_index", self.loop_vert)
        self.loop_edge = np.empty(nl, np.int32)
        me.loops.foreach_get("edge_index", self.loop_edge)
        starts, totals = np.empty(np_, np.int32), np.empty(np_, np.int32)
        me.polygons.foreach_get("loop_start", starts)
        me.polygons.foreach_get("loop_total", totals)
        self.poly_start, self.poly_total = starts, totals
        self.loop_poly = np.repeat(np.arange(np_, dtype=np.int32), totals)
        pos = np.arange(nl) - np.repeat(starts, totals)
        self.loop_next = (np.repeat(starts, totals) + (pos + 1) % np.repeat(totals, totals)).astype(np.int32)
        self.edge_seam = np.zeros(ne, bool)
        me.edges.foreach_get("use_seam", self.edge_seam)
        if obj.mode == "EDIT":  # the Mesh's UV data is empty while in edit mode: the BMesh has it
            bm = bmesh.from_edit_mesh(me)
            layer = bm.loops.layers.uv.active
            uv = np.array([loop[layer].uv[:] for f in bm.faces for loop in f.loops], np.float32)
        else:
            uv = np.empty(nl * 2, np.float32)
            me.uv_layers.active.data.foreach_get("uv", uv)
        self.loop_uv = uv.reshape(-1, 2)
        if len(self.loop_uv) != nl:
            raise ValueError("%s: %d UVs for %d face corners" % (obj.name, len(self.loop_uv), nl))
        me.calc_loop_triangles()
        tl = np.empty(len(me.loop_triangles) * 3, np.int32)
        me.loop_triangles.foreach_get("loops", tl)
        self.tri_loops = tl.reshape(-1, 3)
        tp = np.empty(len(me.loop_triangles), np.int32)
        me.loop_triangles.foreach_get("polygon_index", tp)
        self.tri_poly = tp
        if len(self.tri_loops) == 0:
            raise ValueError("%s has no faces" % obj.name)
        # vertices used by the triangles only, renumbered (scaf maps every vertex given)
        used, inverse = np.unique(self.loop_vert[self.tri_loops], return_inverse=True)
        self.Vt = self.V[used]
        self.Ft = inverse.reshape(-1, 3).astype(np.int32)

    def corner_uvs(self, uv, ft):
        """Per-loop UVs (#loops x 2 float32) from a per-triangle-corner map
        (uv #UV x 2, ft #T x 3) and the number of loops whose triangles
        disagree (a cut through an n-gon: its corner gets one of them)."""
        uv = np.asarray(uv, dtype=np.float64)
        ft = np.asarray(ft)
        out = self.loop_uv.astype(np.float64).copy()
        corner_uv = uv[ft].reshape(-1, 2)
        loops = self.tri_loops.reshape(-1)
        out[loops] = corner_uv
        disagree = np.any(out[loops] != corner_uv, axis=1)
        return out.astype(np.float32), int(np.count_nonzero(disagree))


def write_uvs(obj, loop_uv):
    """Set the active UV map's coordinates of every corner (#loops x 2)."""
    me = obj.data
    if obj.mode == "EDIT":
        bm = bmesh.from_edit_mesh(me)
        layer = bm.loops.layers.uv.active
        values = loop_uv.tolist()
        i = 0
        for f in bm.faces:  # face and loop order = the Mesh's (update_from_editmode)
            for loop in f.loops:
                loop[layer].uv = values[i]
                i += 1
        bmesh.update_edit_mesh(me, loop_triangles=False, destructive=False)
    else:
        me.uv_layers.active.data.foreach_set("uv", np.ascontiguousarray(loop_uv, np.float32).reshape(-1))
        me.update()


def select_polygons(obj, bad, tool_settings):
    """Select exactly the polygons where bad (#polygons bool) is True, in
    the mesh and (edit mode) in the UV editor's own selection. Edit mode
    switches to face select mode: in vertex mode every face whose vertices
    are all selected would be selected too."""
    me = obj.data
    if obj.mode == "EDIT":
        tool_settings.mesh_select_mode = (False, False, True)
        bm = bmesh.from_edit_mesh(me)
        bm.select_mode = {"FACE"}
        layer = bm.loops.layers.uv.active
        flags = bad.tolist()
        for f in bm.faces:
            f.select_set(False)
        for f, b in zip(bm.faces, flags):
            if b:
                f.select_set(True)
            for loop in f.loops:
                loop[layer].select = b
                if hasattr(loop[layer], "select_edge"):  # Blender >= 3.5 only
                    loop[layer].select_edge = b
        bm.select_flush_mode()
        bmesh.update_edit_mesh(me, loop_triangles=False, destructive=False)
    else:
        me.polygons.foreach_set("select", bad.astype(bool))
        me.update()
