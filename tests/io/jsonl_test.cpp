// Unit tests of the JSON Lines formats (docs/contract.md, 9.1): the hinge reader and the result writer of
// `hinge eval` and `hinge oracle` (io/src/jsonl.cpp), the reader of their output that `hinge conform
// --candidate` uses (io/src/eval_output.cpp), and the numbers every writer prints (io/src/number.cpp).
// The contract's promises checked here: every number is a double that reads back exactly (zeros compare
// as values: -0.0 equals 0.0), blank lines are skipped, a line that is not valid input gives
// {"id": null, "line": N, "error": "why"} with the id kept where it could be read. Exact messages are
// checked only where docs/testing.md ("Bad input") or a header documents them.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "hinge/core/errors.hpp"
#include "hinge/io/eval_output.hpp"
#include "hinge/io/jsonl.hpp"
#include "hinge/io/number.hpp"

namespace hinge {
namespace {

using Status = io::EvalOutput::Status;
using Json = nlohmann::json;

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

::testing::AssertionResult contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

::testing::AssertionResult starts_with(const std::string& text, const std::string& prefix) {
  if (text.rfind(prefix, 0) == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not start with \"" << prefix << "\"";
}

// The same double, or two zeros (docs/contract.md: numbers are compared as values, -0.0 equals 0.0). For
// finite non-zero doubles == is equality of the bits, so this is bit-for-bit everywhere else.
::testing::AssertionResult same_value(double expected, double got) {
  if (expected == got) return ::testing::AssertionSuccess();
  char a[40], b[40];
  std::snprintf(a, sizeof a, "%.17g", expected);
  std::snprintf(b, sizeof b, "%.17g", got);
  return ::testing::AssertionFailure() << "expected " << a << " (0x" << std::hex << bits(expected) << "), got " << b
                                       << " (0x" << bits(got) << std::dec << ")";
}

// The doubles that are hard to print and read: the extremes, subnormals, values just below powers of two,
// 17-digit values and values whose shortest form is long.
std::vector<double> hard_doubles() {
  using L = std::numeric_limits<double>;
  const double below_one = std::nextafter(1.0, 0.0);
  std::vector<double> v = {0.0,
                           -0.0,
                           L::denorm_min(),
                           -L::denorm_min(),
                           3 * L::denorm_min(),
                           L::min() - L::denorm_min(),  // the largest subnormal
                           L::min(),
                           -L::min(),
                           std::nextafter(L::min(), 1.0),
                           L::max(),
                           -L::max(),
                           std::nextafter(L::max(), 0.0),
                           std::ldexp(1.0, 1023),
                           std::nextafter(std::ldexp(1.0, 1023), 0.0),
                           below_one,
                           -below_one,
                           std::nextafter(2.0, 0.0),
                           std::nextafter(1024.0, 0.0),
                           std::nextafter(std::ldexp(1.0, -1022 + 1), 0.0),
                           std::nextafter(std::ldexp(1.0, 53), 0.0),  // 2^53 - 1
                           std::ldexp(1.0, 53) + 2,
                           std::nextafter(1.0, 2.0),
                           0.1,
                           0.30000000000000004,
                           1.0 / 3.0,
                           2.0 / 3.0,
                           1e23,
                           8.98846567431158e307,
                           2.2250738585072011e-308,
                           4.9406564584124654e-324,
                           1.7976931348623157e308,
                           123456789012345678.0,
                           9007199254740993.0,
                           -1.2345678901234567e-300,
                           5e-310,
                           1e22,
                           1e-7};
  return v;
}

// Hard doubles, then random finite doubles of every exponent (a share subnormal, a share near 1).
std::vector<double> many_doubles(std::size_t count, std::uint64_t seed) {
  std::vector<double> out = hard_doubles();
  std::mt19937_64 rng(seed);
  while (out.size() < count) {
    std::uint64_t b = rng();
    if (out.size() % 8 == 0) b &= 0x800f'ffff'ffff'ffffULL;  // subnormal (or zero)
    if (out.size() % 8 == 1) b = (b & 0x800f'ffff'ffff'ffffULL) | (std::uint64_t(1023 - 30 + rng() % 60) << 52);
    const double x = std::bit_cast<double>(b);
    if (std::isfinite(x)) out.push_back(x);
  }
  return out;
}

std::string g17(double x) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

// A hinge line with the 12 given number texts.
std::string hinge_line(const std::string& id_json, const std::vector<std::string>& x) {
  std::string s = "{\"id\": " + id_json + ", \"x\": [";
  for (std::size_t i = 0; i < x.size(); ++i) s += (i ? ", " : "") + x[i];
  return s + "]}";
}

std::vector<std::string> twelve(const std::string& text) { return std::vector<std::string>(12, text); }

const std::string kValid = hinge_line("\"h\"", {"0", "1", "0", "0", "0", "0", "1", "0", "0", "0", "-1", "0"});

// The lines for_each_hinge_line hands over for `text`.
std::vector<io::HingeLine> read_lines(const std::string& text, long first_line = 1) {
  std::istringstream in(text);
  std::vector<io::HingeLine> lines;
  io::for_each_hinge_line(
      in, [&](const io::HingeLine& h) { lines.push_back(h); }, first_line);
  return lines;
}

// The object invalid_line writes for `h`, which must be one line of valid JSON.
Json invalid_object(const io::HingeLine& h) {
  const std::string text = io::invalid_line(h);
  EXPECT_EQ(text.find('\n'), std::string::npos) << text;
  EXPECT_TRUE(Json::accept(text)) << text;
  return Json::parse(text, nullptr, false);
}

// Checks that `h` is an invalid line numbered `line` whose output object names that line.
void expect_invalid(const io::HingeLine& h, long line) {
  EXPECT_FALSE(h.x.has_value()) << "line " << line << " was read as a hinge";
  EXPECT_FALSE(h.error.empty());
  EXPECT_EQ(h.line, line);
  const Json j = invalid_object(h);
  ASSERT_TRUE(j.is_object());
  EXPECT_EQ(j.size(), 3u) << j.dump();
  EXPECT_TRUE(j.contains("id")) << j.dump();
  ASSERT_TRUE(j.contains("line") && j["line"].is_number_integer()) << j.dump();
  EXPECT_EQ(j["line"].get<long>(), line);
  ASSERT_TRUE(j.contains("error") && j["error"].is_string()) << j.dump();
  EXPECT_FALSE(j["error"].get<std::string>().empty());
  // The reason as read (invalid UTF-8 in it is replaced in the output: io::json_string).
  const bool ascii =
      std::all_of(h.error.begin(), h.error.end(), [](char c) { return static_cast<unsigned char>(c) < 0x80; });
  if (ascii) {
    EXPECT_EQ(j["error"].get<std::string>(), h.error);
  }
}

// ---------------------------------------------------------------------------------------------------
// Reading hinges

TEST(JsonlRead, ReadsEveryDoubleBackExactly) {
  // Each double written three ways: shortest (the project's writer), %.17g (another program's) and
  // %.17e; every one must come back as the same double.
  const std::vector<double> values = many_doubles(12 * 400, 11);
  for (int style = 0; style < 3; ++style) {
    std::string text;
    for (std::size_t i = 0; i < values.size(); i += 12) {
      std::vector<std::string> x;
      for (std::size_t k = 0; k < 12; ++k) {
        char buffer[40];
        if (style == 2) std::snprintf(buffer, sizeof buffer, "%.17e", values[i + k]);
        x.push_back(style == 0 ? io::format_double(values[i + k]) : style == 1 ? g17(values[i + k]) : buffer);
      }
      text += hinge_line("\"h" + std::to_string(i / 12) + "\"", x) + "\n";
    }
    const std::vector<io::HingeLine> lines = read_lines(text);
    ASSERT_EQ(lines.size(), values.size() / 12);
    int mismatches = 0;
    for (std::size_t l = 0; l < lines.size(); ++l) {
      ASSERT_TRUE(lines[l].x.has_value()) << "style " << style << ", line " << l + 1 << ": " << lines[l].error;
      for (std::size_t k = 0; k < 12; ++k) {
        const auto r = same_value(values[12 * l + k], (*lines[l].x)[k]);
        if (!r && mismatches++ < 5)
          ADD_FAILURE() << "style " << style << ", line " << l + 1 << ", x[" << k << "]: " << r.message();
      }
    }
    EXPECT_EQ(mismatches, 0) << "style " << style;
  }
}

TEST(JsonlRead, RoundsLongAndHalfwayDecimalsCorrectly) {
  // docs/contract.md: numbers are read correctly rounded, as std::from_chars does. Texts beyond 17 digits,
  // exact halfway cases (ties to even) and integers beyond 2^53, against std::from_chars.
  // 2^-1075 exactly (halfway between 0 and the smallest subnormal), its 752 significant digits printed
  // from long double, where it is a normal number (glibc prints the exact value).
  std::string half_denorm_min(1200, '\0');
  half_denorm_min.resize(static_cast<std::size_t>(
      std::snprintf(half_denorm_min.data(), half_denorm_min.size(), "%.800Le", std::ldexp(1.0L, -1075))));
  const std::size_t e = half_denorm_min.find('e');
  ASSERT_NE(e, std::string::npos);
  const std::string mantissa = half_denorm_min.substr(0, half_denorm_min.find_last_not_of('0', e - 1) + 1);
  ASSERT_GT(mantissa.size(), 700u) << "the exact decimal of 2^-1075 has 752 significant digits";
  half_denorm_min = mantissa + half_denorm_min.substr(e);
  struct Case {
    std::string text;
    double expected;
  };
  const std::vector<Case> cases = {
      {half_denorm_min, 0.0},  // tie: to even, 0
      {mantissa + "1" + half_denorm_min.substr(half_denorm_min.find('e')),
       std::numeric_limits<double>::denorm_min()},  // just above
      {"2.4703282292062328e-324", std::numeric_limits<double>::denorm_min()},
      {"1.00000000000000011102230246251565404236316680908203125", 1.0},  // 1 + 2^-53: tie, to even
      {"1.00000000000000011102230246251565404236316680908203125001", std::nextafter(1.0, 2.0)},
      {"0.99999999999999994448884876874217297881", std::nextafter(1.0, 0.0)},
      {"9007199254740993", 9007199254740992.0},  // 2^53 + 1 as a JSON integer: tie, to even
      {"9007199254740995", 9007199254740996.0},
      {"-9007199254740993", -9007199254740992.0},
      {"9007199254740993.0", 9007199254740992.0},
      {"9007199254740993.00000000000000000000001", 9007199254740994.0},
      {"18446744073709551615", 18446744073709551616.0},  // 2^64 - 1: rounds up to 2^64
      {"18446744073709551617", 18446744073709551616.0},  // beyond 64 bits
      {"-9223372036854775809", -9223372036854775808.0},
      {"1.7976931348623158e308", std::numeric_limits<double>::max()},  // below max + ulp/2
      {"2.2250738585072011e-308", std::numeric_limits<double>::min() - std::numeric_limits<double>::denorm_min()},
      {"2.2250738585072012e-308", std::numeric_limits<double>::min()},
      {"1E+2", 100.0},
      {"0.1e1", 1.0},
  };
  for (const Case& c : cases) {
    // The reference: std::from_chars, where it gives a value (it reports underflow to zero as an error).
    double reference = 0;
    const auto [end, ec] = std::from_chars(c.text.data(), c.text.data() + c.text.size(), reference);
    if (ec == std::errc()) {
      ASSERT_EQ(bits(reference), bits(c.expected)) << "the test's own expectation for " << c.text;
    }
    const std::vector<io::HingeLine> lines = read_lines(hinge_line("\"h\"", twelve(c.text)));
    ASSERT_EQ(lines.size(), 1u);
    ASSERT_TRUE(lines[0].x.has_value()) << c.text.substr(0, 60) << ": " << lines[0].error;
    for (double x : *lines[0].x) EXPECT_TRUE(same_value(c.expected, x)) << c.text.substr(0, 60);
  }
}

TEST(JsonlRead, NegativeZeroReadsAsTheValueZero) {
  const std::vector<io::HingeLine> lines =
      read_lines(hinge_line("\"z\"", {"-0.0", "-0", "0", "0.0", "-0e5", "-0.000e-400", "1", "1", "1", "1", "1", "1"}));
  ASSERT_EQ(lines.size(), 1u);
  ASSERT_TRUE(lines[0].x.has_value()) << lines[0].error;
  for (int k = 0; k < 6; ++k) EXPECT_EQ((*lines[0].x)[k], 0.0) << "x[" << k << "]";
}

TEST(JsonlRead, IgnoresOtherFieldsAndKeepsTheCategoryString) {
  const std::string line =
      R"({"category": "needles", "note": {"x": [1, 2], "id": "not this"}, "id": "h1", "weights": [1e3, null, true],)"
      R"( "x": [0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -1, 0], "zzz": "1e400"})";
  const std::vector<io::HingeLine> lines = read_lines(line);
  ASSERT_EQ(lines.size(), 1u);
  ASSERT_TRUE(lines[0].x.has_value()) << lines[0].error;
  EXPECT_EQ(lines[0].id_json, "\"h1\"");
  EXPECT_EQ(lines[0].category, "needles");
  EXPECT_EQ((*lines[0].x)[1], 1.0);
  EXPECT_EQ((*lines[0].x)[10], -1.0);
  // A "category" that is not a string is no category, and no reason to reject the hinge.
  const std::vector<io::HingeLine> other =
      read_lines(R"({"category": 7, "id": "h2", "x": [0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -1, 0]})");
  ASSERT_EQ(other.size(), 1u);
  EXPECT_TRUE(other[0].x.has_value()) << other[0].error;
  EXPECT_EQ(other[0].category, "");
}

TEST(JsonlRead, BlankLinesAreSkippedButCounted) {
  const std::string text = "\n   \n" + kValid + "\n\t\n\r\n \f\v \n" + kValid + "\n\n";
  const std::vector<io::HingeLine> lines = read_lines(text);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].line, 3);
  EXPECT_EQ(lines[1].line, 7);
  EXPECT_TRUE(lines[0].x.has_value());
  EXPECT_TRUE(lines[1].x.has_value());
  EXPECT_TRUE(read_lines("").empty());
  EXPECT_TRUE(read_lines("\n\n  \r\n\t").empty());
  EXPECT_TRUE(io::blank(" \t\r\n\f\v"));
  EXPECT_FALSE(io::blank(" x "));
}

TEST(JsonlRead, CrlfEndingsAndALastLineWithoutNewlineAreRead) {
  const std::vector<io::HingeLine> lines = read_lines(kValid + "\r\n\r\n  " + kValid + "  \r\n" + kValid);
  ASSERT_EQ(lines.size(), 3u);
  for (const auto& h : lines) EXPECT_TRUE(h.x.has_value()) << "line " << h.line << ": " << h.error;
  EXPECT_EQ(lines[2].line, 4);
}

TEST(JsonlRead, AShardNumbersItsLinesFromItsFirstLine) {
  const std::vector<io::HingeLine> lines = read_lines(kValid + "\n\nnot json\n", 1001);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].line, 1001);
  expect_invalid(lines[1], 1003);
}

