// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Multi-label surface nets and each label's surface, on label maps made here: three labels of a
// ball (two halves and a cap, which meet along triple lines and at points where four labels meet,
// the outside included), a label against the array's side, and labels whose voxels touch only
// along an edge or at a corner; cubic voxels and 1 x 1 x 3 ones. Checked:
//  - every point is the centre of its dual cell, and each triangle separates its two labels with
//    its normal from the first into the second (a point just behind it lies in a voxel of the
//    first label, just in front of it in one of the second);
//  - each label's surface is a closed, valid, outward-oriented mesh (positive volume) whose
//    vertices are the shared points bit for bit, made of every triangle that names the label;
//    its triangles meet only at copies of a point where it was split, and the ball's halves
//    not at all;
//  - a label whose voxels touch along an edge or at a corner gets a manifold surface of two
//    sheets; a background other than 0 gets no surface of its own.

#include "test_support.h"

#include <CGAL/Polygon_mesh_processing/label_surface.h>
#include <CGAL/Polygon_mesh_processing/label_surface_nets.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/helpers.h>

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <utility>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
using test::Mesh;
using test::Point;
using Triangle = std::array<std::size_t, 3>;
using Label = std::int16_t;

Eigen::Vector3d vec(const Point& p) { return {p.x(), p.y(), p.z()}; }

struct Label_map
{
  std::array<std::size_t, 3> size;
  std::array<double, 3> spacing, origin;
  std::vector<Label> labels;

  Label at(long i, long j, long k) const
  {
    if(i < 0 || j < 0 || k < 0 || i >= long(size[0]) || j >= long(size[1]) || k >= long(size[2]))
      return -1; // outside
    return labels[(std::size_t(i) * size[1] + std::size_t(j)) * size[2] + std::size_t(k)];
  }
  // The label of the voxel that holds p, -1 outside the array.
  Label at(const Eigen::Vector3d& p) const
  {
    long v[3];
    for(int c = 0; c < 3; ++c)
      v[c] = std::lround((p[c] - origin[std::size_t(c)]) / spacing[std::size_t(c)]);
    return at(v[0], v[1], v[2]);
  }
};

// Labels 1 and 2 (the halves x < 0 and x >= 0 of a ball), 3 (a cap on the ball where z > 0),
// 4 (a slab against the side i = 0), 5 (two voxels that touch along an edge) and 6 (two that
// touch at a corner).
Label_map phantom(std::array<double, 3> spacing)
{
  Label_map map{{28, 28, 28 / std::size_t(spacing[2])}, spacing, {0, 0, 0}, {}};
  map.labels.assign(map.size[0] * map.size[1] * map.size[2], 0);
  const double c = 13.5;
  for(std::size_t i = 0; i < map.size[0]; ++i)
    for(std::size_t j = 0; j < map.size[1]; ++j)
      for(std::size_t k = 0; k < map.size[2]; ++k)
      {
        const double x = double(i) - c, y = double(j) - c, z = double(k) * spacing[2] - c;
        const double r = std::sqrt(x * x + y * y + z * z);
        Label& l = map.labels[(i * map.size[1] + j) * map.size[2] + k];
        if(r < 8)
          l = x < 0 ? 1 : 2;
        else if(r < 10.5 && z > 1)
          l = 3;
        else if(i == 0 && j > 4 && j < 20)
          l = 4;
      }
  const auto set = [&](std::size_t i, std::size_t j, std::size_t k, Label l) {
    map.labels[(i * map.size[1] + j) * map.size[2] + k] = l;
  };
  set(24, 2, 2, 5);
  set(25, 3, 2, 5);
  set(24, 24, 2, 6);
  set(25, 25, 3, 6);
  return map;
}

void check(const Label_map& map, Label background)
{
  std::vector<Point> points;
  std::vector<Triangle> triangles;
  std::vector<std::array<Label, 2> > face_labels;
  PMP::label_surface_nets(map.labels.data(), map.size, map.spacing, map.origin, points, triangles, face_labels,
                          background);
  CHECK(!triangles.empty() && triangles.size() == face_labels.size());

  // Points at cell centres: half a voxel off the voxel grid on every axis.
  for(const Point& p : points)
    for(int c = 0; c < 3; ++c)
    {
      const double t = (p[c] - map.origin[std::size_t(c)]) / map.spacing[std::size_t(c)];
      CHECK(t - std::floor(t) == 0.5);
    }
  // Each triangle between its labels, its normal from the first into the second.
  const auto outside_is = [&](Label l) { return l == -1 ? background : l; };
  const double step = 0.25 * std::min({map.spacing[0], map.spacing[1], map.spacing[2]});
  for(std::size_t f = 0; f < triangles.size(); ++f)
  {
    const Eigen::Vector3d a = vec(points[triangles[f][0]]), b = vec(points[triangles[f][1]]),
                          c = vec(points[triangles[f][2]]);
    const Eigen::Vector3d n = (b - a).cross(c - a).normalized(), centroid = (a + b + c) / 3;
    CHECK(face_labels[f][0] != face_labels[f][1]);
    CHECK(outside_is(map.at(centroid - step * n)) == face_labels[f][0]);
    CHECK(outside_is(map.at(centroid + step * n)) == face_labels[f][1]);
  }

  for(Label label = 0; label <= 6; ++label)
  {
    std::size_t naming = 0;
    for(const auto& pair : face_labels)
      naming += pair[0] == label || pair[1] == label;
    Mesh mesh;
    std::vector<std::size_t> origin;
    const std::size_t made = PMP::label_surface(points, triangles, face_labels, label, mesh, &origin);
    CHECK(made == naming && mesh.number_of_faces() == naming);
    if(label == background)
    {
      CHECK(naming > 0); // the outside of every surface, with none of its own
      continue;
    }
    CHECK(naming > 0);
    CHECK(CGAL::is_valid_polygon_mesh(mesh) && CGAL::is_closed(mesh) && CGAL::is_triangle_mesh(mesh));
    CHECK(PMP::volume(mesh) > 0);
    CHECK(origin.size() == mesh.number_of_vertices());
    for(auto v : mesh.vertices())
      CHECK(origin[v.idx()] < points.size() && mesh.point(v) == points[origin[v.idx()]]);
    if(label == 0) // the former outside: a box with the other labels' holes
      continue;
    const std::size_t sheets = PMP::connected_components(
      mesh, mesh.add_property_map<Mesh::Face_index, std::size_t>("f:component", 0).first);
    CHECK(sheets == (label >= 5 ? 2u : 1u));
    // Triangles meet only where the surface was split: at copies of one point.
    std::vector<std::pair<Mesh::Face_index, Mesh::Face_index> > crossing;
    PMP::self_intersections(mesh, std::back_inserter(crossing));
    for(const auto& faces : crossing)
    {
      bool touching = false;
      for(auto u : CGAL::vertices_around_face(mesh.halfedge(faces.first), mesh))
        for(auto w : CGAL::vertices_around_face(mesh.halfedge(faces.second), mesh))
          touching = touching || mesh.point(u) == mesh.point(w);
      CHECK(touching);
    }
    if(label <= 2)
      CHECK(crossing.empty());
  }
}

int main()
{
  for(const std::array<double, 3> spacing : {std::array<double, 3>{1, 1, 1}, std::array<double, 3>{1, 1, 3}})
  {
    Label_map map = phantom(spacing);
    check(map, 0);
    // Another background: label 3 becomes the outside, and 0 a label with its own surface.
    for(Label& l : map.labels)
      l = l == 3 ? 0 : l == 0 ? 3 : l;
    check(map, 3);
  }
  return test::report("test_label_surfaces");
}
