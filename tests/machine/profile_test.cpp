#include <gtest/gtest.h>

#include <filesystem>

#include "machine/library.hpp"
#include "machine/profile.hpp"

using namespace ncurve::machine;

TEST(Profile, ShippedProfilesLoad) {
  auto mill = load_profile(NCURVE_SOURCE_DIR "/profiles/fanuc-mill.toml");
  EXPECT_EQ(mill.type, MachineType::mill);
  EXPECT_EQ(mill.axes, "XYZ");
  EXPECT_EQ(mill.g_code_macros[0], 102);
  EXPECT_DOUBLE_EQ(mill.arc_radius_tolerance, 0.020);
  EXPECT_DOUBLE_EQ(mill.work_offsets[2][0], -250.0);  // G55 at the same place as G54, below machine zero
  auto lathe = load_profile(NCURVE_SOURCE_DIR "/profiles/fanuc-lathe.toml");
  EXPECT_TRUE(lathe.lathe());
  EXPECT_EQ(lathe.axes, "XZ");
  EXPECT_TRUE(lathe.power_on_feed_per_rev);
  EXPECT_DOUBLE_EQ(lathe.reference_points[0][0], 150.0);
}

// TOML gives a table's keys in alphabetical order: "axes" comes before "type", and a lathe's
// default axes (X Z) must not replace the ones the file gives, wherever the two keys stand.
TEST(Profile, LatheKeepsTheAxesTheFileGives) {
  auto c = parse_profile("[machine]\ntype = \"lathe\"\naxes = [\"X\", \"Z\", \"C\"]\n", "p.toml");
  EXPECT_TRUE(c.lathe());
  EXPECT_EQ(c.axes, "XZC");
  auto before = parse_profile("[machine]\naxes = [\"X\", \"Z\", \"C\"]\ntype = \"lathe\"\n", "p.toml");
  EXPECT_EQ(before.axes, "XZC");
  EXPECT_EQ(parse_profile("[machine]\ntype = \"lathe\"\n", "p.toml").axes, "XZ");
  EXPECT_THROW(parse_profile("[machine]\ntype = \"lathe\"\naxes = [\"X\", \"Z\", \"C\"]\n[feeds]\nrapid = [1, 2]\n",
                             "p.toml"),
               std::runtime_error);
}

TEST(Profile, ThirtyIRaisesNestingAndIncrementSystem) {
  auto p = parse_profile("[machine]\ncontrol = \"30i\"\nincrement_system = \"IS-C\"\n[parameters]\n\"3410\" = 20\n", "p.toml");
  EXPECT_EQ(p.control, Control::fanuc_30i);
  EXPECT_EQ(p.macro_nesting, 5);
  EXPECT_DOUBLE_EQ(p.increment, 0.0001);
  EXPECT_DOUBLE_EQ(p.arc_radius_tolerance, 0.002);
}

// FANUC 0i reads 8 digits in a number (PS0003 beyond); a profile may allow up to 15.
TEST(Profile, NumberDigitsReachTheParser) {
  const std::string program = "O1\n#1=3.14159265358979\nM30\n";
  ProgramLibrary zero_i(default_mill().parse_options());
  auto problems = zero_i.add_text("t.nc", program, true);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].code, "PS0003");
  EXPECT_EQ(problems[0].span.line, 2u);
  auto wide = parse_profile("[machine]\nnumber_digits = 15\n", "p.toml");
  ProgramLibrary thirty(wide.parse_options());
  EXPECT_TRUE(thirty.add_text("t.nc", program, true).empty());
  EXPECT_THROW(parse_profile("[machine]\nnumber_digits = 7\n", "p.toml"), std::runtime_error);
  EXPECT_THROW(parse_profile("[machine]\nnumber_digits = 16\n", "p.toml"), std::runtime_error);
}

