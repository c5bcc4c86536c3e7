// clipbench's external clipper protocol, version 1 (docs/PROTOCOL.md), for the C++ adapters:
// the handshake, then one reply line per request line. Shared by adapters/cgal and adapters/boost.
#pragma once

#include <array>
#include <chrono>
#include <exception>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace clipbench {

using Point = std::array<double, 2>;
using Ring = std::vector<Point>;  // the closing point not repeated
using Rings = std::vector<Ring>;

inline const std::vector<std::string> kOps = {"intersection", "union", "difference", "xor"};
inline const std::vector<std::string> kFills = {"even-odd", "non-zero", "positive", "negative"};

/// What one call returns: the result's rings and the library's own time for the operation.
struct Answer {
  Rings rings;
  long long time_ns;
};

/// Nanoseconds since an arbitrary start, for `time_ns`.
inline long long now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

inline Rings rings_of(const nlohmann::json& value) {
  Rings rings;
  for (const auto& ring : value) {
    Ring r;
    for (const auto& p : ring) r.push_back({p.at(0).get<double>(), p.at(1).get<double>()});
    rings.push_back(std::move(r));
  }
  return rings;
}

/// Writes the handshake and answers requests until standard input closes. A library exception
/// becomes an error reply, so the harness fails that case and keeps the process.
inline int serve(const std::string& name, const std::vector<std::string>& fills,
                 const std::function<Answer(const std::string& op, const std::string& fill, const Rings& subject,
                                            const Rings& clip)>& clip) {
  std::ios::sync_with_stdio(false);
  nlohmann::json handshake = {
      {"protocol", 1},
      {"name", name},
      {"polygon", {{"ops", kOps}, {"fill_rules", fills}, {"window", "any"}, {"output", "conventional"}}}};
  std::cout << handshake.dump() << '\n' << std::flush;
  std::string line;
  while (std::getline(std::cin, line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    nlohmann::json request = nlohmann::json::parse(line);
    nlohmann::json reply = {{"id", request.at("id")}};
    try {
      Answer a = clip(request.at("op").get<std::string>(), request.at("fill").get<std::string>(),
                      rings_of(request.at("subject")), rings_of(request.at("clip")));
      reply["rings"] = a.rings;
      reply["time_ns"] = a.time_ns;
    } catch (const std::exception& e) {
      reply["error"] = std::string(e.what());
    }
    // nlohmann writes doubles shortest-round-trip, so coordinates cross exactly.
    std::cout << reply.dump() << '\n' << std::flush;
  }
  return 0;
}

/// Whether the fill rule counts winding number `w` as inside.
inline bool inside(long w, const std::string& fill) {
  if (fill == "even-odd") return w % 2 != 0;
  if (fill == "non-zero") return w != 0;
  if (fill == "positive") return w > 0;
  if (fill == "negative") return w < 0;
  throw std::invalid_argument("unknown fill rule '" + fill + "'");
}

}  // namespace clipbench
