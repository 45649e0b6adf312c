// The feed along the cutting path for the analyze plot, in bounded memory: up to kDetailed blocks
// each drawn as it ran (in, peak, peak, out), beyond that the lowest feed reached per bin of path
// length (dips stay visible), the bins doubling in width as the path grows so that there are never
// more than kBins of them, however long the program.
#pragma once
#include <algorithm>
#include <cstddef>
#include <vector>

#include "report/motion_plots.hpp"

namespace ncurve::report {

class FeedTrace {
public:
  static constexpr std::size_t kBins = 3000, kDetailed = kBins / 4;

  struct Block {
    double length, programmed, v_in, v_peak, v_out, up, down;  // mm, mm/min; up, down: mm to and from the peak
    bool starved;
  };

  void add(const Block& b) {
    if (bins_.empty() && blocks_.size() < kDetailed) {
      blocks_.push_back({length_, b});
      length_ += b.length;
      return;
    }
    if (bins_.empty()) {  // the first block past the detailed ones: all into bins
      width_ = std::max(length_ + b.length, 1e-9) / (kBins / 2);
      bins_.assign(kBins, Bin{});
      for (const auto& [s0, kept] : blocks_) bin(s0, kept);
      blocks_.clear();
      blocks_.shrink_to_fit();
    }
    bin(length_, b);
    length_ += b.length;
  }

  std::vector<FeedSample> samples() const {
    std::vector<FeedSample> out;
    for (const auto& [s0, b] : blocks_) {
      out.push_back({s0, b.programmed, b.v_in, b.starved});
      out.push_back({s0 + b.up, b.programmed, b.v_peak, b.starved});
      out.push_back({s0 + b.length - b.down, b.programmed, b.v_peak, b.starved});
      out.push_back({s0 + b.length, b.programmed, b.v_out, b.starved});
    }
    for (std::size_t k = 0; k < bins_.size(); ++k)
      if (bins_[k].used) out.push_back({width_ * static_cast<double>(k), bins_[k].programmed, bins_[k].reached, bins_[k].starved});
    return out;
  }
  double length() const { return length_; }

private:
  struct Bin {
    double programmed = 0, reached = 0;
    bool starved = false, used = false;
  };
  void bin(double s0, const Block& b) {
    while (s0 >= width_ * kBins) {  // twice as wide: pairs merged
      for (std::size_t k = 0; k < kBins; ++k) {
        Bin merged{};
        for (std::size_t j : {2 * k, 2 * k + 1})
          if (j < kBins && bins_[j].used) merge(merged, bins_[j]);
        bins_[k] = merged;
      }
      width_ *= 2;
    }
    const auto k = std::min(static_cast<std::size_t>(s0 / width_), kBins - 1);
    merge(bins_[k], Bin{b.programmed, std::min({b.v_in, b.v_peak, b.v_out}), b.starved, true});
  }
  static void merge(Bin& into, const Bin& b) {
    if (!into.used) {
      into = b;
      return;
    }
    into.programmed = std::max(into.programmed, b.programmed);
    into.reached = std::min(into.reached, b.reached);
    into.starved = into.starved || b.starved;
  }
  std::vector<std::pair<double, Block>> blocks_;  // (path length at the start, block)
  std::vector<Bin> bins_;
  double width_ = 0, length_ = 0;
};

}  // namespace ncurve::report
