// An operand's region under a fill rule, exactly, as a CGAL Polygon_set_2 on an exact kernel.
//
// CGAL's Boolean_set_operations_2 take valid polygons, and clipbench's operands are rings read
// together under a fill rule (they may cross themselves and each other, overlap and repeat).
// The region is built with CGAL's exact arrangement, so nothing is rounded:
//   1. every ring edge goes into one Arrangement_2 of segments, each carrying +1 when it runs
//      left to right (x, then y, increasing) and -1 otherwise; where edges overlap the numbers add;
//   2. each face's winding number comes from its neighbour's across an edge (a face on an edge's
//      left winds that edge's number more than the face on its right), starting from 0 outside;
//   3. the edges between a face the fill rule accepts and one it does not are the region's
//      boundary; they go, turned so the region is on their left, into the arrangement of an empty
//      Polygon_set_2, whose faces are then marked contained where they lie on that left side.
// That is the form Boolean_set_operations_2 keep a polygon set in (no edge between two faces of
// the same side), so the set is valid whatever the rings were.
#pragma once

#include <cmath>
#include <deque>
#include <type_traits>
#include <utility>
#include <stdexcept>
#include <vector>

#include <CGAL/Arr_curve_data_traits_2.h>
#include <CGAL/Arr_extended_dcel.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>

#include "protocol.hpp"

namespace clipbench {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Polygon_set = CGAL::Polygon_set_2<Kernel>;

namespace region_detail {

struct Sum {
  long operator()(long a, long b) const { return a + b; }
};
using Segment_traits = CGAL::Arr_segment_traits_2<Kernel>;
using Data_traits = CGAL::Arr_curve_data_traits_2<Segment_traits, long, Sum>;
constexpr long kUnset = std::numeric_limits<long>::min();
using Winding_arrangement = CGAL::Arrangement_2<Data_traits, CGAL::Arr_face_extended_dcel<Data_traits, long>>;

/// How much the winding number rises from the right of `h` to its left (its incident face).
inline long rise(Winding_arrangement::Halfedge_const_handle h) {
  long d = h->curve().data();
  return h->direction() == CGAL::ARR_LEFT_TO_RIGHT ? d : -d;
}

}  // namespace region_detail

/// The region `rings` cover under `fill`, exactly.
inline Polygon_set region_of(const Rings& rings, const std::string& fill) {
  using namespace region_detail;
  inside(0, fill);  // an unknown rule is refused before any work
  std::vector<Data_traits::Curve_2> edges;
  for (const Ring& ring : rings) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Point& a = ring[i];
      const Point& b = ring[(i + 1) % ring.size()];
      if (a == b) continue;  // a repeated point adds no edge
      Kernel::Point_2 p(a[0], a[1]), q(b[0], b[1]);
      long way = (a[0] < b[0] || (a[0] == b[0] && a[1] < b[1])) ? 1 : -1;
      edges.emplace_back(Segment_traits::Curve_2(p, q), way);
    }
  }
  Polygon_set set;
  if (edges.empty()) return set;
  Winding_arrangement arr;
  CGAL::insert(arr, edges.begin(), edges.end());

  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) f->set_data(kUnset);
  auto outside = arr.unbounded_face();
  outside->set_data(0);
  std::deque<Winding_arrangement::Face_handle> queue{outside};
  auto visit = [&](Winding_arrangement::Face_handle f, Winding_arrangement::Ccb_halfedge_circulator start) {
    auto h = start;
    do {
      auto g = h->twin()->face();
      if (g->data() == kUnset) {
        g->set_data(f->data() - rise(h));
        queue.push_back(g);
      }
    } while (++h != start);
  };
  while (!queue.empty()) {
    auto f = queue.front();
    queue.pop_front();
    if (!f->is_unbounded()) visit(f, f->outer_ccb());
    for (auto hole = f->inner_ccbs_begin(); hole != f->inner_ccbs_end(); ++hole) visit(f, *hole);
  }

  // The boundary edges, turned so the region lies on their left.
  std::vector<Polygon_set::Traits_2::X_monotone_curve_2> boundary;
  for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e) {
    bool left = inside(e->face()->data(), fill);
    bool right = inside(e->twin()->face()->data(), fill);
    if (left == right) continue;
    const auto& s = e->source()->point();
    const auto& t = e->target()->point();
    boundary.emplace_back(left ? s : t, left ? t : s);
  }
  if (boundary.empty()) return set;
  auto& out = set.arrangement();
  CGAL::insert_non_intersecting_curves(out, boundary.begin(), boundary.end());
  for (auto f = out.faces_begin(); f != out.faces_end(); ++f) {
    if (f->is_unbounded()) {
      f->set_contained(false);
      continue;
    }
    auto h = f->outer_ccb();
    f->set_contained(h->source()->point() == h->curve().source());
  }
  return set;
}

/// region_of, with a failure named as the reading's, so that it is not taken for the library's.
inline Polygon_set read_operand(const Rings& rings, const std::string& fill) {
  try {
    return region_of(rings, fill);
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("reading the operands failed, before the operation ran: ") + e.what());
  }
}

/// The double nearest to `v` (ties to the lower). Forces `v`'s exact value first: CGAL::to_double
/// of a lazy number returns its interval's estimate whenever that is within 1e-5 relative, and a
/// crossing of two nearly parallel edges came out 3e-5 off both (near-coincident case 3).
inline double nearest_double(const Kernel::FT& v) {
  const auto& e = CGAL::exact(v);
  using Exact = std::decay_t<decltype(e)>;
  const std::pair<double, double> i = CGAL::to_interval(e);
  if (i.first == i.second) return i.first;
  if (std::nextafter(i.first, i.second) != i.second) return CGAL::to_double(e);  // not tight: not expected
  const Exact middle = (Exact(i.first) + Exact(i.second)) / 2;
  return e <= middle ? i.first : i.second;
}

/// The rings of a polygon set's polygons, each point rounded to the nearest double once: outers
/// counter-clockwise, holes clockwise (CGAL's own orientation).
inline Rings rings_of_set(const Polygon_set& set) {
  std::vector<Polygon_set::Polygon_with_holes_2> polygons;
  set.polygons_with_holes(std::back_inserter(polygons));
  Rings rings;
  auto add = [&rings](const Polygon_set::Polygon_2& p) {
    Ring r;
    for (auto v = p.vertices_begin(); v != p.vertices_end(); ++v)
      r.push_back({nearest_double(v->x()), nearest_double(v->y())});
    if (r.size() >= 3) rings.push_back(std::move(r));
  };
  for (const auto& p : polygons) {
    if (p.is_unbounded()) throw std::runtime_error("the result is unbounded");
    add(p.outer_boundary());
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) add(*h);
  }
  return rings;
}

}  // namespace clipbench
