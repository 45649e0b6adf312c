// Symbolic derivatives against closed forms and finite differences; macro text that the
// interpreter reads back to the same values.
#include <gtest/gtest.h>
#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "geom/curve.hpp"
#include "geom/sym.hpp"
#include "nc/program.hpp"
#include "support/run_program.hpp"

using namespace ncurve;
using namespace ncurve::geom;

namespace {
constexpr double kRad = std::numbers::pi / 180;

Sym parse_sym(const std::string& text) { return from_code(nc::compile_expression(text).code, "test"); }

double at(const Sym& e, double t) {
  std::vector<double> vars(kVarCount, 0.0);
  vars[kTVar] = t;
  double out = 0;
  Tape({e})(vars.data(), &out);
  return out;
}
}  // namespace

TEST(Sym, SpiralDerivativesMatchTheClosedForm) {
  const CurveSpec* spec = find_curve("spiral");
  ASSERT_NE(spec, nullptr);
  Curve c(*spec, {{"r0", 1.0}, {"pitch", 4 * std::numbers::pi}});
  for (double t : {0.0, 17.0, 123.4, 359.0}) {
    double r = 1 + 4 * std::numbers::pi * t / 360, dr = 4 * std::numbers::pi / 360;  // per degree
    double x1 = dr * std::cos(t * kRad) - r * std::sin(t * kRad) * kRad;
    double y1 = dr * std::sin(t * kRad) + r * std::cos(t * kRad) * kRad;
    double x2 = -2 * dr * std::sin(t * kRad) * kRad - r * std::cos(t * kRad) * kRad * kRad;
    EXPECT_NEAR(c.d1(t)[0], x1, 1e-12);
    EXPECT_NEAR(c.d1(t)[1], y1, 1e-12);
    EXPECT_NEAR(c.d2(t)[0], x2, 1e-12);
    // curvature of r = a + b*phi: (r^2 + 2b^2) / (r^2 + b^2)^1.5 with b per radian
    double b = 2;
    EXPECT_NEAR(c.curvature(t), (r * r + 2 * b * b) / std::pow(r * r + b * b, 1.5), 1e-9);
  }
}

TEST(Sym, EveryFunctionAgainstFiniteDifferences) {
  const char* texts[] = {"SIN[#100*2]*COS[#100]", "TAN[#100/3]",        "ASIN[#100/100]",   "ACOS[#100/90]",
                         "ATAN[#100/50]",         "ATAN[#100]/[20-#100]", "SQRT[1+#100*#100]", "ABS[#100-40]",
                         "LN[2+#100]",            "EXP[#100/30]",       "POW[1+#100,1.5]",  "POW[2,#100/20]",
                         "#100*#100/[3+#100]",    "-[#100-2]*5"};
  for (const char* text : texts) {
    Sym e = parse_sym(text);
    Sym d = derivative(e, kTVar);
    for (double t : {3.0, 11.5, 27.0}) {
      double h = 1e-5;
      double fd = (at(e, t + h) - at(e, t - h)) / (2 * h);
      EXPECT_NEAR(at(d, t), fd, 1e-6 * (1 + std::fabs(fd))) << text << " at " << t;
    }
  }
}

TEST(Sym, MacroTextReadsBackToTheSameValues) {
  Sym e = parse_sym("[1+2*#100/360]*COS[#100]-7.5*SIN[6*#100]+ATAN[SIN[5*#100]]/[1.4-COS[5*#100]]");
  Sym d2 = derivative(derivative(e, kTVar), kTVar);
  for (const Sym& s : {e, d2}) {
    Sym back = parse_sym(to_macro(s));
    // constants are written with 8 digits (what every FANUC takes): about 1e-8 each
    for (double t : {0.5, 33.0, 71.0}) EXPECT_NEAR(at(back, t), at(s, t), 2e-7 * (1 + std::fabs(at(s, t))));
  }
  EXPECT_EQ(to_macro(parse_sym("#1-[#2-#3]")), "#1-#2+#3");  // sums are flattened
  EXPECT_EQ(to_macro(parse_sym("#1+[#2-#3]-[#4+#5]")), "#1+#2-#3-#4-#5");
  EXPECT_EQ(to_macro(parse_sym("-[#1*2]-#1*2")), "-4.*#1");
  EXPECT_EQ(to_macro(parse_sym("#1*#2-#1*#2")), "0.");
  EXPECT_EQ(to_macro(parse_sym("#1/[#2*#3]")), "#1/[#2*#3]");
  EXPECT_EQ(to_macro(parse_sym("[#1+0]*1")), "#1");
  EXPECT_EQ(to_macro(konst(0.5)), "0.5");
  EXPECT_EQ(to_macro(konst(12.566370614359172)), "12.566371");  // 8 digits
  EXPECT_EQ(to_macro(konst(std::numbers::pi / 180)), ".01745329");  // the leading zero gives way
  EXPECT_EQ(to_macro(konst(1e-9)), "0.000000001");  // 8 digits cannot hold it: written exactly
  EXPECT_EQ(to_macro(parse_sym("#1/360")), "#1/360.");
}

