// ncurve serve's HTTP API, through real requests to a server on a free loopback port.
#include <gtest/gtest.h>
#include <httplib.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

#include "geom/curve.hpp"
#include "machine/profile.hpp"
#include "serve/server.hpp"

namespace ncurve::serve {
namespace {

using nlohmann::json;

class ServerTest : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    ServeConfig c;
    c.max_body = 16u << 20;  // 16 MB: a 10 MB program passes, 20 MB does not
    c.max_steps = 10'000'000;
    c.files = {std::string(NCURVE_SOURCE_DIR) + "/examples/spiral.nc"};
    server_ = new Server(c);
    port_ = server_->bind("127.0.0.1", 0);
    thread_ = new std::thread([] { server_->listen(); });
    for (int i = 0; i < 500 && !server_->running(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  static void TearDownTestSuite() {
    server_->stop();
    thread_->join();
    delete thread_;
    delete server_;
  }
  static httplib::Client client() {
    httplib::Client c("127.0.0.1", port_);
    c.set_read_timeout(120, 0);
    c.set_write_timeout(120, 0);
    return c;
  }
  static json post(const std::string& path, const std::string& body, int expected_status) {
    auto c = client();
    auto r = c.Post(path, body, "application/json");
    EXPECT_TRUE(r) << "no answer to POST " << path << ": " << httplib::to_string(r.error());
    if (!r) return {};
    EXPECT_EQ(r->status, expected_status) << r->body.substr(0, 500);
    EXPECT_TRUE(r->get_header_value("Content-Type").starts_with("application/json"))  // "; charset=utf-8" when big
        << r->get_header_value("Content-Type");
    return json::parse(r->body);
  }
  // the server still answers after whatever went before
  static void still_serving() {
    json j = post("/api/run", R"({"program": "G01 X1. F100.\nM30\n", "moves": false})", 200);
    EXPECT_EQ(j["summary"]["ok"], true);
  }
  static Server* server_;
  static std::thread* thread_;
  static int port_;
};
Server* ServerTest::server_ = nullptr;
std::thread* ServerTest::thread_ = nullptr;
int ServerTest::port_ = 0;

TEST_F(ServerTest, PortInUseIsRefused) {
  Server second(ServeConfig{});
  EXPECT_THROW(second.bind("127.0.0.1", port_), std::runtime_error);
  still_serving();
}

TEST_F(ServerTest, BadJsonIsAClearError) {
  json j = post("/api/run", "{\"program\": \"M30\"", 400);
  EXPECT_EQ(j["status"], 400);
  EXPECT_NE(j["error"].get<std::string>().find("not JSON"), std::string::npos) << j;
  j = post("/api/run", "[1, 2]", 400);
  EXPECT_NE(j["error"].get<std::string>().find("object"), std::string::npos) << j;
  j = post("/api/run", R"({"name": "a.nc"})", 400);  // no program
  EXPECT_NE(j["error"].get<std::string>().find("\"program\""), std::string::npos) << j;
  j = post("/api/run", R"({"program": "M30", "trace": "yes"})", 400);
  EXPECT_NE(j["error"].get<std::string>().find("\"trace\""), std::string::npos) << j;
  j = post("/api/run", R"({"program": "M30", "progam": 1})", 400);  // a misspelt key is not ignored
  EXPECT_NE(j["error"].get<std::string>().find("progam"), std::string::npos) << j;
  still_serving();
}

// A number beyond a double's range is refused as bad input, not an internal error
TEST_F(ServerTest, NumberTooLargeIsAClearError) {
  for (const char* path : {"/api/run", "/api/analyze", "/api/gen"}) {
    json j = post(path, R"({"program": 444e440, "curve": 1e999})", 400);
    EXPECT_NE(j["error"].get<std::string>().find("number too large"), std::string::npos) << j.dump();
  }
  still_serving();
}

// curl -d sends a form: refused (415) before its body is read, saying to send JSON
TEST_F(ServerTest, FormEncodedBodySaysToSendJson) {
  auto c = client();
  const std::string body = json{{"program", "G00 X1.\n(" + std::string(9000, 'A') + ")\nM30\n"}}.dump();
  auto form = c.Post("/api/run", body, "application/x-www-form-urlencoded");
  ASSERT_TRUE(form);
  EXPECT_EQ(form->status, 415);
  EXPECT_NE(form->body.find("Content-Type: application/json"), std::string::npos) << form->body;
  auto as_json = c.Post("/api/run", body, "application/json");
  ASSERT_TRUE(as_json);
  EXPECT_EQ(as_json->status, 200) << as_json->body.substr(0, 300);
  still_serving();
}

TEST_F(ServerTest, UnknownProfileIsAClearError) {
  json j = post("/api/run", R"({"program": "M30\n", "machine": "fanuc-mil"})", 400);
  EXPECT_NE(j["error"].get<std::string>().find("unknown profile \"fanuc-mil\""), std::string::npos) << j;
  j = post("/api/run", R"({"program": "M30\n", "machine": "/etc/passwd"})", 400);  // no file paths
  EXPECT_NE(j["error"].get<std::string>().find("unknown profile"), std::string::npos) << j;
  j = post("/api/run", R"({"program": "M30\n", "machine": "name = \"x\"\nkind = \"drill\"\n"})", 400);
  EXPECT_FALSE(j["error"].get<std::string>().empty());
  still_serving();
}

TEST_F(ServerTest, ProfileAsTomlText) {
  std::ifstream f(std::string(NCURVE_SOURCE_DIR) + "/profiles/fanuc-lathe.toml");
  std::stringstream toml;
  toml << f.rdbuf();
  // lathe, diameter mode: X20. is a radius of 10, written back as a diameter
  json req{{"program", "G00 X20. Z5.\nM30\n"}, {"machine", toml.str()}};
  json j = post("/api/run", req.dump(), 200);
  EXPECT_EQ(j["summary"]["machine"], "FANUC 0i-TF 2-axis lathe");
  EXPECT_EQ(j["moves"]["x"][0], 20.0);
  EXPECT_EQ(j["moves"]["z"][0], 5.0);
}

TEST_F(ServerTest, AlarmIsANormalAnswer) {
  // line 3 divides by zero; the '/' is its 10th character
  json j = post("/api/run", R"({"program": "G01 X1. F100.\n#1=5\n#2=[#1+1]/0\nG01 X2.\nM30\n", "name": "div.nc"})", 200);
  const json& alarm = j["summary"]["alarm"];
  EXPECT_EQ(j["summary"]["ok"], false);
  EXPECT_EQ(alarm["code"], "PS0112");
  EXPECT_EQ(alarm["file"], "div.nc");
  EXPECT_EQ(alarm["line"], 3);
  EXPECT_EQ(alarm["column"], 10);
  EXPECT_EQ(j["diagnostics"].back()["code"], "PS0112");
  EXPECT_EQ(j["moves"]["count"], 1);  // the move before it, not the one after
  EXPECT_EQ(j["moves"]["x"][0], 1.0);
}

TEST_F(ServerTest, RunawayIsAnErrorStatusWithTheRun) {
  json j = post("/api/run", R"({"program": "N1 G01 X1. F100.\nGOTO 1\n", "max_steps": 1000})", 422);
  EXPECT_EQ(j["status"], 422);
  EXPECT_NE(j["error"].get<std::string>().find("stopped after 1000 steps"), std::string::npos) << j["error"];
  EXPECT_NE(j["error"].get<std::string>().find("in a request: \"max_steps\""), std::string::npos) << j["error"];
  EXPECT_EQ(j["summary"]["alarm"]["code"], "NC9000");
  j = post("/api/run", R"({"program": "M30\n", "max_steps": 1e12})", 400);  // over the server's
  EXPECT_NE(j["error"].get<std::string>().find("max_steps"), std::string::npos);
  still_serving();
}

TEST_F(ServerTest, TenMegabyteProgram) {
  std::string program = "G90 G01 F1000.\n";
  std::size_t lines = 0;
  while (program.size() < 10'000'000) {
    program += 'X';  // 10 to 16 bytes a line
    program += std::to_string(lines % 1000);
    program += ".5 Y1.25\n";
    ++lines;
  }
  program += "M30\n";
  json j = post("/api/run", json{{"program", program}, {"name", "big.nc"}}.dump(), 200);
  EXPECT_EQ(j["summary"]["ok"], true);
  EXPECT_EQ(j["summary"]["moves"]["line"], lines);
  EXPECT_EQ(j["moves"]["count"], lines + 1);  // and M30
  EXPECT_EQ(j["moves"]["x"][lines - 1], static_cast<double>((lines - 1) % 1000) + 0.5);
}

TEST_F(ServerTest, TooLargeBodyIsRefused) {
  const std::string program(20u << 20, ' ');  // 20 MB over the 16 MB limit
  auto c = client();
  auto r = c.Post("/api/run", json{{"program", program}}.dump(), "application/json");
  if (r) {  // (httplib may also close the connection before reading it all)
    EXPECT_EQ(r->status, 413);
    EXPECT_NE(json::parse(r->body)["error"].get<std::string>().find("too large"), std::string::npos) << r->body;
  }
  still_serving();
}

TEST_F(ServerTest, EightConcurrentClients) {
  // each client's own #100 decides its path: the answers do not mix
  std::vector<std::thread> threads;
  std::vector<json> answers(8);
  const std::string program =
      "#1=0\nWHILE [#1 LT 20000] DO1\nG01 X#100 Y[#1*0.001] F1000.\n#1=#1+1\nEND1\nM30\n";
  for (int i = 0; i < 8; ++i)
    threads.emplace_back([&, i] {
      auto c = client();
      json req{{"program", program}, {"set", {{"#100", i + 1}}}, {"trace", i % 2 == 0}};
      auto r = c.Post("/api/run", req.dump(), "application/json");
      if (r && r->status == 200) answers[i] = json::parse(r->body);
    });
  for (auto& t : threads) t.join();
  for (int i = 0; i < 8; ++i) {
    ASSERT_FALSE(answers[i].is_null()) << "client " << i;
    EXPECT_EQ(answers[i]["summary"]["moves"]["line"], 20000);
    // the tool starts at reference position 1, machine zero: X250 of the shipped mill's G54 (X-250)
    EXPECT_EQ(answers[i]["summary"]["extent"]["X"][1], 250.0);
    EXPECT_EQ(answers[i]["moves"]["x"][19999], i + 1.0);
    EXPECT_EQ(answers[i].contains("trace"), i % 2 == 0);
  }
}

TEST_F(ServerTest, FilesProfilesAndPage) {
  auto c = client();
  auto r = c.Get("/api/files");
  ASSERT_TRUE(r);
  json files = json::parse(r->body)["files"];
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0]["name"], "spiral.nc");
  r = c.Get("/api/files/spiral.nc");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_NE(r->body.find("O1000"), std::string::npos);
  r = c.Get("/api/files/passwd");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 404);
  r = c.Get("/api/profiles");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  json profiles = json::parse(r->body);
  EXPECT_TRUE(profiles["profiles"].is_array());
  // no --machine: a request naming none runs on `ncurve run`'s default, and the answer says so
  EXPECT_TRUE(profiles["default"].is_null());
  EXPECT_EQ(profiles["server"]["factory"], true);
  EXPECT_TRUE(profiles["server"]["path"].is_null());
  EXPECT_EQ(profiles["server"]["title"], machine::default_mill().name);
  EXPECT_EQ(profiles["server"]["lathe"], false);
  EXPECT_EQ(post("/api/run", R"({"program": "M30\n", "moves": false})", 200)["summary"]["machine"],
            machine::default_mill().name);
  r = c.Get("/");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_NE(r->body.find("<html"), std::string::npos);
  r = c.Get("/assets/workbench.js");  // the page's files, compiled in
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_NE(r->body.find("ncurveWorkbench"), std::string::npos);
  r = c.Get("/assets/wb-colour.js");  // the colour modes, a file of their own
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_NE(r->body.find("NcurveColour"), std::string::npos);
  r = c.Get("/assets/wb-answer.js");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  r = c.Get("/assets/backplot-axes.js");  // the backplot's axes, a file of their own
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_NE(r->body.find("NcurveBackplotAxes"), std::string::npos);
  r = c.Get("/assets/run.html");  // not one of the workbench's
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 404);
  r = c.Get("/api/nothing");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 404);
  EXPECT_TRUE(json::parse(r->body).contains("error"));
}

