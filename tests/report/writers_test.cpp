#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <random>
#include <sstream>
#include <vector>

#include "report/summary.hpp"
#include "report/writers.hpp"
#include "support/run_program.hpp"

using namespace ncurve;

namespace {
std::string write(const std::string& program, const std::string& format, machine::MachineProfile p,
                  double arc_tol = 0.001) {
  machine::ProgramLibrary lib;
  lib.add_text("w.nc", program, true);
  std::ostringstream out;
  std::unique_ptr<machine::MoveSink> sink;
  report::GcodeWriter* g = nullptr;
  if (format == "csv") sink = std::make_unique<report::CsvWriter>(out, p, arc_tol);
  else if (format == "jsonl") sink = std::make_unique<report::JsonlWriter>(out, p);
  else {
    auto w = std::make_unique<report::GcodeWriter>(out, p, "w.nc");
    g = w.get();
    sink = std::move(w);
  }
  machine::Interpreter in(p, lib);
  auto r = in.run(*sink);
  EXPECT_TRUE(r.ok());
  if (g) g->finish();
  return out.str();
}
}  // namespace

TEST(Writers, CsvArcPointsStayWithinTheChordTolerance) {
  std::string csv = write("G00 X10. Y0.\nG03 X-10. Y0. R10. F100.\nM30\n", "csv", machine::default_mill(), 0.001);
  std::istringstream in(csv);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "line,kind,x,y,z,f");
  std::vector<std::pair<double, double>> pts;
  std::string row;
  while (std::getline(in, row)) {
    std::istringstream rs(row);
    std::string line, kind, x, y, z, f;
    std::getline(rs, line, ',');
    std::getline(rs, kind, ',');
    std::getline(rs, x, ',');
    std::getline(rs, y, ',');
    if (kind == "arc") {
      EXPECT_EQ(line, "2");
      pts.emplace_back(std::stod(x), std::stod(y));
    }
  }
  // a half circle of R10 at 1 um chord error needs ceil(pi / (2 acos(1 - 0.001/10))) = 112 chords
  ASSERT_EQ(pts.size(), 112u);
  double prev_x = 10, prev_y = 0;
  for (auto [x, y] : pts) {
    EXPECT_NEAR(std::hypot(x, y), 10.0, 1e-6);
    double chord = std::hypot(x - prev_x, y - prev_y);
    double sagitta = 10 - std::sqrt(100 - chord * chord / 4);
    EXPECT_LE(sagitta, 0.001 + 1e-9);
    prev_x = x;
    prev_y = y;
  }
}

TEST(Writers, CsvLatheXIsADiameter) {
  std::string csv = write("G00 X50. Z2.\nM30\n", "csv", machine::default_lathe());
  EXPECT_NE(csv.find("1,rapid,50.000000,0.000000,2.000000"), std::string::npos) << csv;
}

TEST(Writers, JsonlOneObjectPerMove) {
  std::string j = write("G00 X1. Y2.\nG02 X3. Y2. R1. F100.\nM30\n", "jsonl", test::zero_offset_mill());
  std::istringstream in(j);
  std::string l1, l2, l3;
  std::getline(in, l1);
  std::getline(in, l2);
  std::getline(in, l3);
  EXPECT_NE(l1.find(R"("kind":"rapid")"), std::string::npos);
  EXPECT_NE(l1.find(R"("end":[1,2,0])"), std::string::npos) << l1;
  EXPECT_NE(l2.find(R"("kind":"arc")"), std::string::npos);
  EXPECT_NE(l2.find(R"("center":[2,2,0])"), std::string::npos) << l2;
  EXPECT_NE(l2.find(R"("direction":"G02")"), std::string::npos);
  EXPECT_NE(l2.find(R"("line":2)"), std::string::npos);
  EXPECT_NE(l3.find(R"("kind":"program_end")"), std::string::npos);
}

TEST(Writers, ExpandedGcodeRunsToTheSamePath) {
  std::string macro = "G00 X10. Y0.\n#1=0\nWHILE [#1 LT 90] DO1\n#1=#1+15.\nG01 X[10*COS[#1]] Y[10*SIN[#1]] F300.\nEND1\n"
                      "G02 X0 Y0 R5. \nG91 G03 X0 I-2. J0.\nM30\n";
  auto p = machine::default_mill();
  std::string expanded = write(macro, "gcode", p);
  EXPECT_EQ(expanded.find('#'), std::string::npos);
  EXPECT_EQ(expanded.find("WHILE"), std::string::npos);
  auto original = test::run(macro, p).motions();
  auto again = test::run(expanded, p);
  ASSERT_TRUE(again.result.ok()) << nc::format(*again.result.alarm) << "\n" << expanded;
  auto replay = again.motions();
  ASSERT_EQ(original.size(), replay.size());
  for (std::size_t i = 0; i < original.size(); ++i) {
    EXPECT_EQ(original[i].kind, replay[i].kind);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(original[i].end[a], replay[i].end[a], 1e-9) << i;
    EXPECT_NEAR(original[i].sweep, replay[i].sweep, 1e-9);
  }
}

