"""Label volumes read a box at a time: zarr and N5 arrays, TIFF stacks, NIfTI files, arrays.

A `VolumeSource` names where a volume lies, not its voxels, so that a Dask task can open it
again on any worker and read its chunk's box; a volume a worker cannot open by name (a numpy
array, a zarr array in memory, a compressed NIfTI file) is first written once into the run's
folder as a ``.npy`` file, a slab at a time where it is read from a file.
"""

import dataclasses
from pathlib import Path
from typing import Optional, Sequence, Tuple

import numpy as np

# The slab of a NIfTI file converted at a time: about this many voxels.
SLAB_VOXELS = 1 << 26


@dataclasses.dataclass(frozen=True)
class VolumeSource:
    """A 3-D label volume that a task reads a box of: ``kind`` is ``"npy"``, ``"zarr"``,
    ``"n5"`` or ``"tiff"`` (a stack, one page per index of the first axis), ``path`` the file
    or store, ``component`` the array within a zarr group (``""`` for the store's root
    array)."""

    kind: str
    path: str
    shape: Tuple[int, int, int]
    dtype: str
    component: str = ""
    affine: Optional[Tuple[Tuple[float, ...], ...]] = None  # a NIfTI file's

    def open(self):
        """The volume as an array-like (not for TIFF stacks, read by `read`)."""
        if self.kind == "npy":
            return np.load(self.path, mmap_mode="r")
        import zarr
        store = zarr.N5Store(self.path) if self.kind == "n5" else zarr.DirectoryStore(self.path)
        return zarr.open(store, mode="r", path=self.component or None)

    def read(self, start: Sequence[int], stop: Sequence[int]) -> np.ndarray:
        """The voxels of the box `[start, stop)`, as int64."""
        box = tuple(slice(int(a), int(b)) for a, b in zip(start, stop))
        if self.kind == "tiff":  # the pages of the box's first axis, then the rest of the box
            import tifffile
            with tifffile.TiffFile(self.path) as tif:
                pages = tif.asarray(key=range(box[0].start, box[0].stop))
            pages = pages.reshape((box[0].stop - box[0].start,) + self.shape[1:])
            return np.ascontiguousarray(pages[:, box[1], box[2]], dtype=np.int64)
        return np.ascontiguousarray(self.open()[box], dtype=np.int64)


VOLUME_SUFFIXES = (".zarr", ".n5", ".tif", ".tiff", ".nii", ".nii.gz")


def is_label_volume(path: "str | Path") -> bool:
    """Whether `path` names a label volume: by its suffix, or a folder holding a zarr array."""
    path = Path(path)
    return path.name.lower().endswith(VOLUME_SUFFIXES) or (path / ".zarray").is_file()


def volume_source(volume, folder: Path) -> VolumeSource:
    """`volume` (a path, a zarr array, or an array) as a source that tasks can open."""
    if isinstance(volume, (str, Path)):
        return _source_of_path(Path(volume), folder)
    if type(volume).__module__.startswith("zarr"):
        import zarr
        store = volume.store
        kind = "n5" if isinstance(store, zarr.N5Store) else "zarr"
        if isinstance(store, zarr.DirectoryStore):
            return _checked(VolumeSource(kind, str(Path(store.path).resolve()), volume.shape,
                                         volume.dtype.str, volume.path))
        return _written(volume, folder)
    array = np.asarray(volume)
    return _written(array, folder)


def _source_of_path(path: Path, folder: Path) -> VolumeSource:
    if not path.exists():
        raise FileNotFoundError(f"{path}: no such file or folder")
    name = path.name.lower()
    if name.endswith((".tif", ".tiff")):
        import tifffile
        with tifffile.TiffFile(str(path)) as tif:
            series = tif.series[0]
            shape, dtype = series.shape, series.dtype
        return _checked(VolumeSource("tiff", str(path.resolve()), tuple(shape), np.dtype(dtype).str))
    if name.endswith((".nii", ".nii.gz")):
        return _converted_nifti(path, folder)
    if name.endswith(".npy"):
        array = np.load(path, mmap_mode="r")
        return _checked(VolumeSource("npy", str(path.resolve()), array.shape, array.dtype.str))
    import zarr
    store = zarr.N5Store(str(path)) if name.endswith(".n5") else zarr.DirectoryStore(str(path))
    array = zarr.open(store, mode="r")
    if not isinstance(array, zarr.Array):
        raise ValueError(f"{path} is a zarr group; pass the array, zarr.open({str(path)!r})[NAME]")
    return _checked(VolumeSource("n5" if name.endswith(".n5") else "zarr", str(path.resolve()),
                                 array.shape, array.dtype.str))


def _converted_nifti(path: Path, folder: Path) -> VolumeSource:
    """A NIfTI file written once into `folder` as .npy, a slab of the first axis at a time
    through nibabel's proxy, so that the whole volume is never held."""
    import nibabel
    from .._label_map_files import nifti_affine
    try:
        image = nibabel.load(str(path))
    except (OSError, EOFError, ValueError, nibabel.filebasedimages.ImageFileError) as error:
        raise ValueError(f"{path}: not a valid NIfTI file ({error})") from None
    proxy = image.dataobj
    shape = tuple(int(s) for s in proxy.shape[:3])
    if len(proxy.shape) > 3 and int(np.prod(proxy.shape[3:])) != 1:
        raise ValueError(f"{path}: a label volume has 3 dimensions (got shape {proxy.shape})")
    target = folder / "volume.npy"
    out = np.lib.format.open_memmap(target, mode="w+", dtype=np.int64, shape=shape)
    step = max(1, SLAB_VOXELS // max(1, shape[1] * shape[2]))
    for i in range(0, shape[0], step):
        slab = np.asarray(proxy[i:i + step])
        if slab.dtype.kind == "f" and not np.array_equal(slab, np.round(slab)):
            raise ValueError(f"{path}: labels must be whole numbers (its header scales them to "
                             f"{slab[slab != np.round(slab)].flat[0]})")
        out[i:i + step] = slab.reshape(slab.shape[:3])
    out.flush()
    affine = tuple(tuple(float(x) for x in row) for row in nifti_affine(image))
    return _checked(VolumeSource("npy", str(target), shape, out.dtype.str, affine=affine))


def _written(array, folder: Path) -> VolumeSource:
    """An array written into `folder` as .npy, a slab at a time."""
    target = folder / "volume.npy"
    dtype = np.dtype(array.dtype)
    if dtype.kind == "b":
        dtype = np.dtype(np.uint8)
    if np.ndim(array) != 3:
        raise ValueError(f"a label volume has 3 dimensions (got {np.ndim(array)})")
    out = np.lib.format.open_memmap(target, mode="w+", dtype=dtype, shape=tuple(array.shape))
    step = max(1, SLAB_VOXELS // max(1, array.shape[1] * array.shape[2]))
    for i in range(0, array.shape[0], step):
        out[i:i + step] = array[i:i + step]
    out.flush()
    return _checked(VolumeSource("npy", str(target), tuple(array.shape), dtype.str))


def _checked(source: VolumeSource) -> VolumeSource:
    if len(source.shape) != 3:
        raise ValueError(f"{source.path}: a label volume has 3 dimensions (got shape {source.shape})")
    kind = np.dtype(source.dtype).kind
    if kind not in "iub":
        raise ValueError(f"{source.path}: labels must be integers (got {np.dtype(source.dtype)})")
    return dataclasses.replace(source, shape=tuple(int(s) for s in source.shape))