// An endpoint asked with a method it does not take: 405, Allow, a JSON error (not 404).
TEST_F(ServerTest, OtherMethodIs405) {
  auto c = client();
  for (const char* path : {"/api/run", "/api/analyze", "/api/gen"}) {
    auto r = c.Get(path);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 405) << path;
    EXPECT_EQ(r->get_header_value("Allow"), "POST") << path;
    EXPECT_TRUE(r->get_header_value("Content-Type").starts_with("application/json"));
    const json j = json::parse(r->body);
    EXPECT_EQ(j["status"], 405);
    EXPECT_NE(j["error"].get<std::string>().find("POST only"), std::string::npos) << j;
    r = c.Delete(path);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 405) << path;
  }
  for (const char* path : {"/api/profiles", "/api/curves", "/api/files", "/api/files/spiral.nc", "/"}) {
    auto r = c.Post(path, "{}", "application/json");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 405) << path;
    EXPECT_EQ(r->get_header_value("Allow"), "GET, HEAD") << path;
    EXPECT_EQ(json::parse(r->body)["status"], 405);
  }
  auto r = c.Get("/api/nothing");  // no such endpoint at all: still 404
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 404);
  still_serving();
}

// /api/run's summary holds every key of `ncurve run --json`, printed and printed_left_out too.
TEST_F(ServerTest, RunSummaryKeys) {
  const json j = post("/api/run", R"({"program": "G01 X1. F100.\nDPRNT[HELLO]\nM30\n", "moves": false})", 200);
  std::vector<std::string> keys;
  for (const auto& item : j["summary"].items()) keys.push_back(item.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"alarm", "blocks_executed", "extent", "feed_length_mm", "machine",
                                            "motions", "moves", "ok", "printed", "printed_left_out",
                                            "rapid_length_mm", "source", "source_blocks", "source_bytes",
                                            "source_words", "text_problems", "text_problems_left_out",
                                            "time_at_programmed_feed_s", "unchecked_lines", "warnings"}));
}