TEST(JsonlRead, AnInvalidLineNamesItsLineNumber) {
  const std::vector<std::string> bad = {
      "no",
      "{",
      R"({"id": "a", "x": [1, 2, 3,)",
      R"({"id": "a" "x": []})",
      "[1, 2, 3]",
      "42",
      "\"a string\"",
      "null",
      R"({"x": [0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -1, 0]})",  // no id
      R"({"id": "a"})",
      R"({"id": "a", "x": [1, 2]})",
      R"({"id": "a", "x": [0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -1, "0"]})",
      "{\"id\": \"a\xff\", \"x\": []}",  // invalid UTF-8
  };
  std::string text = kValid + "\n";
  for (const std::string& line : bad) text += "\n" + line + "\n";
  const std::vector<io::HingeLine> lines = read_lines(text);
  ASSERT_EQ(lines.size(), bad.size() + 1);
  EXPECT_TRUE(lines[0].x.has_value());
  for (std::size_t i = 0; i < bad.size(); ++i) {
    SCOPED_TRACE(bad[i]);
    expect_invalid(lines[i + 1], static_cast<long>(3 + 2 * i));
  }
}

TEST(JsonlRead, ALineThatIsNotJsonGetsTheDocumentedMessage) {
  // docs/testing.md, Bad input 31: "not valid JSON: <the parser's message>".
  const std::vector<io::HingeLine> lines = read_lines("no\n");
  ASSERT_EQ(lines.size(), 1u);
  expect_invalid(lines[0], 1);
  EXPECT_TRUE(starts_with(lines[0].error, "not valid JSON: ")) << lines[0].error;
  EXPECT_EQ(lines[0].id_json, "null");
}

