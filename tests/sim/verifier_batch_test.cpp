// The verifier cuts its moves in batches and checks them when a batch is cut: a program longer than
// a batch keeps each finding at its block, with the state (spindle, holder contact) of its move, and
// the volume is the whole cut's. The depths are worked by hand from the stock and the tool.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/verifier.hpp"
#include "support/run_program.hpp"

using namespace ncurve;

namespace {

constexpr double kPi = std::numbers::pi;

// A 100 x 100 x 20 block, top at Z0; T5 a 10 mm end mill with 20 mm flutes in a 40 mm holder 20 mm
// above its tip.
const char* const kSetup = R"(
[stock]
shape = "box"
min = [-50, -50, -20]
max = [50, 50, 0]

[tools.5]
kind = "flat"
diameter = 10
flute_length = 20
stick_out = 20
holder = [{ diameter = 40, length = 30 }]
)";

}  // namespace

TEST(VerifierBatches, FindingsKeepTheirMovesAcrossBatches) {
  // 4,400 passes along a slot 1 mm deep (more moves than a batch holds), then a plunge through the
  // block to Z-25 whose holder face reaches Z-5, then a feed into the block with the spindle stopped
  const std::string program =
      "T5 M06\nM03 S1000\nG90 G00 X-10. Y0 Z5.\nG01 Z-1. F500.\n#1=0\nWHILE[#1LT2200]DO1\nX10.\nX-10.\n"
      "#1=#1+1\nEND1\nG01 Z-25.\nG00 Z30.\nM05\nX30. Y30.\nG01 Z-2.\nG00 Z30.\nM30\n";
  const machine::MachineProfile profile = test::calculator_mill();
  const test::Ran ran = test::run(program, profile);
  ASSERT_TRUE(ran.result.ok());
  const sim::SetupFile setup = sim::parse_setup(kSetup, "s.toml");
  sim::MillTools tools(setup.tools, profile);
  sim::VerifyOptions o;
  o.cell = 0.1;
  sim::Verifier v(*setup.stock, tools, setup.tool_in_spindle, o);
  std::size_t motions = 0;
  for (const auto& m : ran.moves) {
    v.on_move(m);
    motions += m.is_motion();
  }
  ASSERT_GT(motions, sim::ZMap::kBatchSweeps);

  ASSERT_EQ(v.findings().size(), 2u);
  const sim::Finding& holder = v.findings()[0];
  EXPECT_EQ(holder.diagnostic.code, "NC2085");
  EXPECT_EQ(holder.diagnostic.span.line, 11u);
  EXPECT_DOUBLE_EQ(holder.amount, 5.0);  // the holder's face at Z-5 under the block's top
  const sim::Finding& stopped = v.findings()[1];
  EXPECT_EQ(stopped.diagnostic.code, "NC2083");  // and only here: the slot was cut with the spindle on
  EXPECT_EQ(stopped.diagnostic.span.line, 15u);
  EXPECT_DOUBLE_EQ(stopped.amount, 2.0);

  // the slot (20 x 10 with round ends, 1 deep), the plunge's hole through the block (19 deeper), and
  // the hole at X30 Y30
  const double want = (20 * 10 + 25 * kPi) + 19 * 25 * kPi + 2 * 25 * kPi;
  const double bound = std::sqrt(2.0) * 0.1 * ((2 * 20 + 10 * kPi) + 19 * 10 * kPi + 2 * 10 * kPi);
  ASSERT_EQ(v.volume_by_tool().size(), 1u);
  EXPECT_NEAR(v.volume_by_tool().at(5), want, bound);
  EXPECT_NEAR(v.volume_by_tool().at(5), v.map().volume_removed(), 1e-9 * want);
}