TEST_F(ServerTest, AnalyzeAndGen) {
  // from X250 (reference position 1 at machine zero, G54 X-250) to X100: 150 mm at F600, 15 s at the
  // programmed feed
  json j = post("/api/analyze", R"({"program": "G01 X100. F600.\nM30\n"})", 200);
  EXPECT_EQ(j["ok"], true);
  EXPECT_DOUBLE_EQ(j["programmed_time_s"].get<double>(), 15.0);
  EXPECT_GE(j["cycle_time_s"].get<double>(), 15.0);
  j = post("/api/gen", R"({"curve": "ellipse", "params": {"a": 20, "b": 10}, "tol": 0.01})", 200);
  EXPECT_EQ(j["within_tolerance"], true);
  EXPECT_LE(j["max_deviation"].get<double>(), 0.01);
  EXPECT_NE(j["program"].get<std::string>().find("M30"), std::string::npos);
  EXPECT_EQ(j["warnings"], json::array());
  // gen's warnings, in the command line's words (without its "ncurve gen: warning: ")
  j = post("/api/gen", R"({"curve": "hyperbola", "tol": 0.01})", 200);
  ASSERT_EQ(j["warnings"].size(), 1u) << j["warnings"];
  EXPECT_TRUE(j["warnings"][0].get<std::string>().starts_with("hyperbola is a lathe curve; without a lathe profile"));
  j = post("/api/gen", R"({"curve": "hyperbola", "form": "arcs"})", 422);  // arcs of a curve in X and Z on a mill
  EXPECT_NE(j["error"].get<std::string>().find("arcs on a mill are made in the XY plane"), std::string::npos) << j;
  ASSERT_EQ(j["warnings"].size(), 1u) << j;
  j = post("/api/gen", R"({"curve": "elipse"})", 400);
  EXPECT_NE(j["error"].get<std::string>().find("ellipse"), std::string::npos) << j;
}

