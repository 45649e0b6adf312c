// The moves a run cut, each with its tool, kept to ask afterwards how low the tools went over any
// point of the plane: exactly at that point, not at a cell's centre (a wall between two cells).
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "machine/move.hpp"
#include "sim/zmap.hpp"

namespace ncurve::sim {

class CutLog {
public:
  struct Cut {
    std::uint32_t tool = 0;  // index into shapes()
    bool is_arc = false;
    Point3 a{}, b{};         // the tip's ends
    Arc arc{};               // is_arc: the tip's arc or helix
    const nc::SourceFile* file = nullptr;
    std::uint32_t line = 0;  // the block
    bool compensated = false;  // under G41/G42
  };
  struct Lowest {
    double z = kUnreached;
    std::int64_t cut = -1;  // the cut that went lowest there
  };

  // most_cuts: more are refused (base::BoundExceeded naming the move), about 150 bytes each.
  explicit CutLog(std::size_t most_cuts = 2000000) : most_(most_cuts) {}
  void add(const ToolShape& tool, const Point3& a, const Point3& b, const std::optional<Arc>& arc,
           const machine::Move& from);

  std::size_t size() const { return cuts_.size(); }
  const Cut& operator[](std::size_t k) const { return cuts_[k]; }
  const ToolShape& shape(const Cut& c) const { return shapes_[c.tool]; }
  double largest_radius() const { return largest_radius_; }
  bool any_compensated() const { return any_compensated_; }

  // The lowest point of all the cuts' swept tools on the vertical line through (x, y).
  Lowest lowest_at(double x, double y) const;
  // Whether some cut went below z over (x, y), and which (the first found, not the lowest).
  std::int64_t any_below(double x, double y, double z) const;
  // The cut whose tip path passes nearest (x, y) in the plane, and how near; -1 when none.
  std::int64_t nearest(double x, double y, double* distance = nullptr) const;

private:
  double lowest_of(const Cut& c, double x, double y) const;
  double distance_of(const Cut& c, double x, double y) const;
  void index() const;  // the buckets, built on the first query after a cut
  template <class Visit>
  void visit(double x, double y, const Visit& v) const;

  std::size_t most_;
  std::vector<ToolShape> shapes_;
  std::vector<Cut> cuts_;
  double largest_radius_ = 0;
  bool any_compensated_ = false;
  // a square grid of buckets over the cuts' reach: each lists the cuts that can reach into it
  mutable bool indexed_ = false;
  mutable double gx0_ = 0, gy0_ = 0, gcell_ = 1;
  mutable int gnx_ = 0, gny_ = 0;
  mutable std::vector<std::uint32_t> first_, items_;  // bucket b: items_[first_[b] .. first_[b + 1])
};

}  // namespace ncurve::sim