namespace {
// Every motion's start and end in work coordinates: a frame the expansion left out shows as a
// start that differs.
void expect_same_path(const std::vector<machine::Move>& a, const std::vector<machine::Move>& b,
                      const std::string& expanded) {
  ASSERT_EQ(a.size(), b.size()) << expanded;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].kind, b[i].kind) << i;
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(a[i].start[k], b[i].start[k], 1e-9) << i << " axis " << k << "\n" << expanded;
      EXPECT_NEAR(a[i].end[k], b[i].end[k], 1e-9) << i << " axis " << k << "\n" << expanded;
    }
  }
}
}  // namespace

// A hand-written program in G55 (X100 Y50 on the profile): the expansion starts with the modal
// setup, G55 included, and writes only the axes that move.
TEST(Writers, ExpandedGcodeKeepsTheWorkOffsetAndWritesTheAxesThatMove) {
  auto p = machine::default_mill();
  p.work_offsets[2] = {100, 50, 0, 0, 0, 0};
  const std::string program = "G55 G90 G00 X10. Y10. Z5.\nG01 Z-1. F200.\nG01 Y20.\nG00 Z5.\nM30\n";
  std::string g = write(program, "gcode", p);
  EXPECT_NE(g.find("O0001 (EXPANDED BY NCURVE FROM w.nc)\nG17 G21 G40 G80 G90 G94 G55 G49\n"
                   "G00 X10. Y10. Z5.\nG01 Z-1. F200.\nG01 Y20.\nG00 Z5.\nM30\n"),
            std::string::npos)
      << g;
  // started on a machine in G91, G18 and feed per revolution, it still cuts at G55's X110 Y60
  auto other = p;
  other.power_on_g91 = true;
  other.power_on_plane = 18;
  other.power_on_feed_per_rev = true;
  auto again = test::run(g, other);
  ASSERT_TRUE(again.result.ok()) << nc::format(*again.result.alarm) << "\n" << g;
  expect_same_path(test::run(program, p).motions(), again.motions(), g);
}

// G54 to G55 in the middle, then G92: each new frame is set up before the move that uses it; G92's
// shift of the origin (-10, -10 from G55's X100) is written as the G52 that gives the same origin.
TEST(Writers, ExpandedGcodeFollowsTheFramesOfTheRun) {
  auto p = test::zero_offset_mill();
  p.work_offsets[2] = {100, 0, 0, 0, 0, 0};
  const std::string program = "G54 G00 X10. Y0.\nG55 G00 X10.\nG92 X20. Y10.\nG01 X30. F100.\n"
                              "G54 G00 X0.\nM30\n";
  std::string g = write(program, "gcode", p);
  // at G55 X10 (machine X110, Y0), G92 X20 Y10 puts the origin at X90 Y-10: 10 and 10 short of G55's
  EXPECT_NE(g.find("G54 G49\nG00 X10.\nG55\nG00 X10.\nG52 X-10. Y-10. Z0.\nG01 X30. F100.\nG54\nG00 X0.\n"),
            std::string::npos)
      << g;
  auto again = test::run(g, p);
  ASSERT_TRUE(again.result.ok()) << nc::format(*again.result.alarm) << "\n" << g;
  expect_same_path(test::run(program, p).motions(), again.motions(), g);
}

// G43 H1 (Z offset 20) in the run: the expansion sets it up where the run did.
TEST(Writers, ExpandedGcodeKeepsTheToolLengthOffset) {
  auto p = machine::default_mill();
  p.tool_offsets[1].geometry = 20;
  const std::string program = "T1 M06\nG43 H1 G00 Z50.\nG01 Z0. F100.\nG49 G00 Z100.\nM30\n";
  std::string g = write(program, "gcode", p);
  EXPECT_NE(g.find("T1 M06\nG43 H1\nG00 Z50.\nG01 Z0. F100.\nG49\nG00 Z100.\n"), std::string::npos) << g;
  auto again = test::run(g, p);
  ASSERT_TRUE(again.result.ok()) << nc::format(*again.result.alarm) << "\n" << g;
  expect_same_path(test::run(program, p).motions(), again.motions(), g);
}

