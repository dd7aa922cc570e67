// The study's hinges: built in, read from a file, sampled (hinge/study/study.hpp).
#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numeric>
#include <random>

#include "hinge/conformance/inputs.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/io/jsonl.hpp"
#include "hinge/reference/evaluate.hpp"
#include "hinge/study/study.hpp"

namespace hinge::study {

std::vector<StudyHinge> builtin_hinges(bool quick) {
  std::vector<StudyHinge> hinges;
  for (auto& c : conformance::inputs()) hinges.push_back({c.id, c.category, c.x});
  if (!quick) {
    int i = 0;
    for (const auto& x : reference::well_shaped_hinges(2000, 7))
      hinges.push_back({"well-shaped/random-" + std::to_string(i++), "well-shaped", x});
  }
  return hinges;
}

std::vector<StudyHinge> read_hinges(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot be read");
  std::vector<StudyHinge> hinges;
  io::for_each_hinge_line(in, [&](const io::HingeLine& line) {
    if (!line.x) throw InputError(path + ":" + std::to_string(line.line) + ": " + line.error);
    const auto id_value = nlohmann::json::parse(line.id_json);
    const std::string id = id_value.is_string() ? id_value.get<std::string>() : line.id_json;
    hinges.push_back({id, line.category.empty() ? "input" : line.category, *line.x});
  });
  if (in.bad()) throw InputError(path + ": read error");
  if (hinges.empty()) throw InputError(path + ": no hinge in the file");
  return hinges;
}

std::vector<StudyHinge> sample(const std::vector<StudyHinge>& hinges, std::size_t count) {
  if (count == 0 || count >= hinges.size()) return hinges;
  std::vector<std::size_t> index(hinges.size());
  std::iota(index.begin(), index.end(), 0);
  std::mt19937_64 rng(2013);
  std::shuffle(index.begin(), index.end(), rng);
  index.resize(count);
  std::sort(index.begin(), index.end());
  std::vector<StudyHinge> some;
  for (const std::size_t i : index) some.push_back(hinges[i]);
  return some;
}

}  // namespace hinge::study
