#!/usr/bin/env python3
"""The outputs of a build, as hashes, to hold a change that must not move a bit against the code before it.

    PYTHONPATH=build/python /usr/bin/python3 benchmark/output_hashes.py OUT.json [--tool build/tools/constrained_fairing]
        [--compare BEFORE.json] [--quick] [--bunny ../shared/data/bunny00_d0.25.off] [--liver data/images/liver.inr.gz]

Fairs, and hashes the points and reports of:
- the bundled noisy elephant and, where given and present, the shared noisy bunny, in 12 settings (default, box, box
  half-extents, accurate, tangential motion, a region, per-vertex tolerances, fixed vertices, creases, both paper
  methods);
- generated label maps (checkerboards, random voxels on cubic voxels and thick slices, a ball cut by a plane, a small
  block between two labels) through ``label_surfaces``;
- without --quick: the nine atlases of Debian's mricron-data (skipped where absent), and through the tool a mesh and,
  where given and present, CGAL's demo liver (``libcgal-demo``'s ``data.tar.gz``, extracted).
With --compare, prints the cases whose hashes differ from BEFORE.json's and exits 1 if any does.
"""

import argparse
import hashlib
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

import cgal_constrained_fairing as cf

ROOT = Path(__file__).resolve().parent.parent
ATLASES = ["aal", "AICHAmc", "brodmann", "HarvardOxford-cort-maxprob-thr0-1mm", "JHU-WhiteMatter-labels-1mm",
           "JHU-WhiteMatter-labels-2mm", "jhu189", "natbrainlab", "inia19-NeuroMaps"]


def digest(*arrays):
    h = hashlib.sha256()
    for a in arrays:
        h.update(np.ascontiguousarray(a).tobytes())
    return h.hexdigest()[:16]


def report_of(r):
    if r is None:
        return None
    return [str(r.status), int(r.number_of_iterations), int(r.number_of_energy_evaluations),
            float(r.final_energy).hex(), float(r.final_bending_energy).hex(), float(r.max_deviation).hex(),
            int(r.number_of_vertices_at_bound), int(r.number_of_fixed_vertices), int(r.number_of_folded_faces),
            int(r.number_of_feature_edges)]


def mesh_cases(path, out):
    V, F = cf.read_mesh(path)
    eps = 0.25 * cf.mean_edge_length(V, F)
    rng = np.random.default_rng(7)
    cases = {
        "default": {}, "box": dict(bound="box"), "accurate": dict(objective="accurate"),
        "tangential": dict(tangential_motion=True), "region": dict(region=np.arange(len(F) // 3)),
        "tolerance": dict(tolerance=eps * rng.uniform(0.2, 1.0, len(V))), "fixed": dict(fixed=np.arange(0, len(V), 17)),
        "creases": dict(feature_angle=30), "newton": dict(method="active_set_newton", max_iterations=20),
        "gradient": dict(method="projected_gradient", max_iterations=30),
        "box_extents": dict(box_half_extents=[eps, 0.5 * eps, eps]),
    }
    for case, keywords in cases.items():
        W, r = cf.fair(V, F, eps, **keywords)
        out[f"{Path(path).stem}/{case}"] = [digest(W), report_of(r)]


def generated_maps():
    def grid(size, f):
        i, j, k = np.indices(size)
        return f(i, j, k).astype(np.int32)

    ball = lambda i, j, k: np.where((i - 23.5) ** 2 + (j - 23.5) ** 2 + (3 * k - 23.5) ** 2 < 18 ** 2,
                                    np.where(i + 0.3 * j > 30, 2, 1), 0)
    block = lambda i, j, k: np.where((abs(i - 10) <= 1) & (abs(j - 10) <= 1) & (abs(k - 10) <= 1), 3,
                                     np.where(i < 10, 1, 2))
    return {
        "checker2": (grid((12, 12, 12), lambda i, j, k: (i + j + k) % 2 + 1), (1, 1, 1)),
        "checker3": (grid((12, 12, 12), lambda i, j, k: (i + j + k) % 3 + 1), (1, 1, 1)),
        "random4": (np.random.default_rng(3).integers(0, 5, (14, 14, 14)).astype(np.int32), (1, 1, 1)),
        "random_slices": (np.random.default_rng(4).integers(0, 3, (14, 14, 6)).astype(np.int32), (1, 1, 3)),
        "ball_plane": (grid((48, 48, 16), ball), (1, 1, 3)),
        "small_block": (grid((20, 20, 20), block), (1, 1, 1)),
    }


def map_cases(out, quick):
    for name, (labels, spacing) in generated_maps().items():
        S = cf.label_surfaces(labels, spacing=spacing)
        out[f"map/{name}"] = [digest(S.vertices, S.faces, S.face_labels, S.box_half_extents), report_of(S.report)]
    templates = Path("/usr/share/mricron/templates")
    if quick or not templates.is_dir():
        return
    for atlas in ATLASES:
        labels, affine = cf.read_label_map(templates / f"{atlas}.nii.gz")
        S = cf.label_surfaces(labels, affine=affine)
        out[f"atlas/{atlas}"] = [digest(S.vertices, S.faces, S.face_labels), report_of(S.report)]


def tool_cases(tool, liver, out):
    elephant = str(ROOT / "data" / "elephant_noisy.off")
    with tempfile.TemporaryDirectory() as folder:
        runs = [["--eps", "0.25h", elephant, f"{folder}/e.ply"], ["--feature-angle", "30", "--box", elephant,
                                                                   f"{folder}/e2.off"]]
        if liver and Path(liver).is_file():
            runs.append([liver, f"{folder}/liver"])
        for arguments in runs:
            subprocess.run([tool] + arguments, check=True, capture_output=True)
        for path in sorted(Path(folder).rglob("*")):
            if path.is_file():
                out[f"tool/{path.relative_to(folder)}"] = hashlib.sha256(path.read_bytes()).hexdigest()[:16]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--tool", default=str(ROOT / "build" / "tools" / "constrained_fairing"))
    parser.add_argument("--compare")
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--bunny", default=str(ROOT.parent / "shared" / "data" / "bunny00_d0.25.off"))
    parser.add_argument("--liver")
    arguments = parser.parse_args()
    out = {}
    mesh_cases(str(ROOT / "data" / "elephant_noisy.off"), out)
    if Path(arguments.bunny).is_file():
        mesh_cases(arguments.bunny, out)
    map_cases(out, arguments.quick)
    if not arguments.quick:
        tool_cases(arguments.tool, arguments.liver, out)
    Path(arguments.out).write_text(json.dumps(out, indent=1, sort_keys=True))
    if not arguments.compare:
        print(f"{len(out)} cases")
        return 0
    before = json.loads(Path(arguments.compare).read_text())
    differ = [case for case in out if before.get(case) != out[case]]
    for case in differ:
        print(f"differs: {case}")
    print(f"{len(out)} cases compared, {len(differ)} differ")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
