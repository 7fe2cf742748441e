"""Checks and conversions of array arguments: each error names the argument."""

import itertools
import operator

import numpy as np

_U32_MAX = np.iinfo(np.uint32).max


def _as_numeric(value, name):
    try:
        array = np.asarray(value)
    except (TypeError, ValueError) as error:
        raise ValueError(f"{name} cannot be read as an array: {error}") from None
    if array.dtype == object:
        raise ValueError(f"{name} is ragged or holds objects that are not numbers")
    return array


def float_array(value, name, width=None, allow_empty_flat=True):
    """A C-contiguous float64 array of shape (n, width) (or (n,) when width is None)."""
    array = _as_numeric(value, name)
    if array.dtype.kind not in "iuf":
        raise TypeError(f"{name} must hold real numbers, not {array.dtype}")
    if width is not None:
        if array.size == 0 and allow_empty_flat and array.ndim <= 2:
            array = array.reshape(0, width)
        if array.ndim != 2 or array.shape[1] != width:
            raise ValueError(f"{name} must have shape (n, {width}), not {array.shape}")
    elif array.ndim != 1:
        raise ValueError(f"{name} must be one-dimensional, not of shape {array.shape}")
    return np.ascontiguousarray(array, dtype=np.float64)


def index_array(value, name, shape_text="one-dimensional"):
    """A C-contiguous uint32 array from integers of any dtype, each in range."""
    array = _as_numeric(value, name)
    if array.size == 0:
        return np.zeros(array.shape, dtype=np.uint32)
    if array.dtype.kind not in "iu":
        raise TypeError(f"{name} must hold integers, not {array.dtype}")
    if array.dtype != np.uint32:
        low, high = array.min(), array.max()
        if low < 0:
            raise ValueError(f"{name} holds a negative index ({low}) at {_where(array, low)}")
        if high > _U32_MAX:
            raise ValueError(f"{name} holds {high} at {_where(array, high)}, past 32-bit indices")
    return np.ascontiguousarray(array, dtype=np.uint32)


def output_array(array, name, dtype, shape_text, shape_ok):
    """Checks a caller's output array: numpy, of `dtype`, of a shape
    `shape_ok` accepts (`shape_text` says which), C-contiguous and writable."""
    if not isinstance(array, np.ndarray):
        raise TypeError(f"{name} must be a numpy array of {np.dtype(dtype).name}, not {type(array).__name__}")
    if array.dtype != dtype:
        raise TypeError(f"{name} must hold {np.dtype(dtype).name}, not {array.dtype}")
    if not shape_ok(array):
        raise ValueError(f"{name} must have shape {shape_text}, not {array.shape}")
    if not array.flags.c_contiguous or not array.flags.writeable:
        raise ValueError(f"{name} must be C-contiguous and writable")


def _where(array, value):
    position = np.argwhere(array == value)[0]
    return "position " + ", ".join(str(int(p)) for p in position)


def faces_arrays(faces, name="faces"):
    """(face_sizes, face_indices) as uint32 arrays from a list of index
    sequences of mixed sizes, or an (f, k) integer array."""
    if isinstance(faces, np.ndarray):
        if faces.ndim != 2:
            raise ValueError(f"{name} must be a list of index sequences or an (f, k) array, not of shape {faces.shape}")
        indices = index_array(faces, name)
        sizes = np.full(faces.shape[0], faces.shape[1], dtype=np.uint32)
        return sizes, indices.reshape(-1)
    try:
        faces = list(faces)
    except TypeError:
        raise TypeError(f"{name} must be a list of index sequences or an (f, k) array, not {type(faces).__name__}") from None
    sizes = np.empty(len(faces), dtype=np.uint32)
    for f, face in enumerate(faces):
        try:
            sizes[f] = len(face)
        except TypeError:
            raise TypeError(f"{name}[{f}] must be a sequence of vertex indices, not {type(face).__name__}") from None
    for f, face in enumerate(faces):
        if isinstance(face, (str, bytes)):
            raise TypeError(f"{name}[{f}] must be a sequence of vertex indices, not {type(face).__name__}")
    if len(sizes) and sizes.min() == sizes.max():
        # Faces of one size: numpy reads the nested lists in one pass.
        try:
            block = np.array(faces)
        except (TypeError, ValueError):
            block = None
        if block is not None and block.ndim == 2 and block.dtype.kind in "iu":
            return sizes, index_array(block, name).reshape(-1)
    flat = list(itertools.chain.from_iterable(faces))
    if not flat:
        return sizes, np.zeros(0, dtype=np.uint32)
    try:
        indices = np.array(flat)
    except (TypeError, ValueError):
        indices = np.array(flat, dtype=object)
    if indices.dtype.kind not in "iu":
        face = _first_bad_face(faces)
        raise TypeError(f"{name}[{face}] must hold integer vertex indices, not {faces[face]!r}")
    return sizes, index_array(indices, name)


def _first_bad_face(faces):
    for f, face in enumerate(faces):
        for index in face:
            try:
                operator.index(index)
            except TypeError:
                return f
    return 0


def address(array):
    """The address of an array's data, or None for an empty one."""
    return array.ctypes.data if array is not None and array.size else None


def view(pointer, count, ctype, dtype, owner, shape=None):
    """A read-only numpy view of `count` elements at `pointer` that keeps
    `owner` (the object that frees the buffer) alive while it exists."""
    if not pointer or count == 0:
        array = np.zeros(count, dtype=dtype)
    else:
        buffer = (ctype * count).from_address(pointer)
        buffer._owner = owner
        array = np.frombuffer(buffer, dtype=dtype)
    array.flags.writeable = False
    return array.reshape(shape) if shape is not None else array


def lent_array(value, name, dtype, ndim, width=None):
    """`value` itself, checked to be an array a mesh can read in place: a
    C-contiguous numpy array of `dtype` with `ndim` dimensions (the last of
    `width` when given). ValueError otherwise, as numpy's ``copy=False``."""
    wanted = f"a C-contiguous {np.dtype(dtype).name} numpy array of shape {_shape_text(ndim, width)}"
    if not isinstance(value, np.ndarray):
        raise ValueError(f"copy=False needs {name} as {wanted}, not {type(value).__name__}; a copy would be needed")
    if value.dtype != dtype or value.ndim != ndim or (width is not None and value.shape[-1] != width):
        raise ValueError(f"copy=False needs {name} as {wanted}, not {value.dtype} of shape {value.shape}; a copy would be needed")
    if not value.flags.c_contiguous or not value.flags.aligned:
        raise ValueError(f"copy=False needs {name} as {wanted}; this one is strided or unaligned, and a copy would be needed")
    return value


def _shape_text(ndim, width):
    if ndim == 1:
        return "(k,)"
    return f"(n, {width})" if width is not None else "(f, k)"
