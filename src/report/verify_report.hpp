// What `ncurve run --setup/--verify` found: the stock and the tools it cut with, the defaults that
// stood in for a setup, the material removed, and why nothing was verified when it was not.
#pragma once
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "sim/design_check.hpp"
#include "sim/curve_walls.hpp"
#include "sim/lathe_section_sink.hpp"
#include "sim/verifier.hpp"

namespace ncurve::report {

// The cut part's walls measured against a curve (--curve).
struct CurveCheck {
  std::string curve;                        // its name
  double tol = 0;                           // mm
  const sim::WallReport* walls = nullptr;   // null: not measured (refused says why)
  sim::BlockOf block;                       // the block of a wall point's cut (none: not named)
  std::vector<sim::Finding> findings;       // NC2087, NC2088
  std::string refused;
};

struct VerifyReport {
  std::string setup_file;                   // empty: no setup file
  std::optional<sim::Stock> stock;          // the stock cut
  bool stock_default = false;               // the box around the cutting moves
  const sim::Verifier* verifier = nullptr;  // a mill's; null: not verified (see refused) or a lathe
  const sim::LatheSection* section = nullptr;            // a lathe's half-section
  const sim::LatheSectionSink* section_sink = nullptr;
  std::string refused;                      // why nothing was verified
  std::vector<std::string> defaults;        // the defaults in force, in words
  std::vector<std::string> tools;           // each tool used, in words
  std::vector<std::string> fixtures;        // each fixture and whether it was checked
  std::string part_file;                    // where --part wrote the part
  const sim::DesignResult* design = nullptr;  // --design's check, after the run
  std::string design_file;
  std::optional<CurveCheck> curve;
};

// The summary's lines for it (two spaces in, as the summary's), and its JSON object.
std::string verify_text(const VerifyReport& r);
nlohmann::json verify_json(const VerifyReport& r);
// The lines (labels padded to `width`) and object of the walls against the curve alone.
std::string curve_text(const CurveCheck& c, int width);
nlohmann::json curve_json(const CurveCheck& c);
// The walls' errors as the pages colour the part by them: {tol, points: base64 of float32 X Y error
// for each wall point measured, X Y where the wall was found} (docs/html.md).
nlohmann::json deviation_json(const CurveCheck& c);
// "75.6 mm^3 (T1 75.6)": the material removed, in all and by tool; empty when nothing was verified.
std::string removed_text(const VerifyReport& r);

}  // namespace ncurve::report
