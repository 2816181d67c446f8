// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Multi-label surface nets and each label's surface, on label maps made here: three labels of a
// ball (two halves and a cap, which meet along triple lines and at points where four labels meet,
// the outside included), a label against the array's side, labels whose voxels touch only along
// an edge or at a corner, in every orientation, and worst cases: checkerboards of two and three
// labels, one-voxel tubes along every diagonal, tilted one-voxel sheets, a label that meets itself
// around an edge, cells of real segmentations that need a junction point, quarter boxes or rings
// split where two labels are pinched, blocks of them whose points need untangling or whose faces'
// polygons need a search for their ears or, along a junction line, the least folded cut, random
// voxels; cubic voxels and 1 x 1 x 3 ones. Checked:
//  - every point's box lies in its dual cell, `label_box_margin` of the spacing from its sides,
//    and no two boxes meet; a point off its cell's centre has a box smaller than the cell's;
//  - each triangle separates its two labels with its normal from the first into the second (a
//    point just behind it lies in a voxel of the first label, just in front of it in one of the
//    second);
//  - each label's surface is a closed, valid, outward-oriented mesh (positive volume) whose
//    vertices are the shared points bit for bit, made of every triangle that names the label;
//  - on every map, each label's surface is a manifold as the nets make it (label_surface()
//    splits no point), it does not intersect itself and no two triangles of the soup pass
//    through each other, also on blocks of cortical atlases whose triangles do with every point
//    at the centre of its box and on random voxels of 3 and 5 labels, whose triangles the rounds
//    of the untangling alone leave crossing;
//  - a label whose voxels touch along an edge or at a corner gets two sheets; a background other
//    than 0 gets no surface of its own;
//  - in cells where two labels touch themselves (of atlases, and two that share a ring): no
//    label split;
//  - the untangling alone, on a patch whose triangles fold: no crossing left, every point and its
//    new box within the box it had;
//  - nets appended to a soup already there are the same, their indices shifted;
//  - the nets of a box of a map (`first_voxel`): the points of the cells 10 voxels or more from
//    its cut side are the whole map's, bit for bit.

#include "test_support.h"

#include <CGAL/Polygon_mesh_processing/label_surface.h>
#include <CGAL/Polygon_mesh_processing/label_surface_nets.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Dual_cell.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_interfaces/Triangle_crossings.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/box_intersection_d.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
using test::Mesh;
using test::Point;
using Triangle = std::array<std::size_t, 3>;
using Label = std::int16_t;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;

Eigen::Vector3d vec(const Point& p) { return {p.x(), p.y(), p.z()}; }

struct Label_map
{
  std::array<std::size_t, 3> size;
  std::array<double, 3> spacing, origin;
  std::vector<Label> labels;
  std::set<Label> two_sheets; // labels whose voxels touch only along an edge or at a corner

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
  Label_map map{{28, 28, 28 / std::size_t(spacing[2])}, spacing, {0, 0, 0}, {}, {}};
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
  map.two_sheets = {5, 6};
  return map;
}

