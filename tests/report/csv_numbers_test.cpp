// The CSV's number columns written fast: the shortest text as fmt writes it, and a column's recent
// values kept as text give what writing each value afresh gives.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "report/csv_numbers.hpp"

using namespace ncurve;

namespace {

// Values as a path gives them: a few repeated often (a hole's X Y, the R plane and the bottom, a
// feed), new ones among them, and the awkward ones (signed zeros, ties, long and tiny values).
std::vector<double> column_values(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coord(-2000, 2000);
  std::uniform_int_distribution<int> pick(0, 9);
  std::vector<double> pool = {0.0, -0.0, 2.0, -5.0, 300.0, 0.5e-6, 2.675, 1e300, -1.7e308, 1e-300};
  std::vector<double> values;
  for (int i = 0; i < 200000; ++i) {
    const int k = pick(rng);
    if (k < 6) values.push_back(pool[static_cast<std::size_t>(pick(rng))]);
    else if (k < 8 && !values.empty()) values.push_back(values.back());
    else {
      const double v = k == 8 ? coord(rng) : std::round(coord(rng)) / 1024;
      values.push_back(v);
      pool[static_cast<std::size_t>(pick(rng))] = v;
    }
  }
  values.push_back(std::numeric_limits<double>::quiet_NaN());
  values.push_back(std::numeric_limits<double>::infinity());
  values.push_back(-std::numeric_limits<double>::infinity());
  values.push_back(std::numeric_limits<double>::denorm_min());
  return values;
}

template <char* (*Write)(char*, double)>
void expect_kept_texts_as_fresh(std::uint64_t seed) {
  report::RecentNumbers<Write> recent;
  char kept[report::kFixed6Most + 32], fresh[report::kFixed6Most + 32];
  for (double v : column_values(seed)) {
    const std::string a(kept, recent.put(kept, v));
    const std::string b(fresh, Write(fresh, v));
    ASSERT_EQ(a, b) << std::hexfloat << v;
  }
}

}  // namespace

TEST(CsvNumbers, ShortestAsFmtWritesIt) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coord(-2000, 2000);
  std::uniform_int_distribution<std::uint64_t> bits;
  std::vector<double> values = {0.0, -0.0, 300, 1e300, -1.7e308, 5e-324, 0.1, 1e16, 1e-7, 123456789.125};
  for (int i = 0; i < 200000; ++i) values.push_back(coord(rng));
  for (int i = 0; i < 200000; ++i) {
    const double v = std::bit_cast<double>(bits(rng));
    if (std::isfinite(v)) values.push_back(v);
  }
  char text[report::kFixed6Most];
  for (double v : values) ASSERT_EQ(std::string(text, report::shortest(text, v)), fmt::format(",{}", v)) << v;
}

TEST(CsvNumbers, KeptSixDecimalsAreWhatWritingAfreshGives) { expect_kept_texts_as_fresh<report::fixed6>(3); }

TEST(CsvNumbers, KeptShortestTextsAreWhatWritingAfreshGives) { expect_kept_texts_as_fresh<report::shortest>(5); }
