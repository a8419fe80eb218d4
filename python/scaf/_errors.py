"""scaf._errors: the exceptions, one class per C scaf_status.

Every failure of the C library becomes an instance of a subclass of
scaf.Error carrying the library's message (which names the chart, face or
option at fault), the numeric status and its C name.
"""


class Error(Exception):
    """A scaf_status other than SCAF_OK. Attributes: status (int), status_name
    (the C library's name of the status, e.g. "invalid mesh"), message."""

    status = None

    def __init__(self, message, status=None, status_name=None):
        super().__init__(message)
        self.message = message
        if status is not None:
            self.status = status
        self.status_name = status_name


class UsageError(Error, ValueError):
    """SCAF_ERR_USAGE: an invalid argument or option value (also a ValueError),
    e.g. a face index out of range or a padding of 0.5."""

    status = 1


class InputError(Error):
    """SCAF_ERR_IO / SCAF_ERR_PARSE: a file cannot be read or is malformed
    (raised by scaf.read_obj; the array API itself reads no file)."""

    status = 3


class MeshError(Error):
    """SCAF_ERR_MESH: the mesh cannot be parametrized (a chart that is closed,
    has genus, is non-manifold or non-orientable, or a degenerate face);
    the message names the chart and the reason."""

    status = 4


class NumericError(Error):
    """SCAF_ERR_NUMERIC: a numerical step failed (factorization, ...)."""

    status = 5


class OutOfMemory(Error):
    """SCAF_ERR_NOMEM: the C library ran out of memory."""

    status = 6


class Cancelled(Error):
    """SCAF_ERR_CANCELLED: the progress callback returned a true value. The
    map of the last finished iteration stays valid (bijective): the
    high-level scaf.param / scaf.atlas attach it as .result."""

    status = 7
    result = None


class InternalError(Error):
    """SCAF_ERR_INTERNAL: an invariant of scaf itself broke (a bug)."""

    status = 8


BY_STATUS = {
    1: UsageError,
    2: InputError,
    3: InputError,
    4: MeshError,
    5: NumericError,
    6: OutOfMemory,
    7: Cancelled,
    8: InternalError,
}
