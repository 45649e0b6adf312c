// The analyze feed plot's trace: blocks drawn as they ran while few, then bins of path length
// that keep the lowest feed, never more than kBins whatever the number of blocks.
#include <gtest/gtest.h>

#include "report/feed_trace.hpp"

namespace ncurve::report {
namespace {

FeedTrace::Block block(double length, double feed) { return {length, 1000, feed, feed, feed, 0, 0, false}; }

TEST(FeedTrace, FewBlocksAsTheyRan) {
  FeedTrace t;
  t.add({2, 1000, 0, 800, 0, 0.5, 0.5, false});
  t.add({3, 1000, 0, 1000, 100, 1, 1, true});
  const auto s = t.samples();
  ASSERT_EQ(s.size(), 8u);  // in, peak, peak, out of each
  EXPECT_DOUBLE_EQ(s[1].path, 0.5);
  EXPECT_DOUBLE_EQ(s[1].reached, 800);
  EXPECT_DOUBLE_EQ(s[4].path, 2);
  EXPECT_DOUBLE_EQ(s[7].path, 5);
  EXPECT_TRUE(s[7].starved);
}

TEST(FeedTrace, ManyBlocksBoundedWithTheirDips) {
  for (std::size_t n : {FeedTrace::kDetailed + 1, std::size_t{10000}, std::size_t{1000000}}) {
    FeedTrace t;
    for (std::size_t i = 0; i < n; ++i) t.add(block(1, i == n / 2 ? 5.0 : 900.0));  // one dip in the middle
    const auto s = t.samples();
    EXPECT_LE(s.size(), FeedTrace::kBins) << n;
    EXPECT_GE(s.size(), FeedTrace::kBins / 4) << n;
    EXPECT_DOUBLE_EQ(t.length(), static_cast<double>(n));
    double lowest = 1e9, last = -1;
    bool ordered = true;
    for (const auto& x : s) {
      lowest = std::min(lowest, x.reached);
      ordered = ordered && x.path > last;
      last = x.path;
      EXPECT_LE(x.path, static_cast<double>(n));
    }
    EXPECT_EQ(lowest, 5.0) << n << ": the dip is kept";
    EXPECT_TRUE(ordered) << n;
  }
}

}  // namespace
}  // namespace ncurve::report