// The canonical form keeps every value and collects what the local rules cannot see.
TEST(Sym, SimplifyCollectsLikeTermsAndFactors) {
  EXPECT_EQ(to_macro(simplify(parse_sym("#1*#2-#2*#1"))), "0.");
  EXPECT_EQ(to_macro(simplify(parse_sym("#1*#2/#1"))), "#2");
  EXPECT_EQ(to_macro(simplify(parse_sym("3*[#1-#2]+3*[#2-#1]+#3"))), "#3");
  EXPECT_EQ(to_macro(simplify(parse_sym("#1*SIN[#3]+SIN[#3]*#2"))), "SIN[#3]*[#1+#2]");
  EXPECT_EQ(to_macro(simplify(parse_sym("#1/360*2"))), "#1/180.");
  // a sum whose coefficients are whole multiples of one keeps that one outside
  EXPECT_EQ(to_macro(simplify(parse_sym("#3*[0.75*#1+1.5*#2]"))), "0.75*#3*[#1+2.*#2]");
  EXPECT_EQ(to_macro(simplify(parse_sym("#3*[0.75*#1+1.3*#2]"))), "#3*[0.75*#1+1.3*#2]");
  // the rotor's exact second derivatives: same values from much shorter text
  const Curve rotor(*find_curve("rotor"), {});
  Sym raw = derivative(derivative(rotor.position()[0], kTVar), kTVar);
  Sym simple = simplify(raw);
  EXPECT_LT(3 * to_macro(simple).size(), 2 * to_macro(raw).size()) << to_macro(simple);
  for (double t : {0.5, 13.0, 37.25, 71.0})
    EXPECT_NEAR(at(simple, t), at(raw, t), 1e-12 * (1 + std::fabs(at(raw, t)))) << t;
}

// A second derivative nests deeper than FANUC's five brackets; split into temporaries, the
// interpreter accepts every block and computes the same value.
TEST(Sym, DepthLimitedTextRunsOnTheControl) {
  Sym e = derivative(derivative(parse_sym("SIN[COS[TAN[#100/7]*3]*2]*SQRT[1+#100]"), kTVar), kTVar);
  ASSERT_GT(bracket_depth(e), 5);
  int next = 150;
  std::vector<std::pair<int, Sym>> temps;
  Sym limited = limit_depth(e, 5, next, temps);
  EXPECT_LE(bracket_depth(limited), 5);
  std::string prog = "#100=12.5\n";
  for (const auto& [var, s] : temps) {
    EXPECT_LE(bracket_depth(s), 5);
    prog += fmt::format("#{}={}\n", var, to_macro(s));
  }
  prog += "#149=" + to_macro(limited) + "\nM30\n";
  auto r = test::run(prog);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_NEAR(r.var(149), at(e, 12.5), 1e-9 * (1 + std::fabs(at(e, 12.5))));
}