TEST(JsonlRead, EveryTruncationOfAValidLineIsInvalidAndNamesItsLine) {
  const std::string full = R"({"id": "cut", "x": [0.5, 1e-300, 0, 0, 0, 0, 1, 0, 0, 0, -1, 1.7976931348623157e308]})";
  ASSERT_EQ(read_lines(full).size(), 1u);
  ASSERT_TRUE(read_lines(full)[0].x.has_value());
  for (std::size_t n = 1; n < full.size(); ++n) {
    const std::string cut = full.substr(0, n);
    SCOPED_TRACE(cut);
    const std::vector<io::HingeLine> lines = read_lines(kValid + "\n" + cut + "\n" + kValid + "\n");
    ASSERT_EQ(lines.size(), 3u);
    expect_invalid(lines[1], 2);
    EXPECT_TRUE(starts_with(lines[1].error, "not valid JSON: "));
    // The id, where there is one, is this line's and no other's.
    EXPECT_TRUE(lines[1].id_json == "null" || lines[1].id_json == "\"cut\"") << lines[1].id_json;
    EXPECT_TRUE(lines[2].x.has_value()) << "the line after a truncated one";
  }
}

TEST(JsonlRead, KeepsTheIdWhereItCouldBeRead) {
  const std::vector<std::string> bad = {
      R"({"id": "kept-1", "x": [1, 2]})",
      R"({"id": "kept-2"})",
      R"({"x": "twelve", "id": "kept-3"})",
      R"({"id": "kept-4", "x": [0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -1, null]})",
      R"({"id": "kept-5", "x": [0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -1, 0, 0]})",
  };
  std::string text;
  for (const std::string& line : bad) text += line + "\n";
  const std::vector<io::HingeLine> lines = read_lines(text);
  ASSERT_EQ(lines.size(), bad.size());
  for (std::size_t i = 0; i < bad.size(); ++i) {
    SCOPED_TRACE(bad[i]);
    expect_invalid(lines[i], static_cast<long>(i + 1));
    EXPECT_EQ(lines[i].id_json, "\"kept-" + std::to_string(i + 1) + "\"");
    const Json j = invalid_object(lines[i]);
    EXPECT_EQ(j["id"], "kept-" + std::to_string(i + 1));
  }
}