TEST(Writers, SummaryJsonHasTheCounts) {
  machine::ProgramLibrary lib;
  lib.add_text("s.nc", "O1\nG00 X10.\nG01 X20. F100.\nM30\n", true);
  auto p = machine::default_mill();
  machine::Interpreter in(p, lib);
  machine::NullSink sink;
  auto r = in.run(sink);
  report::RunReport rep{"s.nc", &p, &r, report::source_stats(lib, lib.main()->file.get()), {}};
  std::string j = report::summary_json(rep);
  EXPECT_NE(j.find(R"("blocks_executed": 3)"), std::string::npos) << j;
  EXPECT_NE(j.find(R"("feed_length_mm": 10.0)"), std::string::npos) << j;
  EXPECT_NE(j.find(R"("source_words": 7)"), std::string::npos) << j;  // O1 G00 X G01 X F M30
  EXPECT_NE(j.find(R"("ok": true)"), std::string::npos);
}

TEST(Writers, JsonOfAFileNameThatIsNotUtf8) {
  // a Latin-1 file name (bytes that are not UTF-8) is written with U+FFFD, not refused by the JSON
  const std::string name = "caf\xE9.nc", written = "caf\xEF\xBF\xBD.nc";
  machine::ProgramLibrary lib;
  lib.add_text(name, "O1\nG01 X20. F100.\nM30\n", true);
  auto p = machine::default_mill();
  machine::Interpreter in(p, lib);
  std::ostringstream lines;
  report::JsonlWriter jsonl(lines, p);
  auto r = in.run(jsonl);
  EXPECT_NE(lines.str().find("\"file\":\"" + written + "\""), std::string::npos) << lines.str();
  report::RunReport rep{name, &p, &r, report::source_stats(lib, lib.main()->file.get()), {}};
  std::string j;
  EXPECT_NO_THROW(j = report::summary_json(rep));
  EXPECT_NE(j.find("\"source\": \"" + written + "\""), std::string::npos) << j;
}

// A profile with A gets an `a` column after f; roll-over axes go into the G code as continuous angles.
TEST(Writers, RotaryAxesInEveryFormat) {
  auto p = machine::parse_profile("[machine]\naxes = [\"X\", \"Y\", \"Z\", \"A\"]\n[parameters]\n"
                                  "\"1006#0\" = [0, 0, 0, 1]\n\"1008#0\" = [0, 0, 0, 1]\n",
                                  "r.toml");
  const std::string program = "G90 G00 A0.\nG91 A380.\nG90 A-30.\nM30\n";
  std::string csv = write(program, "csv", p);
  // A 0 -> 380 (the position is then 20) -> -30 = 330 the shorter way: 20 - 50 = -30
  EXPECT_EQ(csv, "line,kind,x,y,z,f,a\n1,rapid,0.000000,0.000000,0.000000,0,0.000000\n"
                 "1,rapid,0.000000,0.000000,0.000000,0,0.000000\n2,rapid,0.000000,0.000000,0.000000,0,380.000000\n"
                 "3,rapid,0.000000,0.000000,0.000000,0,-30.000000\n");
  std::string g = write(program, "gcode", p);
  // the first block moves nothing (every axis is at 0 already) and keeps its axes; then only A turns
  EXPECT_NE(g.find("G00 X0. Y0. Z0. A0.\nG00 A380.\nG00 A330.\n"), std::string::npos) << g;
  std::string j = write(program, "jsonl", p);
  EXPECT_NE(j.find(R"("end_abc":[380,0,0])"), std::string::npos) << j;
  // the 3-axis header stays as it was
  EXPECT_EQ(write("G00 X1.\nM30\n", "csv", machine::default_mill()).substr(0, 18), "line,kind,x,y,z,f\n");
}