// The rotor's point and derivatives written with their common parts once: the interpreter computes
// the same values from text that is much shorter, and nothing shared appears twice.
TEST(Sym, SharedSubexpressionsRunOnTheControlAndShortenTheText) {
  const Curve rotor(*find_curve("rotor"), {});
  std::vector<Sym> outputs;
  for (const auto* e : {&rotor.position(), &rotor.first(), &rotor.second()})
    for (int k = 0; k < 2; ++k) outputs.push_back((*e)[k]);
  int next = 150;
  std::vector<std::pair<int, Sym>> temps;
  const std::vector<Sym> shared = share_subexpressions(outputs, next, temps);
  ASSERT_EQ(shared.size(), outputs.size());
  ASSERT_FALSE(temps.empty());
  std::size_t plain = 0, written = 0;
  std::string prog = "#100=37.25\n";
  auto assign = [&](int var, const Sym& e) {
    int depth_next = 190;
    std::vector<std::pair<int, Sym>> deep;
    Sym limited = limit_depth(e, 5, depth_next, deep);
    for (const auto& [v, d] : deep) prog += fmt::format("#{}={}\n", v, to_macro(d));
    prog += fmt::format("#{}={}\n", var, to_macro(limited));
    written += to_macro(e).size();
  };
  for (const auto& [var, e] : temps) assign(var, e);
  for (std::size_t i = 0; i < shared.size(); ++i) {
    assign(120 + static_cast<int>(i), shared[i]);
    plain += to_macro(outputs[i]).size();
  }
  EXPECT_LT(2 * written, plain) << written << " characters shared, " << plain << " plain";
  // no temporary's text occurs in another expression: it was replaced everywhere
  for (const auto& [var, e] : temps) {
    const std::string text = to_macro(e);
    for (const auto& [other, o] : temps)
      if (other != var) {
        EXPECT_EQ(to_macro(o).find(text), std::string::npos) << text;
      }
    for (const Sym& o : shared) EXPECT_EQ(to_macro(o).find(text), std::string::npos) << text;
  }
  prog += "M30\n";
  std::vector<double> vars(kVarCount, 0.0);
  vars[kTVar] = 37.25;
  for (const auto& p : rotor.params()) vars[static_cast<std::size_t>(p.var)] = p.value;
  std::string with_params;
  for (const auto& p : rotor.params()) with_params += "#" + std::to_string(p.var) + "=" + to_macro(konst(p.value)) + "\n";
  auto r = test::run(with_params + prog);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    double expect = 0;
    Tape({outputs[i]})(vars.data(), &expect);
    EXPECT_NEAR(r.var(120 + static_cast<int>(i)), expect, 2e-7 * (1 + std::fabs(expect))) << i;  // 8-digit constants
  }
}

TEST(Sym, WhatCannotBeDifferentiatedIsRefused) {
  EXPECT_THROW(parse_sym("ROUND[#100]"), nc::Alarm);
  EXPECT_THROW(parse_sym("#[#100]"), nc::Alarm);
  EXPECT_THROW(parse_sym("#100 MOD 3"), nc::Alarm);
  EXPECT_EQ(substitute_names("a*cos(t)+PI", {"a"}), "#101*COS[#100]+3.14159265358979");
  EXPECT_THROW(substitute_names("q*t", {"a"}), std::runtime_error);
}

TEST(Sym, TapeSharesSubexpressionsAndSineCosinePairs) {
  // x, y and their derivatives share the radius and one sincos of t; each output must equal its
  // own single-expression tape and the closed form
  Sym x = parse_sym("[2+#100/90]*COS[#100*3]"), y = parse_sym("[2+#100/90]*SIN[#100*3]");
  Sym bad = parse_sym("SQRT[#100-200]");  // NaN below t = 200, and only there
  Tape all({x, y, derivative(x, kTVar), bad});
  EXPECT_EQ(all.outputs(), 4u);
  std::vector<double> vars(kVarCount, 0.0);
  for (double t : {0.0, 30.0, 123.4, 250.0}) {
    vars[kTVar] = t;
    double out[4];
    all(vars.data(), out);
    double r = 2 + t / 90;
    EXPECT_NEAR(out[0], r * std::cos(3 * t * kRad), 1e-13) << t;
    EXPECT_NEAR(out[1], r * std::sin(3 * t * kRad), 1e-13) << t;
    EXPECT_EQ(out[0], at(x, t));
    EXPECT_EQ(out[1], at(y, t));
    EXPECT_NEAR(out[2], std::cos(3 * t * kRad) / 90 - r * 3 * kRad * std::sin(3 * t * kRad), 1e-13) << t;
    if (t < 200) EXPECT_TRUE(std::isnan(out[3])) << t;
    else EXPECT_NEAR(out[3], std::sqrt(t - 200), 1e-13);
  }
  vars[kTVar] = 60;  // 180 degrees: FANUC's exact zero survives the pairing
  double out[4];
  all(vars.data(), out);
  EXPECT_EQ(out[1], 0.0);
}