TEST(JsonlRead, TheIdIsNullWhereItCouldNotBeRead) {
  const std::vector<io::HingeLine> lines = read_lines("[\"id\", \"x\"]\n{\"x\": [1, 2, 3]}\n7\n");
  ASSERT_EQ(lines.size(), 3u);
  for (long i = 0; i < 3; ++i) {
    expect_invalid(lines[i], i + 1);
    EXPECT_EQ(lines[i].id_json, "null");
    EXPECT_TRUE(invalid_object(lines[i])["id"].is_null());
  }
}

TEST(JsonlRead, AnIdWithQuotesEscapesAndUnicodeComesBackAsTheSameString) {
  const std::string id = "a \"quoted\" back\\slash / tab\t newline\n nul-ish\x01 \xC3\xA9 \xF0\x9F\x98\x80";
  const std::string id_json = io::json_string(id);
  ASSERT_TRUE(Json::accept(id_json)) << id_json;
  for (const std::string& line : {hinge_line(id_json, twelve("1")), hinge_line(id_json, {"1", "2"})}) {
    const std::vector<io::HingeLine> lines = read_lines(line);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(Json::parse(lines[0].id_json).get<std::string>(), id);
    const std::string out = lines[0].x ? io::error_line(lines[0].id_json, "why") : io::invalid_line(lines[0]);
    EXPECT_EQ(out.find('\n'), std::string::npos) << out;
    ASSERT_TRUE(Json::accept(out)) << out;
    EXPECT_EQ(Json::parse(out)["id"].get<std::string>(), id);
  }
}

TEST(JsonlRead, AWrongCountOfCoordinatesGetsTheDocumentedMessage) {
  // docs/testing.md, Bad input 32.
  for (const std::string& x : {std::string("[]"), std::string("[1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11]"),
                               std::string("[1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13]"), std::string("1"),
                               std::string("\"0 1 0 0 0 0 1 0 0 0 -1 0\""), std::string("{\"0\": 1}"),
                               std::string("null"), std::string("[[0, 1, 0], [0, 0, 0], [1, 0, 0], [0, -1, 0]]")}) {
    SCOPED_TRACE(x);
    const std::vector<io::HingeLine> lines = read_lines("\n{\"id\": \"w\", \"x\": " + x + "}\n");
    ASSERT_EQ(lines.size(), 1u);
    expect_invalid(lines[0], 2);
    EXPECT_EQ(lines[0].error, "\"x\" must be an array of 12 numbers");
    EXPECT_EQ(lines[0].id_json, "\"w\"");
  }
}

TEST(JsonlRead, AMissingXGetsTheDocumentedMessage) {
  // docs/testing.md, Bad input 33.
  const std::vector<io::HingeLine> lines = read_lines(R"({"id": "m", "X": [0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -1, 0]})");
  ASSERT_EQ(lines.size(), 1u);
  expect_invalid(lines[0], 1);
  EXPECT_EQ(lines[0].error, "missing \"x\"");
  EXPECT_EQ(lines[0].id_json, "\"m\"");
}

TEST(JsonlRead, ACoordinateThatIsNotANumberIsNamedByItsIndex) {
  // docs/testing.md, Bad input 34: "\"x\"[0] is not a number".
  for (const std::string bad : {"\"1.0\"", "\"NaN\"", "\"Infinity\"", "null", "true", "false", "[1]", "{}"}) {
    for (int index : {0, 5, 11}) {
      std::vector<std::string> x = twelve("1");
      x[static_cast<std::size_t>(index)] = bad;
      SCOPED_TRACE(hinge_line("\"n\"", x));
      const std::vector<io::HingeLine> lines = read_lines(hinge_line("\"n\"", x));
      ASSERT_EQ(lines.size(), 1u);
      expect_invalid(lines[0], 1);
      EXPECT_EQ(lines[0].error, "\"x\"[" + std::to_string(index) + "] is not a number");
      EXPECT_EQ(lines[0].id_json, "\"n\"");
    }
  }
}

TEST(JsonlRead, NanInfinityAndNonJsonNumberFormsAreNotValidJson) {
  // JSON has no NaN or infinity: such a line is not valid input (never a silent NaN).
  for (const std::string bad :
       {"NaN", "nan", "-NaN", "Infinity", "-Infinity", "inf", "-inf", "+1", ".5", "1.", "01", "0x10", "1e", "--1"}) {
    std::vector<std::string> x = twelve("1");
    x[3] = bad;
    SCOPED_TRACE(bad);
    const std::vector<io::HingeLine> lines = read_lines("\n\n" + hinge_line("\"nan\"", x) + "\n");
    ASSERT_EQ(lines.size(), 1u);
    expect_invalid(lines[0], 3);
    EXPECT_TRUE(starts_with(lines[0].error, "not valid JSON: "));
    EXPECT_TRUE(lines[0].id_json == "null" || lines[0].id_json == "\"nan\"") << lines[0].id_json;
  }
}

TEST(JsonlRead, AnOverflowingCoordinateReadsAsAnInfinityOfItsSign) {
  // jsonl.cpp and docs/testing.md (Bad input 35): 1e400 is valid JSON whose hinge is non-finite input; the
  // evaluation, not the reader, rejects it ("coordinate x0.x is not finite"). Never a NaN.
  std::vector<std::string> x = twelve("0.5");
  x[0] = "1e400";
  x[4] = "-1e400";
  x[7] = "1.7976931348623159e308";  // above max + ulp/2: overflows
  x[8] = "1.7976931348623158e308";  // below it: max
  x[11] = "-123456789e999999";
  const std::vector<io::HingeLine> lines = read_lines(hinge_line("\"big\"", x));
  ASSERT_EQ(lines.size(), 1u);
  ASSERT_TRUE(lines[0].x.has_value()) << lines[0].error;
  const auto& v = *lines[0].x;
  EXPECT_EQ(v[0], HUGE_VAL);
  EXPECT_EQ(v[4], -HUGE_VAL);
  EXPECT_EQ(v[7], HUGE_VAL);
  EXPECT_EQ(v[8], std::numeric_limits<double>::max());
  EXPECT_EQ(v[11], -HUGE_VAL);
  for (int k : {1, 2, 3, 5, 6, 9, 10}) EXPECT_EQ(v[k], 0.5) << "x[" << k << "]";
  EXPECT_EQ(lines[0].id_json, "\"big\"");
}