// GET /api/curves: the table `ncurve gen --list` prints, each curve with its parameters' defaults.
TEST_F(ServerTest, CurvesAreGensTable) {
  auto c = client();
  auto r = c.Get("/api/curves");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200);
  const json j = json::parse(r->body);
  const auto& table = geom::catalogue();
  ASSERT_EQ(j["curves"].size(), table.size());
  for (std::size_t i = 0; i < table.size(); ++i) {
    const json& got = j["curves"][i];
    const geom::CurveSpec& want = table[i];
    EXPECT_EQ(got["name"], want.name);
    EXPECT_EQ(got["doc"], want.doc);
    EXPECT_EQ(got["x"], want.x);
    EXPECT_EQ(got["y"], want.y);
    EXPECT_EQ(got["z"], want.z);
    EXPECT_EQ(got["from"].get<double>(), want.from);
    EXPECT_EQ(got["to"].get<double>(), want.to);
    EXPECT_EQ(got["t_doc"], want.t_doc);
    EXPECT_EQ(got["lathe"], want.lathe);
    ASSERT_EQ(got["params"].size(), want.params.size()) << want.name;
    for (std::size_t k = 0; k < want.params.size(); ++k) {
      EXPECT_EQ(got["params"][k]["name"], want.params[k].name);
      EXPECT_EQ(got["params"][k]["value"].get<double>(), want.params[k].value);
      EXPECT_EQ(got["params"][k]["doc"], want.params[k].doc);
    }
  }
  EXPECT_EQ(j["curves"][3]["name"], "ellipse");  // as gen --list shows it: a 40, b 20
  EXPECT_EQ(j["curves"][3]["params"][0]["value"], 40.0);
}

