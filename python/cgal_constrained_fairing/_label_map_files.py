"""Label map files: NIfTI (with nibabel), INRIMAGE-4 (CGAL's images) and numpy's ``.npy``."""

import os
from typing import Optional, Tuple

import numpy as np

from . import _core

LABEL_MAP_SUFFIXES = (".nii.gz", ".nii", ".inr.gz", ".inr", ".npy")
"""The extensions of the label map files that `read_label_map` reads."""


def label_map_stem(path: "os.PathLike[str] | str") -> Optional[str]:
    """The file name of a label map without its extension; ``None`` for another file."""
    name = os.path.basename(os.fspath(path))
    for suffix in LABEL_MAP_SUFFIXES:
        if name.lower().endswith(suffix) and len(name) > len(suffix):
            return name[:-len(suffix)]
    return None


def read_label_map(path: "os.PathLike[str] | str") -> Tuple[np.ndarray, np.ndarray]:
    """Read a 3-D label map and the map from its voxel indices to world coordinates.

    A NIfTI-1 or NIfTI-2 file (``.nii``, ``.nii.gz``) is read with nibabel: its voxels as
    stored (a segmentation's integers; stored floats must hold whole numbers) and its
    ``affine``: the sform if its code is set, else the qform if its code is set, else the
    voxel sizes alone (the standard's method 1), as the command-line tool reads them. An
    INRIMAGE-4 file (``.inr``, ``.inr.gz``, the images of CGAL's Mesh_3) is read by the
    command-line tool's own reader, so that both agree bit for bit: its voxels as int64, its
    affine ``diag(VX, VY, VZ)`` plus the origin ``(TX, TY, TZ)``, as CGAL places the voxels.
    A ``.npy`` file holds the array alone; its affine is the identity (voxel ``[i, j, k]`` at
    ``(i, j, k)``). A 4-D image with one volume is read as 3-D.

    Parameters
    ----------
    path : str or os.PathLike
        A ``.nii``, ``.nii.gz``, ``.inr``, ``.inr.gz`` or ``.npy`` file.

    Returns
    -------
    labels : numpy.ndarray
        ``(I, J, K)``, an integer dtype.
    affine : numpy.ndarray
        ``(4, 4)`` float64: the centre of voxel ``[i, j, k]`` is at
        ``affine @ (i, j, k, 1)``. Pass both to `label_surfaces` as ``(labels, affine=affine)``.

    Raises
    ------
    FileNotFoundError
        No such file.
    ValueError
        An unknown extension, a file that is not a valid NIfTI, INRIMAGE-4 or ``.npy`` file
        (the message names the defect), an array that is not 3-D, or voxels that are not whole
        numbers.
    ImportError
        A NIfTI file without nibabel (Debian's ``python3-nibabel``).
    """
    path = os.fspath(path)
    if not os.path.isfile(path):
        raise FileNotFoundError(f"no such file: {path}")
    if label_map_stem(path) is None:
        raise ValueError(f"{path}: a label map must be a {', '.join(LABEL_MAP_SUFFIXES)} file")
    lower = path.lower()
    if lower.endswith((".inr", ".inr.gz")):
        return _core.read_label_map_file(path)
    if lower.endswith(".npy"):
        try:
            data = np.load(path, allow_pickle=False)
        except (OSError, ValueError) as error:
            raise ValueError(f"{path}: not a valid .npy file ({error})") from None
        affine = np.eye(4)
    else:
        data, affine = _read_nifti(path)
    if data.ndim == 4 and data.shape[3] == 1:
        data = data[..., 0]
    if data.ndim != 3:
        raise ValueError(f"{path}: a label map must be 3-D (got shape {data.shape})")
    if data.dtype.kind == "f":
        if not np.isfinite(data).all() or (data != np.round(data)).any():
            raise ValueError(f"{path}: the voxels must be whole numbers (labels)")
        data = data.astype(np.int64)
    elif data.dtype.kind == "b":
        data = data.astype(np.uint8)
    elif data.dtype.kind not in "iu":
        raise ValueError(f"{path}: the voxels must be integers (got {data.dtype})")
    return data, np.asarray(affine, dtype=np.float64)


def nifti_affine(image) -> np.ndarray:
    """The affine of a nibabel NIfTI image: its sform if its code is set, else its qform if
    its code is set, else the NIfTI standard's method 1, as the command-line tool reads it
    (nibabel would centre the volume and mirror x, as for Analyze files)."""
    header = image.header
    if int(header["sform_code"]) == 0 and int(header["qform_code"]) == 0:
        return np.diag([*header.get_zooms()[:3], 1.0])
    return np.asarray(image.affine, dtype=np.float64)


def _read_nifti(path: str):
    try:
        import nibabel
    except ImportError as error:
        raise ImportError("reading NIfTI files needs nibabel: apt-get install python3-nibabel "
                          "(or pip install nibabel)") from error
    try:
        image = nibabel.load(path)
        proxy = image.dataobj
        # The stored integers as they are, unless the header scales them (then whole numbers
        # are checked after the scaling).
        if (getattr(proxy, "slope", 1.0), getattr(proxy, "inter", 0.0)) == (1.0, 0.0) \
                and hasattr(proxy, "get_unscaled"):
            data = proxy.get_unscaled()
        else:
            data = np.asanyarray(proxy)
        return np.asarray(data), nifti_affine(image)
    except (OSError, EOFError, ValueError, nibabel.filebasedimages.ImageFileError) as error:
        raise ValueError(f"{path}: not a valid NIfTI file ({error})") from None
