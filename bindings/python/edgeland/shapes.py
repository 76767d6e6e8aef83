"""Shapes: validated polygon sets to carve and fill with."""
import ctypes

from . import _native, results
from ._handles import Handle, Owned, made
from .errors import call

_lib = _native.lib


def _point(p):
    return _native.Point(int(p[0]), int(p[1]))


def _box(b):
    return _native.Box(_point(b[0]), _point(b[1]))


def _csr(point_lists):
    """Point lists (each a sequence of (x, y)) as C arrays: the coordinates x0, y0, x1, ... and
    the offsets 0, len(list 0), ... (the C API's CSR)."""
    xy, offsets = [], [0]
    for points in point_lists:
        for x, y in points:
            xy += (int(x), int(y))
        offsets.append(len(xy) // 2)
    return (ctypes.c_int64 * len(xy))(*xy), (ctypes.c_uint32 * len(offsets))(*offsets)


class Shape(Handle):
    """A polygon set validated once: strictly simple, counter-clockwise, hole-free polygons with
    disjoint interiors, every coordinate within 2^31 - 1. Build it from polygons (a list of
    polygons, each a sequence of (x, y); numpy arrays of shape (n, 2) work too) or with the
    builders below. Raises InvalidInput / CoordinateOutOfRange naming the polygon and vertex."""

    _destroy = "el_shape_destroy"

    def __init__(self, polygons=None, *, _pointer=None):
        if _pointer is None:
            xy, offsets = _csr(polygons)
            _pointer = made(_lib.el_shape_create, xy, offsets, len(offsets) - 1)
        super().__init__(_pointer)

    @classmethod
    def import_polygons(cls, polygons):
        """Any polygons read with OGC semantics (el_shape_import; JavaScript's Shape.import, a
        keyword in Python): each polygon a list of rings, its exterior then its holes, each ring a
        sequence of (x, y) as another library or an editor drew it: clockwise, self-intersecting
        or touching. Each ring winds around its points (non-zero), exteriors +1, holes -1; the
        shape is where the sum is positive, as valid hole-free pieces (none for rings of no
        area). CoordinateOutOfRange names the polygon (`index`) and the vertex in its ring."""
        rings, polygon_rings = [], [0]
        for polygon in polygons:
            rings += polygon
            polygon_rings.append(len(rings))
        xy, ring_offsets = _csr(rings)
        polygon_array = (ctypes.c_uint32 * len(polygon_rings))(*polygon_rings)
        return cls(_pointer=made(_lib.el_shape_import, xy, ring_offsets, polygon_array,
                                 len(polygon_rings) - 1))

    @classmethod
    def circle(cls, center, radius):
        """A circle of circle_sides(radius) corners (radius 1 .. 2^33), valid by construction."""
        return cls(_pointer=made(_lib.el_shape_circle, ctypes.byref(_point(center)), radius))

    @classmethod
    def regular_polygon(cls, center, radius, sides, phase=(0, 1)):
        """`sides` corners at `radius`, the first at phase[0] / phase[1] turns."""
        return cls(_pointer=made(_lib.el_shape_regular_polygon, ctypes.byref(_point(center)),
                                 radius, sides, phase[0], phase[1]))

    @classmethod
    def capsule(cls, a, b, radius):
        """The stroke from a to b widened by radius, round ends."""
        return cls(_pointer=made(_lib.el_shape_capsule, ctypes.byref(_point(a)),
                                 ctypes.byref(_point(b)), radius))

    @classmethod
    def box(cls, lo, hi):
        """The axis-aligned box from corner lo to corner hi."""
        return cls(_pointer=made(_lib.el_shape_box, ctypes.byref(_box((lo, hi)))))

    @classmethod
    def rotated_box(cls, center, half_width, half_height, angle=(0, 1)):
        """A box of half extents turned by angle[0] / angle[1] turns."""
        return cls(_pointer=made(_lib.el_shape_rotated_box, ctypes.byref(_point(center)),
                                 half_width, half_height, angle[0], angle[1]))

    @property
    def polygons(self):
        """The polygons, each a list of (x, y)."""
        with Owned(made(_lib.el_shape_polygons, self), "el_polygons_destroy") as h:
            return [p.points for p in results.polygons(h)]


def as_shape(shape):
    """A Shape, or polygons made into one."""
    return shape if isinstance(shape, Shape) else Shape(shape)
