"""scaf._arrays: turns user arrays into C buffers and C buffers into results.

With numpy (optional): any array-like of a float or integer dtype is
converted to a C-contiguous float64 (positions, UVs) or int32 (indices)
array; its shape is checked first. Without numpy: nested sequences (lists
or tuples of rows) are packed into array.array buffers with the same
checks. Every problem raises ValueError naming the argument before any C
function is called. Outputs are numpy arrays with numpy, lists of lists
(one list per row) without.
"""

import array
import ctypes
import math
import numbers

try:
    import numpy as np
except ImportError:  # numpy is optional
    np = None

INT32_MIN, INT32_MAX = -(2 ** 31), 2 ** 31 - 1


class Matrix:
    """A C view of an n x cols input: .ptr (ctypes pointer), .rows; keeps
    the memory alive as long as the Matrix lives."""

    def __init__(self, owner, ptr, rows):
        self._owner = owner
        self.ptr = ptr
        self.rows = rows


def _numpy_matrix(x, name, cols, integer):
    try:
        a = np.asarray(x)
    except (ValueError, TypeError) as e:
        raise ValueError("%s: not a rectangular array (%s)" % (name, e)) from None
    if a.dtype.kind not in "fiu":
        raise ValueError("%s: dtype %s is not a float or integer dtype" % (name, a.dtype))
    if a.ndim != 2 or a.shape[1] != cols:
        raise ValueError("%s: shape %s, expected (n, %d)" % (name, a.shape, cols))
    if a.shape[0] < 1:
        raise ValueError("%s: no rows" % name)
    if a.shape[0] > INT32_MAX:
        raise ValueError("%s: %d rows, more than the C int counts allow" % (name, a.shape[0]))
    if integer:
        if a.dtype.kind == "f":
            if not np.all(np.isfinite(a)) or not np.all(a == np.floor(a)):
                raise ValueError("%s: float dtype %s with non-integer values (indices expected)" % (name, a.dtype))
        if a.min() < INT32_MIN or a.max() > INT32_MAX:
            raise ValueError("%s: index values outside the 32-bit int range" % name)
        c = np.ascontiguousarray(a, dtype=np.int32)
        return Matrix(c, c.ctypes.data_as(ctypes.POINTER(ctypes.c_int)), c.shape[0])
    c = np.ascontiguousarray(a, dtype=np.float64)
    return Matrix(c, c.ctypes.data_as(ctypes.POINTER(ctypes.c_double)), c.shape[0])


def _list_matrix(x, name, cols, integer):
    try:
        rows = list(x)
    except TypeError:
        raise ValueError("%s: expected a sequence of rows of %d numbers, got %s" % (name, cols, type(x).__name__)) from None
    if not rows:
        raise ValueError("%s: no rows" % name)
    buf = array.array("i" if integer else "d")
    for i, row in enumerate(rows):
        try:
            vals = list(row)
        except TypeError:
            raise ValueError("%s: row %d is not a sequence" % (name, i)) from None
        if len(vals) != cols:
            raise ValueError("%s: row %d has %d values, expected %d" % (name, i, len(vals), cols))
        for v in vals:
            if isinstance(v, bool) or not isinstance(v, numbers.Real):
                raise ValueError("%s: row %d: %r is not a number" % (name, i, v))
            if integer:
                if not isinstance(v, numbers.Integral) and not (math.isfinite(v) and float(v).is_integer()):
                    raise ValueError("%s: row %d: %r is not an integer index" % (name, i, v))
                v = int(v)
                if not INT32_MIN <= v <= INT32_MAX:
                    raise ValueError("%s: row %d: index %d outside the 32-bit int range" % (name, i, v))
            else:
                v = float(v)
            buf.append(v)
    ctype = ctypes.c_int if integer else ctypes.c_double
    if ctypes.sizeof(ctype) != buf.itemsize:
        raise ValueError("%s: array item size %d differs from C's %d" % (name, buf.itemsize, ctypes.sizeof(ctype)))
    carr = (ctype * len(buf)).from_buffer(buf)
    return Matrix((buf, carr), ctypes.cast(carr, ctypes.POINTER(ctype)), len(rows))


def matrix(x, name, cols, integer):
    """Check and convert an input of shape (n, cols): float64 positions or
    int32 indices (integer=True)."""
    if np is not None:
        return _numpy_matrix(x, name, cols, integer)
    return _list_matrix(x, name, cols, integer)


class Output:
    """A zeroed C buffer of rows x cols (cols None: a vector of rows);
    .ptr for C, .value() for Python."""

    def __init__(self, rows, cols, integer):
        self._shape = (rows,) if cols is None else (rows, cols)
        n = rows * (1 if cols is None else cols)
        if np is not None:
            self._a = np.zeros(self._shape, dtype=np.int32 if integer else np.float64)
            self.ptr = self._a.ctypes.data_as(ctypes.POINTER(ctypes.c_int if integer else ctypes.c_double))
        else:
            self._a = ((ctypes.c_int if integer else ctypes.c_double) * max(n, 1))()
            self.ptr = ctypes.cast(self._a, ctypes.POINTER(ctypes.c_int if integer else ctypes.c_double))

    def value(self):
        if np is not None:
            return self._a
        if len(self._shape) == 1:
            return list(self._a[: self._shape[0]])
        rows, cols = self._shape
        flat = list(self._a[: rows * cols])
        return [flat[i * cols:(i + 1) * cols] for i in range(rows)]
