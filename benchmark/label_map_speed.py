#!/usr/bin/env python3
"""Label maps to surfaces: `label_surfaces` against 3D Slicer's joint smoothing, in one process.

    PYTHONPATH=build/python /usr/bin/python3 benchmark/label_map_speed.py [--runs 3]
        [--threads 2] [--maps aal harvard_oxford jhu aicha liver]
        [--liver build/cgal_demo_data/images/liver.inr.gz]

The maps: four atlases of Debian's mricron-data (/usr/share/mricron/templates) and CGAL's demo
CT segmentation ``liver.inr.gz`` (benchmark/get_demo_meshes.sh puts it in
build/cgal_demo_data/images); a map whose file is missing is skipped with a line saying so.

Ours: ``cf.label_surfaces(labels, affine=affine)`` with its defaults (surface nets, then the
fairing of all interfaces at once within the voxel boxes), timed from the array to the faired
points; the nets alone (``fair=False``) are timed too, so that the fairing's share shows, and
the call is split by its progress callback into what precedes the end of the first iteration
(the nets, the input's checks, the objective's set-up, the smoothed start), the iterations
after it, and what follows the last (the crossings' repair, the report); "without the
iterations" is the call's time less the iterations', over Slicer's time: the ratio no
reduction of the iterations alone can go below.

Slicer's: what 3D Slicer runs to make a segmentation's closed surfaces with joint smoothing
(vtkBinaryLabelmapToClosedSurfaceConversionRule): VTK's discrete flying edges over every label
at once, then 20 iterations of windowed sinc with Slicer's default smoothing factor 0.5 (pass
band 10^(-4 x 0.5)), non-manifold smoothing on, normalized coordinates, boundary and feature
edge smoothing off; timed from the array to the smoothed points. Where python3-vtk9 is not
installed, its column is skipped and ours is still printed.

Both on ``--threads`` threads (TBB's for ours, vtkSMPTools' for VTK's); the median of
``--runs`` runs, each map's runs one after the other. The CPU model and the threads are printed
with the figures.
"""

import argparse
import os
import platform
import statistics
import sys
import time
from pathlib import Path

import numpy as np

import cgal_constrained_fairing as cf
from benchmark_machine import cpu_model, median_seconds

ROOT = Path(__file__).resolve().parents[1]
TEMPLATES = Path("/usr/share/mricron/templates")
MAPS = {
    "aal": ("AAL", TEMPLATES / "aal.nii.gz"),
    "harvard_oxford": ("HarvardOxford cortical", TEMPLATES / "HarvardOxford-cort-maxprob-thr0-1mm.nii.gz"),
    "jhu": ("JHU white matter", TEMPLATES / "JHU-WhiteMatter-labels-1mm.nii.gz"),
    "aicha": ("AICHA", TEMPLATES / "AICHAmc.nii.gz"),
    "liver": ("CGAL's liver.inr.gz", ROOT / "build" / "cgal_demo_data" / "images" / "liver.inr.gz"),
}
SLICER_ITERATIONS = 20
SLICER_SMOOTHING_FACTOR = 0.5


def ours_in_phases(labels, affine, runs):
    """`label_surfaces`' median time, split at its first and last iteration (medians of each
    part), and the last call's result."""
    parts, result = [], None
    for _ in range(runs):
        marks = []

        def progress(iteration, energy):
            marks.append(time.perf_counter())
        start = time.perf_counter()
        result = cf.label_surfaces(labels, affine=affine, progress=progress)
        end = time.perf_counter()
        parts.append((end - start, marks[0] - start, marks[-1] - marks[0], end - marks[-1]))
    return [statistics.median(p[k] for p in parts) for k in range(4)], result


def load_vtk(threads):
    """VTK's modules, or None without python3-vtk9."""
    try:
        from vtkmodules.util import numpy_support
        from vtkmodules.vtkCommonCore import vtkSMPTools
        from vtkmodules.vtkCommonDataModel import vtkImageData
        from vtkmodules.vtkFiltersCore import vtkWindowedSincPolyDataFilter
        from vtkmodules.vtkFiltersGeneral import vtkDiscreteFlyingEdges3D
    except ImportError:
        return None
    vtkSMPTools.Initialize(threads)
    return dict(numpy_support=numpy_support, vtkImageData=vtkImageData,
                vtkWindowedSincPolyDataFilter=vtkWindowedSincPolyDataFilter,
                vtkDiscreteFlyingEdges3D=vtkDiscreteFlyingEdges3D)


