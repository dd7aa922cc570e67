// The worked examples of docs/examples: the reference in MPFR at 256 bits, rounded to double,
// reproduces the contract's independent evaluation exactly (every output equal as a value).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "hinge/reference/rounded.hpp"

namespace hinge::reference {
namespace {

std::vector<nlohmann::json> read_lines(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << "cannot read " << path;
  std::vector<nlohmann::json> lines;
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) lines.push_back(nlohmann::json::parse(line));
  return lines;
}

TEST(OracleExamples, ReferenceInMpfr256RoundsToTheContractValues) {
  const auto inputs = read_lines(HINGE_EXAMPLES_DIR "/eval-input.jsonl");
  const auto outputs = read_lines(HINGE_EXAMPLES_DIR "/oracle-output.jsonl");
  ASSERT_EQ(inputs.size(), 3u);
  ASSERT_EQ(outputs.size(), inputs.size());
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    const auto x = inputs[k]["x"].get<std::array<double, 12>>();
    const RoundedTheta r = theta_derivatives_rounded({ScalarType::Kind::kind_mpfr, 256}, x);
    const auto& want = outputs[k];
    ASSERT_EQ(want["id"], inputs[k]["id"]);
    EXPECT_EQ(r.theta, want["theta"].get<double>()) << want["id"];
    for (int i = 0; i < 12; ++i) EXPECT_EQ(r.grad[i], want["grad"][i].get<double>()) << want["id"] << " grad " << i;
    for (int i = 0; i < 144; ++i) EXPECT_EQ(r.hess[i], want["hess"][i].get<double>()) << want["id"] << " hess " << i;
  }
}

}  // namespace
}  // namespace hinge::reference
