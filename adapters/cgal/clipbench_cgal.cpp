// CGAL's Boolean_set_operations_2 (Polygon_set_2 on Exact_predicates_exact_constructions_kernel)
// behind clipbench's external clipper protocol, version 1 (docs/PROTOCOL.md). Each operand's
// region under the requested fill rule is built exactly (operand_region.hpp); the operation runs
// on the two exact polygon sets; the result is rounded to doubles only when it is written.
// `time_ns` covers the operation only (not the region building, which a user holding valid
// polygons would not need, and not the rounding).

#include <CGAL/version.h>

#include "operand_region.hpp"

int main() {
  using namespace clipbench;
  std::string name = std::string("CGAL ") + CGAL_VERSION_STR +
                     " Boolean_set_operations_2 (Polygon_set_2, exact constructions; operands' regions built exactly "
                     "by Arrangement_2)";
  return serve(name, kFills, [](const std::string& op, const std::string& fill, const Rings& subject,
                                const Rings& clip) {
    Polygon_set a = read_operand(subject, fill);
    Polygon_set b = read_operand(clip, fill);
    long long start = now_ns();
    if (op == "intersection") {
      a.intersection(b);
    } else if (op == "union") {
      a.join(b);
    } else if (op == "difference") {
      a.difference(b);
    } else if (op == "xor") {
      a.symmetric_difference(b);
    } else {
      throw std::invalid_argument("unknown operation '" + op + "'");
    }
    long long time = now_ns() - start;
    return Answer{rings_of_set(a), time};
  });
}