def slicer_joint_smoothing(vtk, labels, spacing):
    """Slicer's closed surfaces with joint smoothing: points and triangles of every label."""
    image = vtk["vtkImageData"]()
    image.SetDimensions(*labels.shape)
    image.SetSpacing(*spacing)
    # VTK's images run x fastest: numpy's Fortran order of an (I, J, K) array.
    scalars = vtk["numpy_support"].numpy_to_vtk(np.ravel(labels, order="F"), deep=True)
    image.GetPointData().SetScalars(scalars)
    nets = vtk["vtkDiscreteFlyingEdges3D"]()
    nets.SetInputData(image)
    for index, label in enumerate(np.unique(labels)[1:]):
        nets.SetValue(index, float(label))
    nets.ComputeGradientsOff()
    nets.ComputeNormalsOff()
    nets.ComputeScalarsOn()
    smoother = vtk["vtkWindowedSincPolyDataFilter"]()
    smoother.SetInputConnection(nets.GetOutputPort())
    smoother.SetNumberOfIterations(SLICER_ITERATIONS)
    smoother.BoundarySmoothingOff()
    smoother.FeatureEdgeSmoothingOff()
    smoother.SetFeatureAngle(120.0)
    smoother.SetPassBand(10.0 ** (-4.0 * SLICER_SMOOTHING_FACTOR))
    smoother.NonManifoldSmoothingOn()
    smoother.NormalizeCoordinatesOn()
    smoother.Update()
    return smoother.GetOutput()


def measure(key, runs, vtk, liver):
    name, path = MAPS[key]
    if key == "liver" and liver is not None:
        path = Path(liver)
    if not path.exists():
        print(f"{name}: {path} missing, skipped")
        return None
    labels, affine = cf.read_label_map(path)
    spacing = np.linalg.norm(affine[:3, :3], axis=0)
    nets_s, _ = median_seconds(lambda: cf.label_surfaces(labels, affine=affine, fair=False), runs)
    (ours_s, before, descent, after), ours = ours_in_phases(labels, affine, runs)
    row = dict(name=name, faces=len(ours.faces), ours=ours_s, nets=nets_s, before=before,
               descent=descent, after=after, iterations=ours.report.number_of_iterations)
    if vtk is not None:
        row["slicer"], smoothed = median_seconds(lambda: slicer_joint_smoothing(vtk, labels, spacing), runs)
        row["slicer_faces"] = smoothed.GetNumberOfPolys()
    return row


def print_table(rows, with_slicer):
    print("| map | faces (ours) | ours | of which nets | to the first iteration | iterations after it "
          "| after the last | iterations | Slicer's pipeline | faces (Slicer's) | ratio "
          "| ratio without the iterations |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        fixed = r["ours"] - r["descent"]
        slicer = (f"{r['slicer']:.2f} s | {r['slicer_faces']:,} | {r['ours'] / r['slicer']:.1f}x | "
                  f"{fixed / r['slicer']:.1f}x" if with_slicer else "not measured | | | ")
        print(f"| {r['name']} | {r['faces']:,} | {r['ours']:.2f} s | {r['nets']:.2f} s | "
              f"{r['before']:.2f} s | {r['descent']:.2f} s | {r['after']:.2f} s | "
              f"{r['iterations']} | {slicer} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--maps", nargs="+", choices=list(MAPS), default=list(MAPS))
    parser.add_argument("--liver", help="CGAL's liver.inr.gz, if not in build/cgal_demo_data/images")
    args = parser.parse_args()
    cf.set_max_threads(args.threads)
    vtk = load_vtk(args.threads)
    print(f"{cpu_model()}, {os.cpu_count()} cores; {args.threads} threads (TBB, vtkSMPTools); "
          f"median of {args.runs} runs; Python {platform.python_version()}")
    if vtk is None:
        print("python3-vtk9 not installed: Slicer's pipeline not measured")
    rows = [row for row in (measure(key, args.runs, vtk, args.liver) for key in args.maps) if row]
    print_table(rows, vtk is not None)
    return 0


if __name__ == "__main__":
    sys.exit(main())