TEST(JsonlRead, AnOverflowingNumberElsewhereLeavesStringsAndTheHingeAlone) {
  // The overflow is handled by rewriting numbers; text inside strings (an id that looks like a number) and
  // the other fields must not change.
  const std::string line =
      R"({"id": "1e400 \"-1e400\" \\", "weight": 1e999, "x": [0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -1, 2.5e-320]})";
  const std::vector<io::HingeLine> lines = read_lines(line);
  ASSERT_EQ(lines.size(), 1u);
  ASSERT_TRUE(lines[0].x.has_value()) << lines[0].error;
  EXPECT_EQ(Json::parse(lines[0].id_json).get<std::string>(), "1e400 \"-1e400\" \\");
  EXPECT_EQ((*lines[0].x)[10], -1.0);
  EXPECT_EQ((*lines[0].x)[11], 2.5e-320);
}

TEST(JsonlRead, NoLineEverGivesANaNCoordinate) {
  // Every line of a mixed file is either a hinge without a NaN or an invalid line with a reason.
  const std::vector<std::string> texts = {kValid,
                                          "NaN",
                                          hinge_line("\"q\"", twelve("1e400")),
                                          hinge_line("\"q\"", twelve("-0")),
                                          hinge_line("\"q\"", twelve("\"nan\"")),
                                          hinge_line("\"q\"", twelve("1e-400"))};
  std::string text;
  for (const auto& t : texts) text += t + "\n";
  const std::vector<io::HingeLine> lines = read_lines(text);
  ASSERT_EQ(lines.size(), texts.size());
  for (const auto& h : lines) {
    if (h.x) {
      for (double c : *h.x) EXPECT_FALSE(std::isnan(c)) << "line " << h.line;
    } else {
      EXPECT_FALSE(h.error.empty()) << "line " << h.line;
    }
  }
}

// ---------------------------------------------------------------------------------------------------
// The loop of hinge eval: one output line per non-blank input line

TEST(JsonlTransform, WritesOneLineForEveryNonBlankLineInOrder) {
  const std::string input = kValid + "\n\n" +                                       // 1: ok
                            hinge_line("\"input-error\"", twelve("1")) + "\n" +     // 3
                            "not json\n" +                                          // 4
                            "   \n" +                                               // 5: blank
                            hinge_line("\"domain-error\"", twelve("2")) + "\r\n" +  // 6
                            R"({"id": "short", "x": [1]})" + "\n" +                 // 7
                            hinge_line("\"last\"", twelve("3"));                    // 8, no newline
  std::istringstream in(input);
  std::ostringstream out;
  int after = 0;
  std::vector<std::string> written;
  io::transform_hinge_lines(
      in, out, 1,
      [&](const std::string& id_json, const std::array<double, 12>& x) -> std::string {
        written.push_back(id_json);
        if (id_json == "\"input-error\"") throw InputError("degenerate hinge: test");
        if (id_json == "\"domain-error\"") throw DomainError("outside the range of double: test");
        return "RESULT " + id_json + " " + io::format_double(x[0]);
      },
      [&] { ++after; });
  EXPECT_EQ(after, 6);
  EXPECT_EQ(written, (std::vector<std::string>{"\"h\"", "\"input-error\"", "\"domain-error\"", "\"last\""}));
  std::istringstream result(out.str());
  std::vector<std::string> got;
  for (std::string line; std::getline(result, line);) got.push_back(line);
  ASSERT_EQ(got.size(), 6u) << out.str();
  EXPECT_EQ(out.str().back(), '\n');
  EXPECT_EQ(got[0], "RESULT \"h\" 0.0");
  EXPECT_EQ(Json::parse(got[1]), Json::parse(R"({"id": "input-error", "error": "degenerate hinge: test"})"));
  const Json bad = Json::parse(got[2]);
  EXPECT_TRUE(bad["id"].is_null());
  EXPECT_EQ(bad["line"], 4);
  EXPECT_TRUE(bad["error"].is_string());
  EXPECT_EQ(Json::parse(got[3]),
            Json::parse(R"({"id": "domain-error", "error": "outside the range of double: test"})"));
  EXPECT_EQ(Json::parse(got[4]),
            Json::parse(R"({"id": "short", "line": 7, "error": "\"x\" must be an array of 12 numbers"})"));
  EXPECT_EQ(got[5], "RESULT \"last\" 3.0");
}

TEST(JsonlTransform, AShardNumbersItsInvalidLinesFromItsFirstLine) {
  std::istringstream in("\n{}\n");
  std::ostringstream out;
  io::transform_hinge_lines(
      in, out, 500, [](const std::string&, const std::array<double, 12>&) { return std::string("unused"); }, [] {});
  const Json j = Json::parse(out.str());
  EXPECT_EQ(j["line"], 501);
}

// ---------------------------------------------------------------------------------------------------
// Writing results

RoundedTheta rounded_from(const std::vector<double>& values, std::size_t offset) {
  RoundedTheta r;
  r.theta = values[offset % values.size()];
  for (std::size_t k = 0; k < 12; ++k) r.grad[k] = values[(offset + 1 + k) % values.size()];
  for (std::size_t k = 0; k < 144; ++k) r.hess[k] = values[(offset + 13 + k) % values.size()];
  return r;
}

// Every number token of a JSON text, read with std::from_chars (an independent reader of the writer).
std::vector<double> number_tokens(const std::string& text) {
  std::vector<double> out;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '-' || (c >= '0' && c <= '9')) {
      double v = 0;
      const auto [end, ec] = std::from_chars(text.data() + i, text.data() + text.size(), v);
      EXPECT_EQ(ec, std::errc()) << text.substr(i, 30);
      out.push_back(v);
      i = static_cast<std::size_t>(end - text.data()) - 1;
    }
  }
  return out;
}

TEST(JsonlWrite, ResultLinesReadBackBitForBit) {
  const std::vector<double> values = many_doubles(157 * 40, 12);
  for (std::size_t offset = 0; offset < values.size(); offset += 157) {
    const RoundedTheta r = rounded_from(values, offset);
    const std::string line = io::result_line("\"r\"", r);
    ASSERT_EQ(line.find('\n'), std::string::npos);
    // Independently: every number token, in order, is the double written (-0.0 included, bit for bit:
    // io/number.hpp promises "-0.0").
    const std::vector<double> tokens = number_tokens(line);
    ASSERT_EQ(tokens.size(), 157u) << line.substr(0, 200);
    EXPECT_EQ(bits(tokens[0]), bits(r.theta)) << io::format_double(r.theta);
    for (std::size_t k = 0; k < 12; ++k) EXPECT_EQ(bits(tokens[1 + k]), bits(r.grad[k])) << "grad " << k;
    for (std::size_t k = 0; k < 144; ++k) EXPECT_EQ(bits(tokens[13 + k]), bits(r.hess[k])) << "hess " << k;
    // And through the project's own reader of results (hinge conform --candidate).
    std::istringstream in(line + "\n");
    const auto results = io::read_eval_outputs(in, "r.jsonl");
    ASSERT_EQ(results.count("r"), 1u);
    const io::EvalOutput& back = results.at("r");
    ASSERT_EQ(back.status, Status::ok) << back.error;
    EXPECT_TRUE(same_value(r.theta, back.theta));
    for (std::size_t k = 0; k < 12; ++k) EXPECT_TRUE(same_value(r.grad[k], back.grad[k])) << "grad " << k;
    for (std::size_t k = 0; k < 144; ++k) EXPECT_TRUE(same_value(r.hess[k], back.hess[k])) << "hess " << k;
  }
}

