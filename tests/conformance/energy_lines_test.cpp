// The files of the command-line energy conformance (hinge/io/energy_lines.hpp): output lines read by the rules of
// `hinge eval` output (a NaN, null or "NaN" is missing, an infinity alone non-finite, a line without "energy"
// missing, an error line an error, the first line of an id counts, a line without a readable id an error naming
// the file and line), written so that every number reads back exactly; input lines carry x and rest.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "hinge/core/errors.hpp"
#include "hinge/io/energy_lines.hpp"

namespace hinge::io {
namespace {

using Status = EnergyOutput::Status;

std::string numbers(std::size_t n, const std::string& value) {
  std::string out = "[";
  for (std::size_t i = 0; i < n; ++i) {
    if (i) out += ", ";
    out += value;
  }
  return out + "]";
}

std::string line(const std::string& id, const std::string& energy, const std::string& entry = "0.5") {
  std::string out = "{\"id\": \"";
  out += id;
  out += "\", \"energy\": ";
  out += energy;
  out += ", \"grad\": ";
  out += numbers(12, entry);
  out += ", \"hess\": ";
  out += numbers(144, entry);
  out += "}";
  return out;
}

// The lines joined, each ended by a newline.
std::string lines(std::initializer_list<std::string> each) {
  std::string out;
  for (const std::string& l : each) {
    out += l;
    out += '\n';
  }
  return out;
}

std::map<std::string, EnergyOutput> read(const std::string& text) {
  std::istringstream in(text);
  return read_energy_outputs(in, "candidate.jsonl");
}

TEST(EnergyLines, AResultLineIsRead) {
  const auto r = read(lines({line("a", "1.25")}));
  ASSERT_EQ(r.size(), 1u);
  const EnergyOutput& a = r.at("a");
  EXPECT_EQ(a.status, Status::ok);
  EXPECT_EQ(a.theta, 1.25);
  EXPECT_EQ(a.grad[11], 0.5);
  EXPECT_EQ(a.hess[143], 0.5);
}

TEST(EnergyLines, BadNumbersFollowTheEvalRules) {
  const auto r = read(lines({line("null", "null"), line("nan-string", "\"NaN\""), line("bare-nan", "NaN"),
                             line("infinity", "\"Infinity\""), line("bare-infinity", "1.0", "-Infinity")}));
  EXPECT_EQ(r.at("null").status, Status::missing);
  EXPECT_EQ(r.at("nan-string").status, Status::missing);
  EXPECT_EQ(r.at("bare-nan").status, Status::missing);
  EXPECT_EQ(r.at("infinity").status, Status::nonfinite);
  EXPECT_EQ(r.at("bare-infinity").status, Status::nonfinite);
}

TEST(EnergyLines, ALineWithoutEnergyIsMissingAndThetaIsNotTakenForIt) {
  std::string theta_line = line("theta", "1.0");
  theta_line.replace(theta_line.find("\"energy\""), 8, "\"theta\"");
  std::string both = line("both", "3.0");
  both.insert(both.find(", \"energy\""), ", \"theta\": 2.0");
  const auto r = read(lines({theta_line, both}));
  EXPECT_EQ(r.at("theta").status, Status::missing);
  EXPECT_EQ(r.at("theta").error, "no \"energy\"");
  EXPECT_EQ(r.at("both").status, Status::ok);
  EXPECT_EQ(r.at("both").theta, 3.0);
}

TEST(EnergyLines, ErrorLinesAndTheFirstLineOfAnIdCount) {
  const auto r = read(
      lines({"{\"id\": \"e\", \"error\": \"degenerate\"}", "", line("e", "1.0"), line("f", "1.0"), line("f", "2.0")}));
  EXPECT_EQ(r.at("e").status, Status::error);
  EXPECT_EQ(r.at("e").error, "degenerate");
  EXPECT_EQ(r.at("f").theta, 1.0);
}

TEST(EnergyLines, ALineWithoutAReadableIdNamesTheFileAndLine) {
  try {
    read(lines({line("a", "1.0"), "", "{\"energy\": 1.0}"}));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("candidate.jsonl:3:"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read("not json at all\n"), InputError);
}

TEST(EnergyLines, WrittenLinesReadBackExactly) {
  EnergyOutput r;
  r.status = Status::ok;
  r.theta = -0.0;
  for (int i = 0; i < 12; ++i) r.grad[i] = std::ldexp(1.0 + i * 0x1p-52, -1074 + 60 * i);
  for (int i = 0; i < 144; ++i) r.hess[i] = 0.1 * (i - 70);
  r.hess[5] = 5e-324;
  const auto back = read(lines({energy_output_line("id \"quoted\"", r)})).at("id \"quoted\"");
  EXPECT_EQ(back.status, Status::ok);
  EXPECT_TRUE(std::signbit(back.theta));
  EXPECT_EQ(back.grad, r.grad);
  EXPECT_EQ(back.hess, r.hess);

  EnergyOutput missing;
  missing.error = "returned 1";
  EXPECT_EQ(read(lines({energy_output_line("m", missing)})).at("m").status, Status::error);
}

TEST(EnergyLines, AnInputLineCarriesXAndRest) {
  std::array<double, 12> x{}, rest{};
  for (int i = 0; i < 12; ++i) x[i] = i, rest[i] = -0.5 * i;
  const nlohmann::json j =
      nlohmann::json::parse(energy_input_line("well-shaped/flat/00-random", "well-shaped/flat", x, rest));
  EXPECT_EQ(j["id"], "well-shaped/flat/00-random");
  EXPECT_EQ(j["category"], "well-shaped/flat");
  EXPECT_EQ(j["x"].get<std::vector<double>>(), std::vector<double>(x.begin(), x.end()));
  EXPECT_EQ(j["rest"].get<std::vector<double>>(), std::vector<double>(rest.begin(), rest.end()));
}

}  // namespace
}  // namespace hinge::io
