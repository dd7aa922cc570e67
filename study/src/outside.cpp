// Plugins as rows of the study (hinge/study/outside.hpp), through hinge::conformance::Plugin.
#include "hinge/study/outside.hpp"

#include <algorithm>
#include <filesystem>
#include <memory>

#include "hinge/conformance/plugin.hpp"
#include "timing.hpp"

namespace hinge::study {

OutsideTiming time_beside_fast(const std::function<double(const std::vector<std::array<double, 12>>&)>& pass,
                               const std::vector<std::array<double, 12>>& hinges, int rounds) {
  OutsideTiming t;
  if (hinges.empty()) return t;
  detail::Slots slots(hinges.size());
  const auto fast_pass = [&] {
    return detail::timed_pass(0, hinges.size(), hinges.size(), 1,
                              [&](std::size_t i) { detail::fast_into(2, hinges[i], slots, i); });
  };
  for (int r = 0; r < rounds; ++r) {
    double mine = 0, fast = 0;
    if (r % 2) {
      fast = fast_pass();
      mine = pass(hinges);
    } else {
      mine = pass(hinges);
      fast = fast_pass();
    }
    t.rounds.push_back({mine, fast});
  }
  return t;
}

Outside plugin_candidate(const std::string& path, const std::string& symbol, const std::string& label) {
  auto plugin = std::make_shared<conformance::Plugin>(path, symbol);
  Outside o;
  o.label = label.empty() ? std::filesystem::path(path).filename().string() : label;
  o.evaluate = [plugin](const std::vector<std::array<double, 12>>& hinges) {
    std::vector<io::EvalOutput> out;
    out.reserve(hinges.size());
    for (const auto& x : hinges) out.push_back((*plugin)(x));
    return out;
  };
  o.time = [plugin](const std::vector<std::array<double, 12>>& hinges, int rounds) {
    // fast's pass repeated to at least 256 calls; the child is given 10 s per call of the plugin's pass
    const int repeats = static_cast<int>(std::max<std::size_t>(1, (256 + hinges.size() - 1) / hinges.size()));
    const double timeout = 10.0 + 1e-3 * static_cast<double>(rounds) * static_cast<double>(hinges.size() * 2);
    const conformance::Plugin::Timing t = plugin->time(hinges, rounds, &detail::fast_per_hinge, repeats, timeout);
    return OutsideTiming{t.rounds, t.error};
  };
  return o;
}

}  // namespace hinge::study
