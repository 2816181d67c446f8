// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What users judge a faired noisy mesh by, when its clean original (same connectivity) is known:
// the bound as they check it, in double; the RMS distance of the vertices to the clean
// *surface* (sliding along the surface is harmless); the mean angle between corresponding face
// normals; the smallest triangle angle; and the folds, faces whose normal is more than 90
// degrees from the clean one, with those of them at the clean mesh's own creases (a face with
// a neighbour more than 90 degrees away), where no smooth surface keeps the clean normals.

#ifndef CGAL_CONSTRAINED_FAIRING_BENCHMARK_SURFACE_QUALITY_H
#define CGAL_CONSTRAINED_FAIRING_BENCHMARK_SURFACE_QUALITY_H

#include "benchmark_support.h"
#include "../test/triangle_tree.h"

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Bending_energy.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace benchmark {

using Tree = test::Triangle_tree<K, Mesh>;

struct Quality
{
  double max_distance = 0;   // Euclidean, to the input position
  double max_coordinate = 0; // largest per-coordinate offset
  bool ball_holds = true, box_holds = true;
  double energy = 0, surface_rms = 0, normal_error_deg = 0, min_angle_deg = 180;
  std::size_t folds = 0, folds_at_creases = 0;
};

// The clean mesh's distance tree, its face normals, and its faces at creases sharper than 90
// degrees.
struct Clean_surface
{
  Tree tree;
  std::vector<K::Vector_3> normal; // by face index
  std::vector<bool> at_crease;     // by face index
  std::size_t creased_faces = 0;

  explicit Clean_surface(const Mesh& clean)
      : tree(faces(clean).first, faces(clean).second, clean), at_crease(num_faces(clean), false)
  {
    tree.accelerate_distance_queries();
    for(auto f : faces(clean))
      normal.push_back(CGAL::Polygon_mesh_processing::compute_face_normal(f, clean));
    for(auto f : faces(clean))
    {
      for(auto h : halfedges_around_face(halfedge(f, clean), clean))
      {
        const auto g = face(opposite(h, clean), clean);
        if(g != boost::graph_traits<Mesh>::null_face() && normal[f.idx()] * normal[g.idx()] < 0)
          at_crease[f.idx()] = true;
      }
      creased_faces += at_crease[f.idx()];
    }
  }
};

// The paper's bending energy of `result` over all its hinges, creases included, as the default
// call measures it from `input` (same connectivity): a call with creases reports its energy
// without the hinges across them.
inline double bending_energy(const Mesh& result, const Mesh& input)
{
  namespace CF = CGAL::Polygon_mesh_processing::internal::Constrained_fairing;
  CF::Points X0(num_vertices(input), 3), X(num_vertices(result), 3);
  for(auto v : vertices(input))
  {
    const Point &p = input.point(v), &q = result.point(v);
    X0.row(v.idx()) << p.x(), p.y(), p.z();
    X.row(v.idx()) << q.x(), q.y(), q.z();
  }
  const CF::Hinge_mesh mesh(input, get(CGAL::vertex_index, input));
  CF::Bending_energy energy(mesh, X0);
  return energy.value(X);
}

// `result` and `input` have the clean mesh's connectivity; `eps` is the bound checked.
inline Quality measure(const Mesh& result, const Mesh& input, const Clean_surface& clean, double eps, double energy)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  Quality q;
  q.energy = energy;
  double sum2 = 0;
  for(auto v : vertices(result))
  {
    const Point& p = result.point(v);
    const Point& p0 = input.point(v);
    const double d2 = CGAL::squared_distance(p, p0);
    q.max_distance = (std::max)(q.max_distance, std::sqrt(d2));
    q.ball_holds = q.ball_holds && d2 <= eps * eps && std::sqrt(d2) <= eps;
    for(int c = 0; c < 3; ++c)
    {
      const double dc = std::abs(p[c] - p0[c]);
      q.max_coordinate = (std::max)(q.max_coordinate, dc);
      q.box_holds = q.box_holds && dc <= eps;
    }
    sum2 += clean.tree.squared_distance(p);
  }
  q.surface_rms = std::sqrt(sum2 / double(num_vertices(result)));

  double normal_sum = 0;
  for(auto f : faces(result))
  {
    const auto n = PMP::compute_face_normal(f, result);
    const auto& n_clean = clean.normal[f.idx()];
    normal_sum += angle_deg(n, n_clean);
    if(n * n_clean < 0)
    {
      ++q.folds;
      q.folds_at_creases += clean.at_crease[f.idx()];
    }
  }
  q.normal_error_deg = normal_sum / double(num_faces(result));
  q.min_angle_deg = smallest_angle_deg(result);
  return q;
}

// A result against a reference result from the same input (same connectivity): how far the
// iterations that produced the reference would still have moved it.
struct Agreement
{
  double distance_rms = 0;   // each vertex of one to the other surface, both ways
  double normal_difference_deg = 0; // mean angle between corresponding face normals
};

inline double squared_distances_to(const Mesh& from, const Mesh& to)
{
  Tree tree(faces(to).first, faces(to).second, to);
  tree.accelerate_distance_queries();
  double sum = 0;
  for(auto v : vertices(from))
    sum += tree.squared_distance(from.point(v));
  return sum;
}

inline Agreement compare(const Mesh& result, const Mesh& reference)
{
  Agreement a;
  a.distance_rms = std::sqrt((squared_distances_to(result, reference) + squared_distances_to(reference, result)) /
                             double(2 * num_vertices(result)));
  double normal_sum = 0;
  for(auto f : faces(result))
    normal_sum += angle_deg(CGAL::Polygon_mesh_processing::compute_face_normal(f, result),
                            CGAL::Polygon_mesh_processing::compute_face_normal(f, reference));
  a.normal_difference_deg = normal_sum / double(num_faces(result));
  return a;
}

// Whether every vertex of `result` lies within `eps` of its position in `input`, in double.
inline bool ball_holds(const Mesh& result, const Mesh& input, double eps)
{
  for(auto v : vertices(result))
  {
    const double d2 = CGAL::squared_distance(result.point(v), input.point(v));
    if(!(d2 <= eps * eps && std::sqrt(d2) <= eps))
      return false;
  }
  return true;
}

} // namespace benchmark

#endif // CGAL_CONSTRAINED_FAIRING_BENCHMARK_SURFACE_QUALITY_H