TEST(Sym, TapeConstantOperandsOnEitherSide) {
  // each form of a step with a constant operand, against the arithmetic; k/t is NaN at t = 0
  const char* texts[] = {"2.5+#100", "#100+2.5", "2.5-#100", "#100-2.5", "2.5*#100", "#100*2.5", "2.5/#100", "#100/2.5",
                         "-[2.5-#100]*4"};
  auto direct = [](int i, double t) {
    const double values[] = {2.5 + t, t + 2.5, 2.5 - t, t - 2.5, 2.5 * t, t * 2.5, t == 0 ? NAN : 2.5 / t, t / 2.5,
                             -(2.5 - t) * 4};
    return values[i];
  };
  std::vector<Sym> outputs;
  for (const char* text : texts) outputs.push_back(parse_sym(text));
  Tape all(outputs);
  std::vector<double> vars(kVarCount, 0.0);
  for (double t : {-3.0, 0.0, 0.75, 1e3}) {
    vars[kTVar] = t;
    double out[9];
    all(vars.data(), out);
    for (int i = 0; i < 9; ++i) {
      if (std::isnan(direct(i, t))) EXPECT_TRUE(std::isnan(out[i])) << texts[i] << " at " << t;
      else EXPECT_NEAR(out[i], direct(i, t), 1e-12 * (1 + std::fabs(direct(i, t)))) << texts[i] << " at " << t;
    }
  }
}

TEST(Sym, CurveJetIsPointAndDerivatives) {
  Curve c(*find_curve("rotor"), {});
  for (double t : {0.0, 11.0, 97.5, 300.0}) {
    Curve::Jet j = c.jet(t);
    EXPECT_EQ(j.p, c.point(t));
    EXPECT_EQ(j.d1, c.d1(t));
    EXPECT_EQ(j.d2, c.d2(t));
  }
}

TEST(Sym, TapeLanesAgreeWithOnePointAtEveryFunction) {
  // every step kind and function, with NaN where the one-point tape has it (domain, division by 0)
  const char* texts[] = {"SIN[#100]*COS[#100]", "SIN[#100*7]", "COS[#100-1000]", "TAN[#100/3]", "ASIN[#100/4000]",
                         "ACOS[#100/4000]", "ATAN[#100/50]", "ATAN[#100,30]", "SQRT[#100]", "ABS[#100-40]",
                         "LN[#100]", "EXP[#100/900]", "POW[2,#100/900]", "2.5/#100", "#100/[#100-90]",
                         "-[2.5-#100]*4+#100*#100"};
  std::vector<Sym> outputs;
  for (const char* text : texts) outputs.push_back(parse_sym(text));
  const std::size_t n = outputs.size();
  for (bool nat : {false, true}) {
    nc::EvalOptions options;
    options.atan_signed = nat;
    options.atan_comma = true;
    Tape one(outputs, options, {kTVar}), lanes(outputs, options, {kTVar});
    std::vector<double> t(Tape::kLanes);
    // whole multiples of 90 (exact sines), negative angles, far turns and an irregular spread
    for (std::size_t j = 0; j < t.size(); ++j) t[j] = j < 12 ? 90.0 * (static_cast<double>(j) - 5) : -2000 + 1234.567 * static_cast<double>(j);
    t[12] = 0;
    t[13] = 90;  // #100/[#100-90] divides by 0
    std::vector<double> out(n * Tape::kLanes);
    lanes.lanes(t.data(), out.data());
    for (std::size_t j = 0; j < t.size(); ++j) {
      std::vector<double> expect(n);
      one(&t[j], expect.data());
      for (std::size_t i = 0; i < n; ++i) {
        const double got = out[i * Tape::kLanes + j];
        if (std::isnan(expect[i])) {
          EXPECT_TRUE(std::isnan(got)) << texts[i] << " at " << t[j];
        } else if (std::fmod(t[j], 90) == 0 && i < 2) {
          EXPECT_EQ(got, expect[i]) << texts[i] << " at " << t[j];  // exact on the axes
        } else {
          EXPECT_NEAR(got, expect[i], 1e-13 * (1 + std::fabs(expect[i]))) << texts[i] << " at " << t[j];
        }
      }
    }
  }
}

TEST(Sym, LanesSineAndCosineAreAccurateInDegrees) {
  // against long double sine and cosine, over many turns and fractions of a degree
  Tape trig({parse_sym("SIN[#100]"), parse_sym("COS[#100]")}, {}, {kTVar});
  std::vector<double> t(Tape::kLanes), out(2 * Tape::kLanes);
  double worst = 0;
  for (int round = 0; round < 200; ++round) {
    for (std::size_t j = 0; j < t.size(); ++j) t[j] = -36000 + 11.3137 * (round * 32.0 + static_cast<double>(j));
    trig.lanes(t.data(), out.data());
    for (std::size_t j = 0; j < t.size(); ++j) {
      const long double rad = std::fmod(static_cast<long double>(t[j]), 360.0L) * (std::numbers::pi_v<long double> / 180);
      worst = std::max({worst, static_cast<double>(std::fabs(out[j] - std::sin(rad))),
                        static_cast<double>(std::fabs(out[Tape::kLanes + j] - std::cos(rad)))});
    }
  }
  EXPECT_LT(worst, 4e-16);
}