// Tens of thousands of rows (more than a megabyte of CSV): each row as worked out from its block, in both
// formats, so a record left in the writer's buffer, written twice or run into the next would show.
TEST(Writers, EveryRowOfALongProgramAsItsBlockSaysInCsvAndJsonl) {
  auto p = machine::parse_profile("[machine]\naxes = [\"X\", \"Y\", \"Z\", \"A\"]\n", "a.toml");
  // thousandths: "-12.345" for the block, "-12.345000" for the CSV, "-12.345" for JSON (its shortest form)
  auto word = [](long t) {
    const long a = t < 0 ? -t : t;
    return fmt::format("{}{}.{:03}", t < 0 ? "-" : "", a / 1000, a % 1000);
  };
  auto json = [&](long t) {
    std::string s = word(t);
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s == "-0" ? std::string("0") : s;
  };
  const int n = 30000;
  std::string program = "G90 G21 G17 G01 X0 Y0 Z0 A0 F1.\n";
  std::string csv = "line,kind,x,y,z,f,a\n1,line,0.000000,0.000000,0.000000,1,0.000000\n"
                    "1,line,0.000000,0.000000,0.000000,1,0.000000\n";
  std::vector<std::string> ends{"0,0,0"};
  unsigned long seed = 12345;
  auto next = [&](long range) {  // -range .. range
    seed = seed * 6364136223846793005UL + 1442695040888963407UL;
    return static_cast<long>((seed >> 33) % static_cast<unsigned long>(2 * range + 1)) - range;
  };
  for (int i = 0; i < n; ++i) {
    const long x = next(999999), y = next(99999), z = i % 7 == 0 ? 0 : next(50000), a = next(3600), f = 1 + i % 5000;
    program += fmt::format("G01 X{} Y{} Z{} A{} F{}.\n", word(x), word(y), word(z), word(a), f);
    csv += fmt::format("{},line,{}000,{}000,{}000,{},{}000\n", i + 2, word(x), word(y), word(z), f, word(a));
    ends.push_back(fmt::format("{},{},{}", json(x), json(y), json(z)));
  }
  program += "M30\n";
  ASSERT_GT(csv.size(), 1u << 20);
  const std::string out = write(program, "csv", p);
  ASSERT_EQ(std::count(out.begin(), out.end(), '\n'), n + 3);
  std::istringstream got(out), want(csv);
  std::string g, w;
  for (int row = 1; std::getline(want, w); ++row) {
    ASSERT_TRUE(std::getline(got, g)) << row;
    ASSERT_EQ(g, w) << "row " << row;
  }
  EXPECT_FALSE(std::getline(got, g));

  std::istringstream jsonl(write(program, "jsonl", p));
  for (int i = 0; i <= n; ++i) {
    ASSERT_TRUE(std::getline(jsonl, g)) << i;
    const std::string head =
        fmt::format(R"({{"kind":"line","file":"w.nc","line":{},"program":-1,"start":[{}],"end":[{}],)", i + 1,
                    i == 0 ? "0,0,0" : ends[i - 1], ends[i]);
    ASSERT_EQ(g.substr(0, head.size()), head) << "record " << i;
    ASSERT_EQ(g.back(), '}') << "record " << i;
  }
  ASSERT_TRUE(std::getline(jsonl, g));
  EXPECT_EQ(g, R"({"kind":"program_end","file":"w.nc","line":30002,"program":-1,"code":30})");
  EXPECT_FALSE(std::getline(jsonl, g));
}

// The CSV's six decimals against std::to_chars(fixed, 6): ties to even (k/128), values near a tie,
// large and tiny values, negative zero, and a million random coordinates.
TEST(Writers, SixDecimalsAsToCharsWritesThem) {
  auto reference = [](double v) {
    char text[400];
    text[0] = ',';
    const auto r = std::to_chars(text + 1, text + sizeof text, v, std::chars_format::fixed, 6);
    return std::string(text, r.ptr);
  };
  auto ours = [](double v) {
    fmt::memory_buffer b;
    ncurve::report::fixed6(b, v);
    return std::string(b.data(), b.size());
  };
  std::vector<double> values = {0.0, -0.0, 1e-7, -1e-7, 5e-7, 0.0000005, 1e9, -1e9, 999999999.9999995, 1e15, 1e300,
                                -123.4567895, 0.1, 0.7, 2.675, 1.0000005, 4.0000015};
  for (int k = -5000; k <= 5000; ++k) values.push_back(k / 128.0), values.push_back(k / 1024.0 + 1e-12);
  for (int k = 1; k < 2000; ++k) values.push_back((k + 0.5) * 1e-6), values.push_back(std::nextafter((k + 0.5) * 1e-6, 1.0));
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coord(-2000, 2000);
  for (int i = 0; i < 1000000; ++i) values.push_back(coord(rng));
  for (double v : values) ASSERT_EQ(ours(v), reference(v)) << std::hexfloat << v;
}