TEST(JsonlWrite, AResultLineHoldsExactlyTheDocumentedFields) {
  RoundedTheta r;
  r.theta = 0.25;
  r.grad[3] = -1.5;
  r.hess[143] = 7.0;
  const Json j = Json::parse(io::result_line("\"the-id\"", r));
  ASSERT_TRUE(j.is_object());
  EXPECT_EQ(j.size(), 4u) << j.dump();
  EXPECT_EQ(j["id"], "the-id");
  EXPECT_EQ(j["theta"], 0.25);
  ASSERT_TRUE(j["grad"].is_array());
  ASSERT_EQ(j["grad"].size(), 12u);
  ASSERT_TRUE(j["hess"].is_array());
  ASSERT_EQ(j["hess"].size(), 144u);
  EXPECT_EQ(j["grad"][3], -1.5);
  EXPECT_EQ(j["hess"][143], 7.0);
  // Every number looks like a double, so that a reader never takes it for an integer.
  for (const auto& g : j["grad"]) EXPECT_TRUE(g.is_number_float()) << g.dump();
  for (const auto& h : j["hess"]) EXPECT_TRUE(h.is_number_float()) << h.dump();
}

TEST(JsonlWrite, AnErrorLineHoldsTheIdAndTheReasonAsOneLineOfJson) {
  const std::string why = "degenerate hinge: \"quoted\"\nsecond line \\ and bad UTF-8 \xff\xfe";
  const std::string line = io::error_line("\"e\"", why);
  EXPECT_EQ(line.find('\n'), std::string::npos) << line;
  ASSERT_TRUE(Json::accept(line)) << line;
  const Json j = Json::parse(line);
  EXPECT_EQ(j.size(), 2u) << line;
  EXPECT_EQ(j["id"], "e");
  const std::string back = j["error"].get<std::string>();
  EXPECT_TRUE(starts_with(back, "degenerate hinge: \"quoted\"\nsecond line \\ and bad UTF-8 "));
}

TEST(JsonlWrite, JsonStringEscapesAndReplacesInvalidUtf8) {
  // io/jsonl.hpp: "`s` as a JSON string, quotes and escapes included (invalid UTF-8 replaced)".
  const std::string s = io::json_string("a\"b\\c\n\x01\xff");
  ASSERT_TRUE(Json::accept(s)) << s;
  EXPECT_EQ(s.find('\n'), std::string::npos);
  EXPECT_EQ(Json::parse(s).get<std::string>(), "a\"b\\c\n\x01\xEF\xBF\xBD");  // U+FFFD for the bad byte
  EXPECT_EQ(io::json_string(""), "\"\"");
}

TEST(JsonlWrite, AnInvalidLineWithBadBytesStillGivesValidJson) {
  // The parser's message quotes the bad bytes; the output line must stay valid JSON.
  const std::vector<io::HingeLine> lines = read_lines("\xff\xfe{\"id\": \"\xc3\"}\n");
  ASSERT_EQ(lines.size(), 1u);
  expect_invalid(lines[0], 1);
}

// ---------------------------------------------------------------------------------------------------
// Numbers (io/number.hpp)

TEST(Numbers, FormatDoubleWritesTheDocumentedExamples) {
  EXPECT_EQ(io::format_double(1.0), "1.0");
  EXPECT_EQ(io::format_double(-0.0), "-0.0");
  EXPECT_EQ(io::format_double(0.0), "0.0");
  EXPECT_EQ(io::format_double(1e300), "1e+300");
  EXPECT_EQ(io::format_double(5e-324), "5e-324");
  EXPECT_EQ(io::format_double(0.1), "0.1");
  EXPECT_EQ(io::format_double(-2.5), "-2.5");
}

// The count of significant digits of a decimal text.
int significant_digits(const std::string& s) {
  std::string digits;
  for (char c : s) {
    if (c == 'e') break;
    if (c >= '0' && c <= '9') digits += c;
  }
  const std::size_t first = digits.find_first_not_of('0');
  if (first == std::string::npos) return 1;
  const std::size_t last = digits.find_last_not_of('0');
  return static_cast<int>(last - first + 1);
}

// The fewest significant digits with which the correctly rounded decimal (printf's %.*e) reads back as x.
// (At a power of two another decimal of fewer digits may read back too: this is an upper bound of the
// shortest.)
int fewest_digits_nearest(double x) {
  for (int digits = 1; digits < 17; ++digits) {
    char text[40];
    std::snprintf(text, sizeof text, "%.*e", digits - 1, x);
    if (std::strtod(text, nullptr) == x) return digits;
  }
  return 17;
}

TEST(Numbers, FormatDoubleIsTheShortestTextThatReadsBackExactly) {
  // io/number.hpp: the shortest decimal that reads back exactly (std::to_chars: the fewer characters of
  // the fixed and the scientific form), with ".0" on integral values.
  int failures = 0;
  for (double x : many_doubles(20000, 13)) {
    const std::string s = io::format_double(x);
    double back = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), back);
    const bool exact = ec == std::errc() && end == s.data() + s.size() && bits(back) == bits(x);
    // Looks like a double: a point or an exponent, so that no reader takes it for an integer.
    const bool looks_double = s.find_first_of(".e") != std::string::npos;
    bool shortest = true;
    const bool fixed_integral =
        s.find('e') == std::string::npos && s.size() > 2 && s.compare(s.size() - 2, 2, ".0") == 0;
    if (fixed_integral) {
      // All the integer's digits: then no scientific form with the fewest digits may be shorter.
      const int d = fewest_digits_nearest(x);
      const int exponent = static_cast<int>(s.size()) - 2 - (x < 0) - 1;
      const int scientific = (x < 0) + d + (d > 1) + 2 +
                             (exponent >= 100  ? 3
                              : exponent >= 10 ? 2
                                               : 1) +
                             (exponent < 10);
      shortest = static_cast<int>(s.size()) - 2 <= scientific || x == 0;
    } else {
      // No decimal with one significant digit fewer reads back; in particular not the nearest one.
      const int d = significant_digits(s);
      if (d > 1) {
        char shorter[40];
        std::snprintf(shorter, sizeof shorter, "%.*e", d - 2, x);
        shortest = std::strtod(shorter, nullptr) != x;
      }
    }
    if ((!exact || !looks_double || !shortest) && failures++ < 5)
      ADD_FAILURE() << g17(x) << " written as \"" << s << "\": exact " << exact << ", looks like a double "
                    << looks_double << ", shortest " << shortest;
  }
  EXPECT_EQ(failures, 0);
}