TEST(Sym, BindFoldsParametersAsTheControlWould) {
  Sym e = parse_sym("#101*COS[#100]+ATAN[#102]+ASIN[#102/2]");
  std::vector<double> vars(kVarCount, 0.0);
  vars[kTVar] = 30;
  vars[101] = 2;
  vars[102] = -1;
  for (bool nat : {false, true}) {
    nc::EvalOptions options;
    options.atan_signed = nat;
    Sym bound = bind(e, {{101, 2.0}, {102, -1.0}}, options);
    EXPECT_FALSE(depends_on(bound, 101));
    EXPECT_FALSE(depends_on(bound, 102));
    double free = 0, folded = 0;
    Tape(std::vector<Sym>{e}, options)(vars.data(), &free);
    Tape(std::vector<Sym>{bound}, options)(vars.data(), &folded);
    EXPECT_NEAR(folded, free, 1e-12);
    // ATAN[-1] is -45 either way; ASIN[-0.5] is 330 without NAT, -30 with it
    EXPECT_NEAR(folded, 2 * std::cos(30 * kRad) - 45 + (nat ? -30 : 330), 1e-12);
  }
  // the same constants folded by make() keep ATAN and ASIN for the control's setting
  EXPECT_EQ(make(SymOp::asin, konst(-0.5))->op, SymOp::asin);
  EXPECT_EQ(make(SymOp::sin, konst(30))->op, SymOp::konst);
}

TEST(Sym, CurveJetsAtManyParametersAreItsJets) {
  Curve c(*find_curve("rotor"), {});
  std::vector<double> t;
  for (int i = 0; i < 77; ++i) t.push_back(0.37 + 4.7 * i);  // two full batches and a part
  std::vector<Curve::Jet> many(t.size());
  c.jets(t, many);
  for (std::size_t i = 0; i < t.size(); ++i) {
    const Curve::Jet one = c.jet(t[i]);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(many[i].p[k], one.p[k], 1e-12) << t[i];
      EXPECT_NEAR(many[i].d1[k], one.d1[k], 1e-12) << t[i];
      EXPECT_NEAR(many[i].d2[k], one.d2[k], 1e-12) << t[i];
    }
  }
}

TEST(Sym, CurveReversedIsTheSameCurveTracedBackwards) {
  Curve c(*find_curve("rotor"), {});
  c.set_range(10, 300);
  const Curve back = c.reversed();
  EXPECT_EQ(back.t0(), -300);
  EXPECT_EQ(back.t1(), -10);
  std::vector<double> t, minus_t;
  for (int i = 0; i < 40; ++i) t.push_back(10 + 7.25 * i), minus_t.push_back(-t.back());
  std::vector<Curve::Jet> forwards(t.size()), backwards(t.size());
  c.jets(t, forwards);
  back.jets(minus_t, backwards);
  const Vec3 zero{0, 0, 0};
  for (std::size_t i = 0; i < t.size(); ++i) {
    const Curve::Jet j = c.jet(t[i]), b = back.jet(-t[i]);
    ASSERT_NE(j.d1, zero);
    const Vec3 minus_d1{-j.d1[0], -j.d1[1], -j.d1[2]};
    EXPECT_EQ(b.p, j.p) << t[i];
    EXPECT_EQ(b.d1, minus_d1) << t[i];
    EXPECT_EQ(b.d2, j.d2) << t[i];
    EXPECT_EQ(back.point(-t[i]), j.p);
    EXPECT_EQ(back.d1(-t[i]), minus_d1);
    EXPECT_EQ(back.d2(-t[i]), j.d2);
    EXPECT_EQ(backwards[i].p, forwards[i].p);
    EXPECT_EQ(backwards[i].d1, (Vec3{-forwards[i].d1[0], -forwards[i].d1[1], -forwards[i].d1[2]}));
    EXPECT_EQ(backwards[i].d2, forwards[i].d2);
  }
  EXPECT_EQ(back.reversed().jet(t[3]).d1, c.jet(t[3]).d1);
  // its expressions are the forward curve's: what would read them refuses it
  EXPECT_THROW(back.validate(), std::logic_error);
  EXPECT_THROW(back.offset(1, true, 0, 1), std::logic_error);
}