// How many times the closed mesh winds around q: its triangles' solid angles seen from q, over 4 pi
// (A. Van Oosterom and J. Strackee, 1983).
double winding_number(const Mesh& mesh, const Eigen::Vector3d& q)
{
  double sum = 0;
  for(auto f : mesh.faces())
  {
    Eigen::Vector3d r[3];
    int k = 0;
    for(auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      r[k++] = vec(mesh.point(v)) - q;
    const double l0 = r[0].norm(), l1 = r[1].norm(), l2 = r[2].norm();
    sum += 2 * std::atan2(r[0].dot(r[1].cross(r[2])),
                          l0 * l1 * l2 + r[0].dot(r[1]) * l2 + r[1].dot(r[2]) * l0 + r[2].dot(r[0]) * l1);
  }
  return sum / (4 * CGAL_PI);
}

void check(const Label_map& map, Label background)
{
  std::vector<Point> points;
  std::vector<Triangle> triangles;
  std::vector<std::array<Label, 2> > face_labels;
  std::vector<std::array<double, 3> > half;
  PMP::label_surface_nets(map.labels.data(), map.size, map.spacing, map.origin, points, triangles, face_labels, half,
                          background);
  CHECK(!triangles.empty() && triangles.size() == face_labels.size() && half.size() == points.size());

  // Each box in its dual cell (which spans [c - 1, c] in voxels from the origin), the margin
  // from its sides; the boxes apart.
  std::vector<Box> boxes;
  std::vector<bool> at_centre(points.size());
  for(std::size_t p = 0; p < points.size(); ++p)
  {
    double lo[3], hi[3];
    bool centre = true;
    for(std::size_t c = 0; c < 3; ++c)
    {
      const double s = map.spacing[c], t = (points[p][int(c)] - map.origin[c]) / s, cell = std::floor(t);
      lo[c] = points[p][int(c)] - half[p][c];
      hi[c] = points[p][int(c)] + half[p][c];
      CHECK(half[p][c] > 0);
      CHECK((lo[c] - map.origin[c]) / s >= cell + PMP::label_box_margin - 1e-12);
      CHECK((hi[c] - map.origin[c]) / s <= cell + 1 - PMP::label_box_margin + 1e-12);
      centre = centre && t - cell == 0.5;
    }
    at_centre[p] = centre;
    if(!centre) // a part of the cell
      CHECK(half[p][0] < map.spacing[0] * (0.5 - PMP::label_box_margin) ||
            half[p][1] < map.spacing[1] * (0.5 - PMP::label_box_margin) ||
            half[p][2] < map.spacing[2] * (0.5 - PMP::label_box_margin));
    boxes.emplace_back(CGAL::Bbox_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]), p);
  }
  std::size_t meeting = 0;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box&, const Box&) { ++meeting; });
  CHECK(meeting == 0);

  // No two triangles of the soup pass through each other, of one label's surface or of two.
  {
    namespace CF = PMP::internal::Constrained_fairing;
    std::vector<std::array<CF::Index, 3> > soup;
    for(const Triangle& t : triangles)
      soup.push_back({CF::Index(t[0]), CF::Index(t[1]), CF::Index(t[2])});
    CF::Points X(static_cast<Eigen::Index>(points.size()), 3);
    for(std::size_t p = 0; p < points.size(); ++p)
      CF::point(X, p) = vec(points[p]);
    const std::vector<bool> crossing = CF::Triangle_crossings(soup).find(X, {});
    CHECK(std::find(crossing.begin(), crossing.end(), true) == crossing.end());
  }

  // Each triangle between its labels, its normal from the first into the second.
  const auto outside_is = [&](Label l) { return l == -1 ? background : l; };
  const double step = 0.25 * std::min({map.spacing[0], map.spacing[1], map.spacing[2]});
  for(std::size_t f = 0; f < triangles.size(); ++f)
  {
    CHECK(face_labels[f][0] != face_labels[f][1]);
    if(!(at_centre[triangles[f][0]] && at_centre[triangles[f][1]] && at_centre[triangles[f][2]]))
      continue; // in a cell of several points: the volume of each sheet below tells
    const Eigen::Vector3d a = vec(points[triangles[f][0]]), b = vec(points[triangles[f][1]]),
                          c = vec(points[triangles[f][2]]);
    const Eigen::Vector3d n = (b - a).cross(c - a).normalized(), centroid = (a + b + c) / 3;
    CHECK(outside_is(map.at(centroid - step * n)) == face_labels[f][0]);
    CHECK(outside_is(map.at(centroid + step * n)) == face_labels[f][1]);
  }

  std::set<Label> labels;
  for(const auto& pair : face_labels)
    labels.insert(pair.begin(), pair.end());
  for(Label label : labels)
  {
    std::size_t naming = 0;
    for(const auto& pair : face_labels)
      naming += pair[0] == label || pair[1] == label;
    Mesh mesh;
    std::vector<std::size_t> origin;
    const std::size_t made = PMP::label_surface(points, triangles, face_labels, label, mesh, &origin);
    CHECK(made == naming && mesh.number_of_faces() == naming && naming > 0);
    if(label == background) // the outside of every surface, with none of its own
      continue;
    CHECK(CGAL::is_valid_polygon_mesh(mesh) && CGAL::is_closed(mesh) && CGAL::is_triangle_mesh(mesh));
    CHECK(PMP::volume(mesh) > 0);
    CHECK(origin.size() == mesh.number_of_vertices());
    for(auto v : mesh.vertices())
      CHECK(origin[v.idx()] < points.size() && mesh.point(v) == points[origin[v.idx()]]);
    // Outward, sheet by sheet: on a small map, the surface winds once around each voxel centre
    // of the label and not around the others; on a larger one, each sheet holds a triangle of
    // cells of one point, whose side the voxels told, and its triangles are oriented alike.
    auto component = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:c", 0).first;
    const std::size_t sheets = PMP::connected_components(mesh, component);
    if(map.labels.size() <= 4096)
      for(long i = 0; i < long(map.size[0]); ++i)
        for(long j = 0; j < long(map.size[1]); ++j)
          for(long k = 0; k < long(map.size[2]); ++k)
          {
            const Eigen::Vector3d q(map.origin[0] + double(i) * map.spacing[0],
                                    map.origin[1] + double(j) * map.spacing[1],
                                    map.origin[2] + double(k) * map.spacing[2]);
            CHECK(std::abs(winding_number(mesh, q) - (map.at(i, j, k) == label ? 1 : 0)) < 0.5);
          }
    else
    {
      std::vector<bool> told(sheets, false);
      std::size_t face = 0;
      for(std::size_t f = 0; f < triangles.size(); ++f)
        if(face_labels[f][0] == label || face_labels[f][1] == label)
        {
          const bool centres = at_centre[triangles[f][0]] && at_centre[triangles[f][1]] && at_centre[triangles[f][2]];
          const std::size_t sheet = component[Mesh::Face_index(Mesh::size_type(face++))];
          told[sheet] = told[sheet] || centres;
        }
      CHECK(std::find(told.begin(), told.end(), false) == told.end());
    }
    if(map.two_sheets.count(label) > 0)
      CHECK(sheets == 2u);
    std::sort(origin.begin(), origin.end());
    CHECK(std::adjacent_find(origin.begin(), origin.end()) == origin.end());
    CHECK(!PMP::does_self_intersect(mesh));
  }
}