TEST(Profile, UnknownKeysAreErrorsWithPosition) {
  try {
    parse_profile("[machine]\ntype = \"mill\"\nspeed = 3\n", "p.toml");
    FAIL() << "accepted an unknown key";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("p.toml:3:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("speed"), std::string::npos);
  }
  EXPECT_THROW(parse_profile("[parameters]\n\"1234\" = 1\n", "p.toml"), std::runtime_error);
  EXPECT_THROW(parse_profile("[machine]\naxes = [\"X\", \"X\"]\n", "p.toml"), std::runtime_error);
  EXPECT_THROW(parse_profile("[machine\n", "p.toml"), std::runtime_error);
  EXPECT_THROW(parse_profile("[work_offsets]\nG54 = [1, 2]\n", "p.toml"), std::runtime_error);
}

// A bit parameter takes true/false or 0/1, as a float too; any other number (one past int64's
// range among them, which the TOML library would convert undefined) is refused at its line.
TEST(Profile, BitParametersTakeZeroOrOne) {
  EXPECT_TRUE(parse_profile("[parameters]\n\"3401#0\" = 1\n", "p.toml").decimal_calculator);
  EXPECT_TRUE(parse_profile("[parameters]\n\"3401#0\" = 1.0\n", "p.toml").decimal_calculator);
  EXPECT_FALSE(parse_profile("[parameters]\n\"3401#0\" = false\n", "p.toml").decimal_calculator);
  for (const char* v : {"2", "0.5", "1e33", "-1e300", "nan"}) {
    try {
      parse_profile(std::string("[parameters]\n\"3401#0\" = ") + v + "\n", "p.toml");
      ADD_FAILURE() << v << " taken as a bit";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("p.toml:2:"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("must be true/false or 0/1"), std::string::npos) << e.what();
    }
  }
}

TEST(Profile, MotionAndServoTables) {
  auto mill = load_profile(NCURVE_SOURCE_DIR "/profiles/fanuc-mill.toml");
  EXPECT_EQ(mill.motion.look_ahead, 30);
  EXPECT_DOUBLE_EQ(mill.motion.acceleration[2], 800.0);
  EXPECT_DOUBLE_EQ(mill.motion.corner_speed[0], 400.0);
  EXPECT_DOUBLE_EQ(mill.servo.kv[1], 30.0);
  auto p = parse_profile("[machine]\naxes = [\"X\", \"Y\"]\n[motion]\nacc_dec = \"after\"\nfilter = \"exponential\"\n"
                         "time_constant = [0.03, 0.05]\n[servo]\nkv = [25, 20]\nfeed_forward = 0.5\n",
                         "p.toml");
  EXPECT_EQ(p.motion.acc_dec, AccDec::after);
  EXPECT_EQ(p.motion.filter, Filter::exponential);
  EXPECT_DOUBLE_EQ(p.motion.time_constant[1], 0.05);
  EXPECT_DOUBLE_EQ(p.servo.kv[0], 25.0);
  EXPECT_DOUBLE_EQ(p.servo.feed_forward, 0.5);
  auto error = [](const std::string& text) {
    try {
      parse_profile(text, "bad.toml");
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error("[motion]\nacceleration = [1000, 0, 1000]\n").find("bad.toml:2:"), std::string::npos);
  EXPECT_NE(error("[motion]\nlook_ahead = 2.5\n").find("whole number"), std::string::npos);
  EXPECT_NE(error("[servo]\nfeed_forward = 1.5\n").find("0 to 1"), std::string::npos);
  EXPECT_NE(error("[servo]\ngain = 30\n").find("unknown key 'gain'"), std::string::npos);
  EXPECT_NE(error("[motion]\nacc_dec = \"during\"\n").find("acc_dec must be"), std::string::npos);
}

TEST(Profile, EveryShippedProfileLoads) {
  int loaded = 0;
  for (const auto& entry : std::filesystem::directory_iterator(NCURVE_SOURCE_DIR "/profiles")) {
    if (entry.path().extension() != ".toml") continue;
    EXPECT_NO_THROW(load_profile(entry.path().string())) << entry.path();
    ++loaded;
  }
  EXPECT_GE(loaded, 5);
  EXPECT_EQ(load_profile(NCURVE_SOURCE_DIR "/profiles/seed001.toml").motion.look_ahead, 0);
}