TEST(Sym, ValidateGivesTheSurveyOfTheJetsItChecked) {
  Curve c(*find_curve("rotor"), {});
  c.set_range(10.3, 297.9);
  const Survey checked = c.validate(), computed = c.survey();
  EXPECT_EQ(checked.values, computed.values);
  std::vector<double> t;
  for (std::size_t i = 0; i < Survey::kPoints; ++i) t.push_back(10.3 + (297.9 - 10.3) * static_cast<double>(i) / 256);
  std::vector<Curve::Jet> jets(t.size());
  c.jets(t, jets);
  for (std::size_t i = 0; i < t.size(); ++i) {
    for (std::size_t a = 0; a < 3; ++a) {
      ASSERT_EQ(checked.d1(a)[i], jets[i].d1[a]) << i;
      ASSERT_EQ(checked.d2(a)[i], jets[i].d2[a]) << i;
      EXPECT_NEAR(checked.d1(a)[i], c.d1(t[i])[a], 1e-9) << i;  // and one at a time
    }
  }
}

// A curve that stops inside its range (x ~ u^3, y ~ u^2 about the stop: a cusp) is named at the
// first stop in t, in whichever part of the check it lies, also where two parts share the sample;
// a stop at an end of the range is no cusp (the curve starts from rest or comes to rest), also
// one of higher order (x ~ u^4, y ~ u^3: the samples next to it are as slow).
TEST(Sym, ValidateNamesTheFirstStopInside) {
  auto stops = [](const std::vector<int>& at, int order = 2) {
    std::string x = "1", y = "1";
    for (int a : at) {
      const std::string u = fmt::format("[[t-{}]/1000]", a);
      for (int k = 0; k <= order; ++k) x += "*" + u;
      for (int k = 0; k < order; ++k) y += "*" + u;
    }
    CurveSpec spec{"stops", "", {}, x, y, "0", 0, 4096, ""};
    try {
      Curve(spec, {}).validate();
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(stops({2600}).find("stops at t = 2600 "), std::string::npos) << stops({2600});
  EXPECT_NE(stops({2560}).find("stops at t = 2560 "), std::string::npos) << stops({2560});
  EXPECT_NE(stops({3000, 1000}).find("stops at t = 1000 "), std::string::npos) << stops({3000, 1000});
  EXPECT_EQ(stops({0}), "");
  EXPECT_EQ(stops({4096}), "");
  EXPECT_EQ(stops({0}, 3), "");
  EXPECT_EQ(stops({4096}, 3), "");
  EXPECT_NE(stops({1}).find("stops at t = 1 "), std::string::npos) << stops({1});  // a sample inside
  EXPECT_NE(stops({4095}).find("stops at t = 4095 "), std::string::npos) << stops({4095});
  // at rest at both ends: x = cos, y = sin^2 of 180 t / 4096 (a parabola there and back: a stop
  // inside at t = 4096, where it turns, over 0..8192)
  CurveSpec both{"both", "", {}, "COS[t*180/4096]", "SIN[t*180/4096]*SIN[t*180/4096]", "0", 0, 4096, ""};
  EXPECT_NO_THROW(Curve(both, {}).validate());
  both.to = 8192;
  try {
    Curve(both, {}).validate();
    ADD_FAILURE() << "no error for the turn at t = 4096";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("stops at t = 4096 "), std::string::npos) << e.what();
  }
  EXPECT_EQ(stops({5000}), "");  // beyond the range
}

TEST(Sym, ValidateNamesTheFirstProblemAlongTheCurve) {
  // a pole at t = 1000 (X jumps from -inf to +inf) and Y undefined beyond t = 2500: the check runs
  // in parts on all cores, and still names the pole, the first problem in t
  CurveSpec spec{"two-problems", "", {}, "1/[t-1000]", "SQRT[2500-t]", "0", 0, 3000, ""};
  Curve c(spec, {});
  auto error = [&](double from, double to) -> std::string {
    c.set_range(from, to);
    try {
      c.validate();
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(error(0, 3000).find("jumps between t = 999."), std::string::npos) << error(0, 3000);
  // alone, the part beyond 2500 is named where it starts; without either, nothing
  EXPECT_NE(error(1500, 3000).find("not defined or singular at t = 250"), std::string::npos) << error(1500, 3000);
  EXPECT_EQ(error(1500, 2400), "");
}