Label_map generated(std::array<std::size_t, 3> size, std::array<double, 3> spacing,
                    const std::function<Label(long, long, long)>& f)
{
  Label_map map{size, spacing, {0.5, -2, 3}, {}, {}};
  for(std::size_t i = 0; i < size[0]; ++i)
    for(std::size_t j = 0; j < size[1]; ++j)
      for(std::size_t k = 0; k < size[2]; ++k)
        map.labels.push_back(f(long(i), long(j), long(k)));
  return map;
}

// The untangling (Net_untangling.h) on a flat 3 x 3 patch whose centre point lies beyond its
// neighbours, in a box large enough to go back, so that its triangles fold over theirs; the patch
// after a point and a triangle already there, and a point of no triangle after it. Checked: the
// patch entered tangled, and leaves with no crossing, every point within the box it had, each
// new box within the old one and not empty; the points outside the patch keep their places and
// boxes.
void check_untangling()
{
  namespace CF = PMP::internal::Constrained_fairing;
  std::vector<Point> points = {Point(9, 9, 9)};
  std::vector<std::array<double, 3> > half = {{0.1, 0.1, 0.1}};
  std::vector<Triangle> triangles = {{0, 0, 0}};
  const auto at = [](std::size_t i, std::size_t j) { return 1 + 3 * i + j; };
  for(std::size_t i = 0; i < 3; ++i)
    for(std::size_t j = 0; j < 3; ++j)
    {
      const bool centre = i == 1 && j == 1;
      points.push_back(centre ? Point(2.5, 1.2, 0) : Point(double(i), double(j), 0));
      half.push_back(centre ? std::array<double, 3>{2, 2, 1} : std::array<double, 3>{0.1, 0.1, 0.1});
    }
  points.push_back(Point(-9, -9, -9));
  half.push_back({0.1, 0.1, 0.1});
  for(std::size_t i = 0; i < 2; ++i)
    for(std::size_t j = 0; j < 2; ++j)
    {
      triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  const auto crossings = [&]() {
    std::vector<std::array<CF::Index, 3> > patch;
    for(std::size_t f = 1; f < triangles.size(); ++f)
      patch.push_back({CF::Index(triangles[f][0] - 1), CF::Index(triangles[f][1] - 1), CF::Index(triangles[f][2] - 1)});
    CF::Points X(static_cast<Eigen::Index>(points.size() - 1), 3);
    for(std::size_t p = 1; p < points.size(); ++p)
      CF::point(X, p - 1) = vec(points[p]);
    const std::vector<bool> crossing = CF::Triangle_crossings(patch).find(X, {});
    return std::count(crossing.begin(), crossing.end(), true);
  };
  CHECK(crossings() > 0);
  const std::vector<Point> before = points;
  const std::vector<std::array<double, 3> > before_half = half;
  CF::untangle_nets(points, triangles, half, 1, 1, 1, std::vector<bool>(points.size() - 1, true));
  CHECK(crossings() == 0);
  for(std::size_t p = 0; p < points.size(); ++p)
    for(std::size_t c = 0; c < 3; ++c)
    {
      const double moved = std::abs(points[p][int(c)] - before[p][int(c)]);
      CHECK(moved <= before_half[p][c] && moved + half[p][c] <= before_half[p][c] + 1e-12 && half[p][c] > 0);
    }
  for(std::size_t p : {std::size_t(0), points.size() - 1})
    CHECK(points[p] == before[p] && half[p] == before_half[p]);
}

// Blocks of cortical atlases (natbrainlab, inia19; 6 x 6 x 6 voxels, labels renumbered) whose
// nets cross with every point at the centre of its box.
std::vector<std::string> tangled_blocks()
{
  return {"123111131111111111111113113343134344552133553333533111311111111111111114112222552233551333533333333111311111"
          "555122555552555212555133553333333334555552555522555522555511555522555512555525555555555555555555555555555555",
          "111022111022100222000222000222000222111122111022110222100222000222002222111122111022111222110222100222002222"
          "111112111122111022110222112222002222111112111122111122111222112222102222111112111122111122111222112222102222",
          "111122111122111122011122111222111222311122311122311122311122111222111222331122331122331122331422331522331222"
          "333122333152333422333522334522335222333422333422334522334222345222442222444522444522445222455222555222552222"};
}

// The worst cases.
std::vector<Label_map> worst_cases()
{
  std::vector<Label_map> cases;
  const auto inside = [](long i, long j, long k, long n) {
    return i >= 2 && j >= 2 && k >= 2 && i + 2 < n && j + 2 < n && k + 2 < n;
  };
  for(Label first : {0, 1})
    cases.emplace_back(generated({10, 10, 10}, {1, 1, 1}, [&](long i, long j, long k) {
                         return inside(i, j, k, 10) ? Label((i + j + k) % 2 + first) : Label(0);
                       }));
  cases.emplace_back(generated({10, 10, 10}, {1, 1, 1}, [&](long i, long j, long k) {
                       return inside(i, j, k, 10) ? Label((i + 2 * j + k) % 3 + 1) : Label(0);
                     }));
  // One-voxel tubes along the four space diagonals and six face diagonals.
  cases.emplace_back(generated({14, 14, 14}, {1, 1, 1}, [](long i, long j, long k) {
                       const bool space = (i == j && j == k) || (i == j && j == 13 - k) || (i == 13 - j && j == k) ||
                                          (13 - i == j && j == 13 - k);
                       const bool face = (k == 3 && (i == j || i == 13 - j)) || (j == 4 && (i == k || i == 13 - k)) ||
                                         (i == 10 && (j == k || j == 13 - k));
                       return space ? Label(1) : face ? Label(2) : Label(0);
                     }));
  // Tilted one-voxel sheets, crossing.
  cases.emplace_back(generated({16, 16, 16}, {1, 1, 1}, [](long i, long j, long k) {
                       return long(0.3 * double(i) + 0.5 * double(j)) + 4 == k ? Label(1)
                              : i + 2 * k == 24                                  ? Label(2)
                                                                                 : Label(0);
                     }));
  // Pairs of voxels that touch along an edge (6 orientations) or at a corner (4), and a label
  // that meets itself around an edge: two voxels diagonal in one layer, joined through the next.
  Label_map contacts = generated({20, 12, 12}, {1, 1, 3}, [](long i, long j, long k) {
                       const long d[10][3] = {{1, 1, 0}, {1, -1, 0}, {1, 0, 1}, {1, 0, -1}, {0, 1, 1},
                                              {0, 1, -1}, {1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {-1, 1, 1}};
                       for(long c = 0; c < 10; ++c)
                       {
                         const long x = 2 + 3 * (c % 5), y = c < 5 ? 3 : 8, z = 5;
                         if((i == x && j == y && k == z) || (i == x + d[c][0] && j == y + d[c][1] && k == z + d[c][2]))
                           return Label(c + 1);
                       }
                       const bool around = (k == 9 && ((i == 9 && j == 9) || (i == 10 && j == 10))) ||
                                           (k == 10 && i >= 9 && i <= 10 && j >= 9 && j <= 10 && !(i == 9 && j == 10));
                       return around ? Label(11) : Label(0);
                     });
  contacts.two_sheets = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
  cases.emplace_back(contacts);
  // Cells found in cortical atlases, with their neighbours (4 x 4 x 4 voxels, labels renumbered):
  // holes of a ridge that border several interfaces, capped around a junction point; two points
  // whose faces lie in one octant of their cell, their boxes a quarter of it apart; and a label
  // and the background each touching itself at the centre through a corner, two labels around
  // (their seeds tie together: rings of four labels are split).
  for(const char* cell : {"1114111414244424111411144424444411541124424444441145114534444444",
                          "3322333233323333321133313321333332113122321233322211321222223322",
                          "3344114411141111333333031114111122222223003010002222222222220333"})
    cases.emplace_back(generated({4, 4, 4}, {1, 1, 1},
                                 [cell](long i, long j, long k) { return Label(cell[16 * i + 4 * j + k] - '0'); }));
  // Blocks of 6 x 6 x 6 voxels, each label written as the character '0' + label.
  const auto block_map = [](const std::string& block) {
    return generated({6, 6, 6}, {1, 1, 1},
                     [&block](long i, long j, long k) { return Label(block[std::size_t(36 * i + 6 * j + k)] - '0'); });
  };
  for(const std::string& block : tangled_blocks())
    cases.emplace_back(block_map(block));
  // A block of inia19 (labels 1 to 16 as '1' to '@') with a face whose polygon, a corner of two
  // points next to a corner of one, a greedy cut of ears left with no ear of opposite cells: it
  // cut a triangle two faces of one label shared, and label_surface() split the label there.
  cases.emplace_back(block_map("122222112222311222311144335555635555227777122227812222339122"
                               "335522:33552229999829997882927382922:38922:33992827;;;822;;9"
                               "88<799:88<99:=82<9::389<=87;;;=88:;;:8877;:=822;::=82;::3882"
                               ":>8?;;:>88;;::@87;::@82;::@88;:::@88"));
  // A block of inia19 (labels 1 to 17 as '1' to 'A', 0 its background) with two faces that no
  // ears of opposite cells alone cut, along one junction line of three labels: the polygon's
  // first ear, taken for each, laid a triangle on three points of that line, and the two folded
  // onto each other (label 12's surface crossed itself).
  cases.emplace_back(block_map("1111231111245111446644445444444447781111121111121551145664445644449:;;<733111131111"
                               "1115514=>664499<<44<<;;<<?33111333111331564@99<9<9<<<<<<<<;<<??3311????11???996@9"
                               "<<<<0<<<<<<<<<<<A???31?????1A0?99<A0<<<<@<<<<<<<<<<<"));
  // Blocks of random voxels of 4 labels with faces that ears of opposite cells alone do not cut,
  // two of one label around a dual edge: the first ears of one left it only a triangle the other
  // had cut (label 1's surface held it twice), or the least folded cuts of both took the same
  // diagonal between neighbouring cells (an edge of four triangles of label 3).
  cases.emplace_back(block_map("013102121121200303311112013021011201111021230303231220201203122232022132"
                               "021301120320031021331211020202003322231233231323101322112310320200231012"
                               "220303333202222310033020010010231321101031001302203012333231323033100331"));
  cases.emplace_back(block_map("003223112130210301100230001333233012131313221332033021003231030301301302"
                               "310101332201110032021300031230300001002231300321320221020022301000201022"
                               "123120020300003022221130310330003231330033023220213213030231102011001333"));
  std::mt19937 random(7);
  for(int labels : {2, 3, 5})
    for(const std::array<double, 3> spacing : {std::array<double, 3>{1, 1, 1}, std::array<double, 3>{1, 1, 3}})
    {
      std::uniform_int_distribution<int> pick(0, labels - 1);
      cases.emplace_back(generated({9, 9, 9}, spacing, [&](long, long, long) { return Label(pick(random)); }));
    }
  return cases;
}

// Cells of real segmentations where two labels each touch themselves at the centre, with others
// around, so that their seeds tie together (4 x 4 x 4 voxels, labels renumbered): two of
// natbrainlab, one whose pinched labels the split rings' sheets part alone, one whose ridges need
// a seed too, and one of inia19 against the background; and random voxels of 5 labels where
// two such cells share a ring of four labels, which only the first of them may split. Before the
// rings were split and bridged, one label of each such cell was left touching itself, and
// label_surface() split it there. Checked: every label's surface is a manifold as the nets make
// it and does not intersect itself, besides the checks of every map; and on the first cell
// alone, a bridge per split ring, no split of a ring the cell before has split, and with every
// ring kept whole, no bridge and the fallback's ridge (one label left whole, the other parted).
void check_bridged_cells()
{
  const std::array<const char*, 3> cells = {"1111222122212221222122312111111144442444432543354444444444443334",
                                            "1222222222222223123022333455435543333545334333355554334533353335",
                                            "1111011000002200330044204520455533353355334566453335334733376664"};
  for(const char* cell : cells)
    check(generated({4, 4, 4}, {1, 1, 1},
                    [cell](long i, long j, long k) { return Label(cell[16 * i + 4 * j + k] - '0'); }),
          0);
  const std::string shared = "13304424210130411302331332243020113044134231001013001030431010010442440124002320443401"
                             "122343142433033041412232023243303203010";
  check(generated({5, 5, 5}, {1, 1, 1},
                  [&shared](long i, long j, long k) { return Label(shared[std::size_t(25 * i + 5 * j + k)] - '0'); }),
        0);

  // The cell's block is voxels 1 and 2 of the 4 along each axis.
  const auto label = [&cells](int d0, int d1, int d2) {
    const int i = d0 + 1, j = d1 + 1, k = d2 + 1;
    return i < 0 || j < 0 || k < 0 || i > 3 || j > 3 || k > 3 ? Label(0) : Label(cells[0][16 * i + 4 * j + k] - '0');
  };
  using Cell = PMP::internal::Constrained_fairing::Dual_cell<Label>;
  // Bit r set where ring r (half-axis: 2 axis + side) is split.
  const auto split_rings = [](const Cell& cell) {
    unsigned rings = 0;
    for(const Cell::Bridge& bridge : cell.bridges())
      rings |= 1u << (2 * bridge.axis + bridge.side);
    return rings;
  };
  const Cell bridged(label, 0, PMP::label_box_margin);
  const unsigned split = split_rings(bridged);
  std::size_t rings = 0;
  for(unsigned r = split; r != 0; r &= r - 1)
    ++rings;
  CHECK(!bridged.bridges().empty() && bridged.bridges().size() == rings);
  const Cell after(label, 0, PMP::label_box_margin, split);
  CHECK((split_rings(after) & split) == 0u);
  const Cell whole(label, 0, PMP::label_box_margin, 0x3fu);
  CHECK(whole.bridges().empty() && whole.size() > 1);
  std::cout << "  natbrainlab's cell: " << bridged.bridges().size() << " bridges, " << bridged.size()
            << " points; with every ring whole, " << whole.size() << " points\n";
}

// Cells where no seeds, splits or label left whole keep every label from touching itself: four
// labels each on two opposite voxels of a block, alone and with the background as one of them,
// and a block of random voxels of 4 labels with a cell whose ring has its two pairs in one
// sheet there and in the next cell (a doubled edge, whose seeds conflict). The cell gets a point
// per node and a small ball of one label at the centre, the other labels capped against it.
// Checked: every label's surface a manifold that does not intersect itself, besides the checks
// of every map; the first cells' 6 points, one per half-axis, and a cap per voxel not of the
// ball's label.
void check_ball_cells()
{
  const std::string doubled = "000130022033121101222231332010102202202101312331112130321123121212002232"
                              "310211112102030313111213302112120101102120030332122013120331223213213201"
                              "130123032033102111121102020201332210123323132323132210231031020022101203";
  check(generated({6, 6, 6}, {1, 1, 1},
                  [&doubled](long i, long j, long k) { return Label(doubled[std::size_t(36 * i + 6 * j + k)] - '0'); }),
        0);
  for(const Label odd_one : {Label(1), Label(0)})
  {
    const auto antipodal = [odd_one](long i, long j, long k) {
      return i == j && j == k ? odd_one : j == k ? Label(2) : i == k ? Label(3) : Label(4);
    };
    check(generated({2, 2, 2}, {1, 1, 1}, antipodal), 0);
    using Cell = PMP::internal::Constrained_fairing::Dual_cell<Label>;
    const Cell cell([&](int d0, int d1, int d2) { return d0 < 0 || d1 < 0 || d2 < 0 || d0 > 1 || d1 > 1 || d2 > 1
                                                             ? Label(0) : antipodal(d0, d1, d2); },
                    0, PMP::label_box_margin);
    CHECK(cell.size() == 6 && cell.caps().size() == 6 && cell.bridges().empty());
    std::cout << "  four labels on opposite voxels" << (odd_one == 0 ? ", the background one of them" : "") << ": "
              << cell.size() << " points, " << cell.caps().size() << " caps\n";
  }
}

// label_surface_nets() appending to a soup already there (a tangled block of an atlas, so that
// the untangling runs on the appended part): the second soup is the first, its indices shifted
// by the number of points before it, bit for bit.
void check_appending()
{
  const std::string block = tangled_blocks().front();
  std::vector<Label> labels;
  for(char c : block)
    labels.push_back(Label(c - '0'));
  const std::array<std::size_t, 3> size{6, 6, 6};
  const std::array<double, 3> spacing{1, 1, 1}, origin{0.5, -2, 3};
  std::vector<Point> points;
  std::vector<Triangle> triangles;
  std::vector<std::array<Label, 2> > face_labels;
  std::vector<std::array<double, 3> > half;
  PMP::label_surface_nets(labels.data(), size, spacing, origin, points, triangles, face_labels, half);
  const std::size_t n = points.size(), m = triangles.size();
  PMP::label_surface_nets(labels.data(), size, spacing, origin, points, triangles, face_labels, half);
  CHECK(n > 0 && points.size() == 2 * n && half.size() == 2 * n && triangles.size() == 2 * m &&
        face_labels.size() == 2 * m);
  for(std::size_t p = 0; p < n && points.size() == 2 * n && half.size() == 2 * n; ++p)
    CHECK(points[n + p] == points[p] && half[n + p] == half[p]);
  for(std::size_t f = 0; f < m && triangles.size() == 2 * m && face_labels.size() == 2 * m; ++f)
  {
    const Triangle shifted = {triangles[f][0] + n, triangles[f][1] + n, triangles[f][2] + n};
    CHECK(triangles[m + f] == shifted && face_labels[m + f] == face_labels[f]);
  }
}

// label_surface_nets() on a box of a larger map (`first_voxel`): the points of the cells 10
// voxels or more from the box's cut side are the whole map's, bit for bit and in their order, on
// random voxels of 4 labels and an anisotropic spacing, whose crossing tests are near coplanar.
void check_chunk()
{
  const std::size_t n = 16, cut = 3, halo = 10;
  std::mt19937 random(11);
  std::vector<Label> labels(n * n * n);
  for(Label& l : labels)
    l = Label(random() % 4);
  const std::array<double, 3> spacing{0.7, 1, 1.3}, origin{0.5, -2, 3};
  // The points of cells (i, j, k) with i >= `from`, as nets of `box` starting at voxel `first` give them.
  const auto far_points = [&](const Label* box, std::size_t voxels, std::size_t first, std::size_t from) {
    std::vector<Point> points, kept;
    std::vector<Triangle> triangles;
    std::vector<std::array<Label, 2> > face_labels;
    std::vector<std::array<double, 3> > half;
    PMP::label_surface_nets(box, {voxels, n, n}, spacing, origin, points, triangles, face_labels, half, Label(0),
                            PMP::label_box_margin, {first, 0, 0});
    for(const Point& p : points)
      if(std::floor((p.x() - origin[0]) / spacing[0]) + 1 >= double(from))
        kept.push_back(p);
    return kept;
  };
  const std::size_t from = cut + 1 + halo;
  const std::vector<Point> whole = far_points(labels.data(), n, 0, from);
  const std::vector<Point> chunk = far_points(labels.data() + cut * n * n, n - cut, cut, from);
  CHECK(!whole.empty() && chunk == whole);
  std::cout << "  a chunk's nets: " << chunk.size() << " points of the whole map's " << whole.size() << "\n";
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
  for(const Label_map& worst : worst_cases())
    check(worst, 0);
  check_bridged_cells();
  check_ball_cells();
  check_untangling();
  check_appending();
  check_chunk();
  return test::report("test_label_surfaces");
}