TEST(Numbers, AppendArrayWritesABracketedCommaSeparatedList) {
  const double v[] = {1.0, -0.5, 5e-324, -0.0};
  std::string out = "x";
  io::append_array(out, v, 4);
  EXPECT_EQ(out, "x[1.0, -0.5, 5e-324, -0.0]");
  std::string empty;
  io::append_array(empty, v, 0);
  EXPECT_EQ(empty, "[]");
}

TEST(Numbers, GradientTextRoundTripsBitForBit) {
  const std::vector<double> values = many_doubles(3000, 14);
  const auto path = std::filesystem::temp_directory_path() /
                    ("hinge_numbers_test_" + std::to_string(std::random_device{}()) + ".txt");
  {
    std::ofstream out(path, std::ios::binary);
    io::write_numbers(out, values);
  }
  std::ifstream check(path);
  std::size_t lines = 0;
  for (std::string line; std::getline(check, line);) ++lines;
  EXPECT_EQ(lines, values.size()) << "one number per line";
  const std::vector<double> back = io::read_numbers(path.string());
  std::filesystem::remove(path);
  ASSERT_EQ(back.size(), values.size());
  for (std::size_t i = 0; i < values.size(); ++i) ASSERT_EQ(bits(back[i]), bits(values[i])) << "number " << i;
}

TEST(Numbers, ReadNumbersReadsATokenThatIsNotANumberAsNaN) {
  // io/number.hpp: "a token that is not a number is read as NaN, for the caller to count as non-finite".
  const auto path = std::filesystem::temp_directory_path() /
                    ("hinge_numbers_test_" + std::to_string(std::random_device{}()) + ".txt");
  {
    std::ofstream out(path, std::ios::binary);
    out << "1.5\nabc\n  -0.0\t2e-310 1.0x 0x10\n\n3\n";
  }
  const std::vector<double> v = io::read_numbers(path.string());
  std::filesystem::remove(path);
  ASSERT_EQ(v.size(), 7u);
  EXPECT_EQ(v[0], 1.5);
  EXPECT_TRUE(std::isnan(v[1]));
  EXPECT_EQ(v[2], 0.0);
  EXPECT_EQ(v[3], 2e-310);
  EXPECT_TRUE(std::isnan(v[4]));
  EXPECT_TRUE(std::isnan(v[5])) << "hexadecimal is not read as a number";
  EXPECT_EQ(v[6], 3.0);
}

TEST(Numbers, ReadNumbersNamesAMissingFile) {
  const std::string path = (std::filesystem::temp_directory_path() / "hinge_numbers_test_missing_file.txt").string();
  std::filesystem::remove(path);
  try {
    io::read_numbers(path);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), path));
  }
}

// ---------------------------------------------------------------------------------------------------
// Reading results back (hinge conform --candidate, io/eval_output.hpp)

std::map<std::string, io::EvalOutput> read_results(const std::string& text, const std::string& name = "c.jsonl") {
  std::istringstream in(text);
  return io::read_eval_outputs(in, name);
}