// A profile's TOML text in /api/gen's "machine", as in /api/run: a lathe curve on the lathe; a bad
// profile is a 400 saying what is wrong.
TEST_F(ServerTest, GenTakesAProfilesText) {
  std::ifstream f(std::string(NCURVE_SOURCE_DIR) + "/profiles/fanuc-lathe.toml");
  std::stringstream toml;
  toml << f.rdbuf();
  json j = post("/api/gen", json{{"curve", "hyperbola"}, {"tol", 0.01}, {"machine", toml.str()}}.dump(), 200);
  EXPECT_EQ(j["within_tolerance"], true);
  // the run names the profile's kind for the page: a lathe, X in diameters
  j = post("/api/run", json{{"program", "G00 X20. Z5.\nM30\n"}, {"machine", toml.str()}, {"moves", false}}.dump(), 200);
  EXPECT_EQ(j["profile"]["lathe"], true);
  EXPECT_EQ(j["profile"]["diameter"], true);
  EXPECT_EQ(j["profile"]["title"], "FANUC 0i-TF 2-axis lathe");
  j = post("/api/gen", json{{"curve", "ellipse"}, {"machine", "name = \"x\"\nkind = \"drill\"\n"}}.dump(), 400);
  EXPECT_FALSE(j["error"].get<std::string>().empty());
}

// The profile's rotary axes named for the page (their ends are degrees), the ends in the moves' columns.
TEST_F(ServerTest, RunNamesTheRotaryAxes) {
  std::ifstream f(std::string(NCURVE_SOURCE_DIR) + "/profiles/fanuc-4axis-helicoid.toml");
  std::stringstream toml;
  toml << f.rdbuf();
  json j = post("/api/run", json{{"program", "G00 A90.\nM30\n"}, {"machine", toml.str()}}.dump(), 200);
  EXPECT_EQ(j["profile"]["rotary"], "A");
  EXPECT_EQ(j["moves"]["a"][0], 90.0);
  j = post("/api/run", json{{"program", "G00 X1.\nM30\n"}, {"moves", false}}.dump(), 200);
  EXPECT_EQ(j["profile"]["rotary"], "");  // the factory mill: X Y Z
}

// "format": "binary": the same answer with each array as little-endian bytes after the JSON.
TEST_F(ServerTest, BinaryAnswerHoldsTheArrays) {
  auto c = client();
  const std::string program = "#1=2.5\nG01 X#1 Y1. F100.\nG02 X5. Y1. R1.25\n#1=#0\nM30\n";
  auto r = c.Post("/api/run", json{{"program", program}, {"trace", true}, {"format", "binary"}}.dump(),
                  "application/json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200);
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/octet-stream");
  const std::string& body = r->body;
  ASSERT_GE(body.size(), 8u);
  EXPECT_EQ(body.substr(0, 4), "NCB1");
  std::uint32_t length = 0;
  std::memcpy(&length, body.data() + 4, 4);
  ASSERT_LE(8u + length, body.size());
  EXPECT_EQ(length % 8, 0u);
  const json j = json::parse(body.substr(8 + length));
  const std::size_t base = 8;
  auto f64 = [&](const json& d) {
    EXPECT_EQ(d["type"], "f64");
    std::vector<double> out(d["count"].get<std::size_t>());
    const std::size_t at = base + d["offset"].get<std::size_t>();
    EXPECT_EQ(at % 8, 0u);
    EXPECT_LE(at + 8 * out.size(), body.size());
    if (!out.empty()) std::memcpy(out.data(), body.data() + at, 8 * out.size());
    return out;
  };
  EXPECT_EQ(j["summary"]["ok"], true);
  const json& m = j["moves"];
  EXPECT_EQ(m["count"], 3);  // the line, the arc, M30
  EXPECT_EQ(f64(m["x"]), (std::vector<double>{2.5, 5.0, 5.0}));
  EXPECT_EQ(f64(m["arcs"]["cx"]), std::vector<double>{3.75});  // R1.25 over the 2.5 mm chord: a half circle
  const json& kind = m["kind"];
  EXPECT_EQ(kind["type"], "u8");
  EXPECT_EQ(body[base + kind["offset"].get<std::size_t>() + 1], 2);  // "kinds"[2] is "arc"
  const std::vector<double> written = f64(j["trace"]["writes"]["new"]);
  ASSERT_EQ(written.size(), 2u);
  EXPECT_EQ(written[0], 2.5);
  EXPECT_TRUE(std::isnan(written[1]));  // vacant: NaN where the JSON says null
  json bad = post("/api/run", R"({"program": "M30\n", "format": "xml"})", 400);
  EXPECT_NE(bad["error"].get<std::string>().find("format"), std::string::npos);
}

}  // namespace
}  // namespace ncurve::serve
