// Boost.Geometry's boolean operations (intersection, union_, difference, sym_difference on
// multi_polygons of double points) behind clipbench's external clipper protocol, version 1
// (docs/PROTOCOL.md).
//
// Boost.Geometry takes valid polygons only, and has no way to read crossing rings under a fill
// rule. Each operand's region is therefore built exactly by CGAL's arrangement (the CGAL
// adapter's operand_region.hpp) and rounded to doubles: valid polygons, outers counter-clockwise,
// holes clockwise, as the polygon type below declares. `time_ns` covers Boost's operation only.

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <boost/version.hpp>

#include "../cgal/operand_region.hpp"

namespace bg = boost::geometry;
using BPoint = bg::model::d2::point_xy<double>;
// Counter-clockwise outers (ClockWise = false), rings not closed (Closed = false): clipbench's form.
using BPolygon = bg::model::polygon<BPoint, false, false>;
using BMulti = bg::model::multi_polygon<BPolygon>;

namespace {

/// An operand's region, rounded to doubles once, as Boost polygons.
BMulti boost_region(const clipbench::Rings& rings, const std::string& fill) {
  clipbench::Polygon_set set = clipbench::read_operand(rings, fill);
  std::vector<clipbench::Polygon_set::Polygon_with_holes_2> polygons;
  set.polygons_with_holes(std::back_inserter(polygons));
  auto ring_of = [](const clipbench::Polygon_set::Polygon_2& p, BPolygon::ring_type& r) {
    for (auto v = p.vertices_begin(); v != p.vertices_end(); ++v)
      r.push_back(BPoint(clipbench::nearest_double(v->x()), clipbench::nearest_double(v->y())));
  };
  BMulti multi;
  for (const auto& p : polygons) {
    BPolygon b;
    ring_of(p.outer_boundary(), b.outer());
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) {
      b.inners().emplace_back();
      ring_of(*h, b.inners().back());
    }
    multi.push_back(std::move(b));
  }
  return multi;
}

clipbench::Rings rings_of_multi(const BMulti& m) {
  clipbench::Rings rings;
  auto add = [&rings](const BPolygon::ring_type& r, bool outer) {
    clipbench::Ring out;
    for (const BPoint& p : r) out.push_back({p.x(), p.y()});
    // Boost may repeat the first point at the end of an open ring; drop it.
    if (out.size() > 1 && out.front() == out.back()) out.pop_back();
    if (out.size() < 3) return;
    double twice = 0;
    for (std::size_t i = 0, j = out.size() - 1; i < out.size(); j = i++)
      twice += (out[j][0] - out[i][0]) * (out[j][1] + out[i][1]);
    if ((twice > 0) != outer) std::reverse(out.begin(), out.end());
    rings.push_back(std::move(out));
  };
  for (const BPolygon& p : m) {
    add(p.outer(), true);
    for (const auto& h : p.inners()) add(h, false);
  }
  return rings;
}

}  // namespace

int main() {
  using namespace clipbench;
  std::string name = "Boost.Geometry " + std::to_string(BOOST_VERSION / 100000) + "." +
                     std::to_string(BOOST_VERSION / 100 % 1000) +
                     " (double; operands' regions built exactly by CGAL's Arrangement_2, then rounded)";
  return serve(name, kFills, [](const std::string& op, const std::string& fill, const Rings& subject,
                                const Rings& clip) {
    BMulti a = boost_region(subject, fill);
    BMulti b = boost_region(clip, fill);
    BMulti out;
    long long start = now_ns();
    if (op == "intersection") {
      bg::intersection(a, b, out);
    } else if (op == "union") {
      bg::union_(a, b, out);
    } else if (op == "difference") {
      bg::difference(a, b, out);
    } else if (op == "xor") {
      bg::sym_difference(a, b, out);
    } else {
      throw std::invalid_argument("unknown operation '" + op + "'");
    }
    long long time = now_ns() - start;
    return Answer{rings_of_multi(out), time};
  });
}