std::string read_results_error(const std::string& text, const std::string& name = "c.jsonl") {
  try {
    read_results(text, name);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no hinge::InputError for:\n" << text;
  return {};
}

std::string ok_line(const std::string& id, double theta) {
  RoundedTheta r;
  r.theta = theta;
  return io::result_line(io::json_string(id), r);
}

TEST(EvalOutputRead, ReadsResultsErrorsAndBlankLinesById) {
  const auto results = read_results(ok_line("a", 0.5) + "\n\n  \r\n" +
                                    io::error_line("\"b\"", "degenerate hinge: why") + "\r\n" + ok_line("c", -0.0));
  ASSERT_EQ(results.size(), 3u);
  EXPECT_EQ(results.at("a").status, Status::ok);
  EXPECT_EQ(results.at("a").theta, 0.5);
  EXPECT_EQ(results.at("b").status, Status::error);
  EXPECT_EQ(results.at("b").error, "degenerate hinge: why");
  EXPECT_EQ(results.at("c").status, Status::ok);
  EXPECT_EQ(results.at("c").theta, 0.0);
}

TEST(EvalOutputRead, ALineWithoutAReadableIdNamesTheFileAndLine) {
  // docs/testing.md, Bad input 43: "c.jsonl:1: not valid JSON, and no \"id\" found".
  EXPECT_EQ(read_results_error("not json at all\n"), "c.jsonl:1: not valid JSON, and no \"id\" found");
  EXPECT_EQ(read_results_error(ok_line("a", 1) + "\n\n{\"theta\": NaN\n", "x.jsonl"),
            "x.jsonl:3: not valid JSON, and no \"id\" found");
  EXPECT_EQ(read_results_error("{\"id\": 5, \"theta\": NaN}\n"), "c.jsonl:1: not valid JSON, and no \"id\" found");
  // Valid JSON whose id is not a string, or that is no object: the message names the line too.
  EXPECT_TRUE(contains(read_results_error(ok_line("a", 1) + "\n{\"id\": 7, \"theta\": 1}\n"), "c.jsonl:2: "));
  EXPECT_TRUE(contains(read_results_error("\n[1, 2]\n"), "c.jsonl:2: "));
  EXPECT_TRUE(contains(read_results_error("{\"theta\": 1}\n"), "c.jsonl:1: "));
}

TEST(EvalOutputRead, ALineThatIsNotJsonButHasAnIdIsMissingWithANaNAndNonFiniteOtherwise) {
  // eval_output.hpp: a line that is not JSON but whose "id" can be found counts as missing if it has a NaN
  // token, else as non-finite.
  std::string hess = "[";
  for (int k = 0; k < 144; ++k) hess += (k ? ", " : "") + std::string(k == 7 ? "NaN" : "0.0");
  hess += "]";
  const auto results = read_results(
      "{\"id\": \"n1\", \"theta\": NaN}\n"
      "{\"id\" : \"n2\", \"theta\": 1e400, \"grad\": []}\n"
      "{\"id\": \"n3\", \"theta\": 1, \"grad\": [0,0,0,0,0,0,0,0,0,0,0,0], \"hess\": " +
      hess + "}\n");
  ASSERT_EQ(results.size(), 3u);
  for (const char* id : {"n1", "n3"}) EXPECT_EQ(results.at(id).status, Status::missing) << id;
  EXPECT_EQ(results.at("n2").status, Status::nonfinite);
}

TEST(EvalOutputRead, NullAndNaNNumbersAreMissingInfinitiesNonFiniteAndMissingArraysMissing) {
  RoundedTheta r;
  Json with_null = Json::parse(io::result_line("\"null-grad\"", r));
  with_null["grad"][4] = nullptr;
  Json short_hess = Json::parse(io::result_line("\"short-hess\"", r));
  short_hess["hess"].erase(143);
  Json no_theta = Json::parse(io::result_line("\"no-theta\"", r));
  no_theta.erase("theta");
  Json string_theta = Json::parse(io::result_line("\"string-theta\"", r));
  string_theta["theta"] = "NaN";
  Json infinite_theta = Json::parse(io::result_line("\"infinite-theta\"", r));
  infinite_theta["theta"] = "-Infinity";
  const auto results = read_results(with_null.dump() + "\n" + short_hess.dump() + "\n" + no_theta.dump() + "\n" +
                                    string_theta.dump() + "\n" + infinite_theta.dump() + "\n");
  ASSERT_EQ(results.size(), 5u);
  EXPECT_EQ(results.at("null-grad").status, Status::missing);
  EXPECT_EQ(results.at("infinite-theta").status, Status::nonfinite);
  EXPECT_EQ(results.at("short-hess").status, Status::missing);
  EXPECT_FALSE(results.at("short-hess").error.empty());
  EXPECT_EQ(results.at("no-theta").status, Status::missing);
  EXPECT_FALSE(results.at("no-theta").error.empty());
  EXPECT_EQ(results.at("string-theta").status, Status::missing);
}

TEST(EvalOutputRead, TheFirstLineOfAnIdCounts) {
  const auto results =
      read_results(ok_line("dup", 1.0) + "\n" + ok_line("dup", 2.0) + "\n" + io::error_line("\"dup\"", "later") + "\n");
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results.at("dup").status, Status::ok);
  EXPECT_EQ(results.at("dup").theta, 1.0);
}

TEST(EvalOutputRead, CheckFiniteMarksAResultWithANaNMissingAndOneWithOnlyAnInfinityNonFinite) {
  for (int where = 0; where < 3; ++where) {
    for (double bad : {std::numeric_limits<double>::quiet_NaN(), HUGE_VAL, -HUGE_VAL}) {
      io::EvalOutput r;
      r.status = Status::ok;
      (where == 0 ? r.theta : where == 1 ? r.grad[11] : r.hess[143]) = bad;
      r.grad[0] = where == 0 ? HUGE_VAL : 0.0;  // an infinity beside a NaN: still not evaluated
      io::check_finite(r);
      EXPECT_EQ(r.status, std::isnan(bad) ? Status::missing : Status::nonfinite) << where << " " << bad;
    }
  }
  io::EvalOutput fine;
  fine.status = Status::ok;
  fine.hess[0] = std::numeric_limits<double>::max();
  fine.grad[0] = std::numeric_limits<double>::denorm_min();
  io::check_finite(fine);
  EXPECT_EQ(fine.status, Status::ok);
  io::EvalOutput error;
  error.status = Status::error;
  error.theta = std::numeric_limits<double>::quiet_NaN();
  io::check_finite(error);
  EXPECT_EQ(error.status, Status::error) << "only an ok result becomes non-finite";
}

TEST(EvalOutputRead, EvalOutputLineRoundTripsAResultAndWritesAnErrorForAnythingElse) {
  const std::vector<double> values = many_doubles(157 * 3, 15);
  io::EvalOutput ok;
  ok.status = Status::ok;
  const RoundedTheta r = rounded_from(values, 157);
  ok.theta = r.theta;
  ok.grad = r.grad;
  ok.hess = r.hess;
  io::EvalOutput error;
  error.status = Status::error;
  error.error = "degenerate hinge: because";
  io::EvalOutput nonfinite;
  nonfinite.status = Status::nonfinite;
  nonfinite.theta = std::numeric_limits<double>::quiet_NaN();
  io::EvalOutput missing;
  const std::string text = io::eval_output_line("ok \"1\"", ok) + "\n" + io::eval_output_line("error", error) + "\n" +
                           io::eval_output_line("nonfinite", nonfinite) + "\n" +
                           io::eval_output_line("missing", missing) + "\n";
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) EXPECT_TRUE(Json::accept(line)) << line;
  const auto back = read_results(text);
  ASSERT_EQ(back.size(), 4u);
  ASSERT_EQ(back.at("ok \"1\"").status, Status::ok);
  EXPECT_EQ(bits(back.at("ok \"1\"").theta), bits(ok.theta));
  for (std::size_t k = 0; k < 12; ++k) EXPECT_EQ(bits(back.at("ok \"1\"").grad[k]), bits(ok.grad[k])) << k;
  for (std::size_t k = 0; k < 144; ++k) EXPECT_EQ(bits(back.at("ok \"1\"").hess[k]), bits(ok.hess[k])) << k;
  EXPECT_EQ(back.at("error").status, Status::error);
  EXPECT_EQ(back.at("error").error, "degenerate hinge: because");
  EXPECT_EQ(back.at("nonfinite").status, Status::error);
  EXPECT_FALSE(back.at("nonfinite").error.empty());
  EXPECT_EQ(back.at("missing").status, Status::error);
  EXPECT_FALSE(back.at("missing").error.empty());
}

TEST(EvalOutputRead, AMissingFileIsNamed) {
  // docs/testing.md, Bad input 42: "cannot read candidate missing.jsonl".
  const std::string path = (std::filesystem::temp_directory_path() / "hinge_eval_output_test_missing.jsonl").string();
  std::filesystem::remove(path);
  try {
    io::read_eval_outputs(path);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "cannot read candidate " + path));
  }
}

}  // namespace
}  // namespace hinge
