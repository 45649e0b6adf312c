// ncurve serve against other sites' pages, runs without end, slow clients, a FIFO and programs
// costly in memory: each test starts a server of its own on a free loopback port, and every
// request and loop in it is bounded in count and time.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <httplib.h>

#include <nlohmann/json.hpp>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <thread>

#include "serve/api.hpp"
#include "serve/server.hpp"

namespace ncurve::serve {
namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// A server on a free loopback port, listening on a thread of the test; stopped at the end.
struct Running {
  explicit Running(ServeConfig config) : server(std::move(config)) {
    port = server.bind("127.0.0.1", 0);
    listening = std::async(std::launch::async, [this] { return server.listen(); });
    for (int i = 0; i < 500 && !server.running(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ~Running() {
    server.stop();
    listening.wait();
  }
  httplib::Client client(double timeout = 10) const {
    httplib::Client c("127.0.0.1", port);
    const auto t = std::chrono::milliseconds(static_cast<long>(timeout * 1000));
    c.set_read_timeout(t);
    c.set_write_timeout(t);
    c.set_connection_timeout(std::chrono::seconds(2));
    return c;
  }
  std::string host() const { return "127.0.0.1:" + std::to_string(port); }

  Server server;
  int port = 0;
  std::future<bool> listening;
};

ServeConfig files_config() {
  ServeConfig c;
  c.files = {std::string(NCURVE_SOURCE_DIR) + "/examples/spiral.nc"};
  return c;
}

const char* kShortRun = R"({"program": "G01 X1. F100.\nM30\n", "moves": false})";
const char* kEndless = R"({"program": "N1 #1=#1+1\nGOTO 1\n", "moves": false})";

// A TCP connection to the server, written and read by the test itself.
struct RawSocket {
  explicit RawSocket(int port) {
    fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(static_cast<std::uint16_t>(port));
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    connected = ::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0;
  }
  ~RawSocket() { ::close(fd); }
  bool send(const std::string& s) const { return ::send(fd, s.data(), s.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(s.size()); }
  // true once the server has closed its side (read to the end within `ms`)
  bool closed_by_server(int ms) const {
    const auto until = Clock::now() + std::chrono::milliseconds(ms);
    char buffer[4096];
    while (Clock::now() < until) {
      pollfd p{fd, POLLIN, 0};
      if (::poll(&p, 1, 20) <= 0) continue;
      const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
      if (n <= 0) return true;
    }
    return false;
  }
  int fd;
  bool connected = false;
};

// --- another site's page -------------------------------------------------------------------

// DNS rebinding: the page of attacker.example, its name now pointing at 127.0.0.1, reads the files
TEST(ServeGuard, ForeignHostIsRefused) {
  Running s(files_config());
  auto c = s.client();
  for (const char* path : {"/api/files", "/api/files/spiral.nc", "/", "/api/profiles"}) {
    auto r = c.Get(path, {{"Host", "attacker.example:" + std::to_string(s.port)}});
    ASSERT_TRUE(r) << path;
    EXPECT_EQ(r->status, 403) << path;
    EXPECT_EQ(r->body.find("spiral"), std::string::npos) << r->body;
    EXPECT_NE(json::parse(r->body)["error"].get<std::string>().find("attacker.example"), std::string::npos);
  }
  auto r = c.Get("/api/files", {{"Host", "127.0.0.1:1"}});  // our address, another port
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 403);
  // the loopback names with the port are ours
  for (std::string host : {s.host(), "localhost:" + std::to_string(s.port), "LocalHost:" + std::to_string(s.port),
                           "[::1]:" + std::to_string(s.port)}) {
    r = c.Get("/api/files", {{"Host", host}});
    ASSERT_TRUE(r) << host;
    EXPECT_EQ(r->status, 200) << host;
    EXPECT_NE(r->body.find("spiral.nc"), std::string::npos) << host;
  }
}

// CSRF: a page of another site posts to /api/run
TEST(ServeGuard, ForeignOriginIsRefused) {
  Running s(files_config());
  auto c = s.client();
  for (const char* origin : {"http://attacker.example", "null", "https://127.0.0.1", "http://127.0.0.1:1"}) {
    auto r = c.Post("/api/run", {{"Origin", origin}}, kShortRun, "application/json");
    ASSERT_TRUE(r) << origin;
    EXPECT_EQ(r->status, 403) << origin;
    r = c.Get("/api/files", {{"Origin", origin}});
    ASSERT_TRUE(r) << origin;
    EXPECT_EQ(r->status, 403) << origin;
  }
  // the page's own requests, and a script's without Origin
  auto r = c.Post("/api/run", {{"Origin", "http://" + s.host()}}, kShortRun, "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200) << r->body;
  r = c.Post("/api/run", {{"Origin", "http://localhost:" + std::to_string(s.port)}}, kShortRun, "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200) << r->body;
  r = c.Post("/api/run", kShortRun, "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200) << r->body;
}

// A form or a text/plain fetch is sent by a browser without a preflight: only JSON is taken
TEST(ServeGuard, BodyMustBeJson) {
  Running s(files_config());
  auto c = s.client();
  for (const char* path : {"/api/run", "/api/analyze", "/api/gen"})
    for (const char* type : {"text/plain", "application/x-www-form-urlencoded", "multipart/form-data; boundary=x"}) {
      auto r = c.Post(path, kShortRun, type);
      ASSERT_TRUE(r) << path << " " << type;
      EXPECT_EQ(r->status, 415) << path << " " << type;
      EXPECT_NE(json::parse(r->body)["error"].get<std::string>().find("application/json"), std::string::npos);
    }
  auto r = c.Post("/api/run", kShortRun, "application/json; charset=utf-8");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200) << r->body;
  // no Content-Type at all, and the connection refused is not read on as the next request
  RawSocket raw(s.port);
  ASSERT_TRUE(raw.connected);
  const std::string body = kShortRun;
  ASSERT_TRUE(raw.send("POST /api/run HTTP/1.1\r\nHost: " + s.host() + "\r\nContent-Length: " +
                       std::to_string(body.size()) + "\r\n\r\n" + body));
  std::string answer;
  char buffer[4096];
  for (int i = 0; i < 100 && answer.find("\r\n\r\n") == std::string::npos; ++i) {
    pollfd p{raw.fd, POLLIN, 0};
    if (::poll(&p, 1, 20) > 0) {
      const ssize_t n = ::recv(raw.fd, buffer, sizeof buffer, 0);
      if (n <= 0) break;
      answer.append(buffer, static_cast<std::size_t>(n));
    }
  }
  EXPECT_TRUE(answer.starts_with("HTTP/1.1 415")) << answer;
  EXPECT_TRUE(raw.closed_by_server(2000));
}

TEST(ServeGuard, AllowHostNamesAnotherHost) {
  ServeConfig config = files_config();
  config.allow_hosts = {"workbench.lan"};
  Running s(config);
  auto c = s.client();
  const std::string name = "workbench.lan:" + std::to_string(s.port);
  auto r = c.Post("/api/run", {{"Host", name}, {"Origin", "http://" + name}}, kShortRun, "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200) << r->body;
  r = c.Get("/api/files", {{"Host", "other.lan:" + std::to_string(s.port)}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 403);
  EXPECT_NE(std::find(s.server.hosts().begin(), s.server.hosts().end(), name), s.server.hosts().end());
}

// --- runs without end ----------------------------------------------------------------------

TEST(ServeGuard, CancelledRunStops) {
  std::atomic<bool> cancel{true};
  ServeConfig config;
  const auto t = Clock::now();
  Answer a = api_run(config, kEndless, &cancel);
  EXPECT_LT(seconds_since(t), 5);
  EXPECT_EQ(a.status, 422);
  json j = json::parse(a.body);
  EXPECT_EQ(j["summary"]["alarm"]["code"], "NC9000");
  EXPECT_NE(j["error"].get<std::string>().find("cancelled"), std::string::npos) << j["error"];
}

// One G83 block of 10^8 pecks: the run's time bound stops it, and the server answers
TEST(ServeGuard, HugeCycleIsStoppedInTime) {
  Running s(ServeConfig{});
  auto c = s.client(5);
  const json request{{"program", "G90 G00 X0 Y0 Z10.\nG83 X0 Y0 Z-99999. R1. Q0.001 F100.\nM30\n"},
                     {"max_seconds", 2},
                     {"moves", false}};
  const auto t = Clock::now();
  auto r = c.Post("/api/run", request.dump(), "application/json");
  ASSERT_TRUE(r) << httplib::to_string(r.error());
  EXPECT_EQ(r->status, 422) << r->body.substr(0, 300);
  EXPECT_LT(seconds_since(t), 5);
  EXPECT_EQ(json::parse(r->body)["summary"]["alarm"]["code"], "NC9000");
}

// Clients that give up on endless runs: their runs stop, and the server answers the next one
TEST(ServeGuard, ClientGoneStopsItsRun) {
  ServeConfig config;
  config.max_seconds = 60;
  Running s(config);
  std::vector<std::thread> clients;
  for (int i = 0; i < 12; ++i)  // more than the runs at once
    clients.emplace_back([&] {
      auto c = s.client(0.3);
      auto r = c.Post("/api/run", kEndless, "application/json");
      EXPECT_FALSE(r);  // gave up
    });
  for (auto& t : clients) t.join();
  const auto t = Clock::now();
  auto r = s.client(10).Post("/api/run", kShortRun, "application/json");
  ASSERT_TRUE(r) << httplib::to_string(r.error());
  EXPECT_EQ(r->status, 200) << r->body;
  EXPECT_LT(seconds_since(t), 3);
}

// stop() (SIGTERM, Ctrl-C) ends the server with runs under way
TEST(ServeGuard, StopEndsRunsUnderWay) {
  ServeConfig config;
  config.max_seconds = 60;
  auto s = std::make_unique<Running>(config);
  std::vector<std::thread> clients;
  for (int i = 0; i < 3; ++i)
    clients.emplace_back([&] { s->client(20).Post("/api/run", kEndless, "application/json"); });
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const auto t = Clock::now();
  s->server.stop();
  EXPECT_EQ(s->listening.wait_for(std::chrono::seconds(3)), std::future_status::ready);
  EXPECT_LT(seconds_since(t), 3);
  for (auto& c : clients) c.join();
  s.reset();
}

// SIGTERM ends `ncurve serve` with a run under way
TEST(ServeGuard, SigtermEndsTheCommand) {
  int out[2];
  ASSERT_EQ(::pipe(out), 0);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    ::dup2(out[1], 1);
    ::execl(NCURVE_BINARY, NCURVE_BINARY, "serve", "--port", "0", "--max-seconds", "60", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(out[1]);
  std::string line;
  char ch;
  for (int i = 0; i < 300 && line.find('\n') == std::string::npos; ++i) {
    pollfd p{out[0], POLLIN, 0};
    if (::poll(&p, 1, 20) > 0 && ::read(out[0], &ch, 1) == 1) line += ch;
  }
  ::close(out[0]);
  const auto colon = line.rfind(':');
  ASSERT_NE(colon, std::string::npos) << line;
  const int port = std::atoi(line.c_str() + colon + 1);
  std::thread client([port] {
    httplib::Client c("127.0.0.1", port);
    c.set_read_timeout(std::chrono::seconds(10));
    c.Post("/api/run", kEndless, "application/json");
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ::kill(pid, SIGTERM);
  int status = 0;
  const auto t = Clock::now();
  while (::waitpid(pid, &status, WNOHANG) == 0 && seconds_since(t) < 4)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const bool ended = seconds_since(t) < 4;
  if (!ended) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &status, 0);
  }
  client.join();
  EXPECT_TRUE(ended);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
}

// --- slow clients --------------------------------------------------------------------------

// 64 clients sending a byte each 100 ms: others are answered at once, and the slow ones are cut
// at the request deadline
TEST(ServeGuard, SlowClientsHoldNothing) {
  ServeConfig config;
  config.request_seconds = 1.5;
  Running s(config);
  std::vector<std::unique_ptr<RawSocket>> slow;
  for (int i = 0; i < 64; ++i) {
    slow.push_back(std::make_unique<RawSocket>(s.port));
    ASSERT_TRUE(slow.back()->connected);
    slow.back()->send("GET /api/profiles HTTP/1.1\r\nHost: " + s.host() + "\r\nX-Slow: ");
  }
  std::atomic<bool> done{false};
  std::thread trickle([&] {
    for (int tick = 0; tick < 40 && !done; ++tick) {  // 4 s at most
      for (auto& r : slow) r->send("a");
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  auto t = Clock::now();
  auto r = s.client(5).Get("/api/profiles");
  EXPECT_TRUE(r && r->status == 200);
  EXPECT_LT(seconds_since(t), 2.0);
  int cut = 0;
  t = Clock::now();
  for (auto& sock : slow) cut += sock->closed_by_server(std::max(1, 3000 - static_cast<int>(seconds_since(t) * 1000)));
  done = true;
  trickle.join();
  EXPECT_EQ(cut, 64);
}

// --- a FIFO among the files ----------------------------------------------------------------

struct Fifo {
  Fifo() : path(fs::temp_directory_path() / ("ncurve-guard-" + std::to_string(::getpid()) + ".nc")) {
    fs::remove(path);
    created = ::mkfifo(path.c_str(), 0600) == 0;
  }
  ~Fifo() {
    // a reader blocked on it (the fault tested) is let go before the server stops
    const int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK);
    if (fd >= 0) ::close(fd);
    fs::remove(path);
  }
  fs::path path;
  bool created = false;
};

TEST(ServeGuard, FifoIsNotReadAsAFile) {
  Fifo fifo;
  ASSERT_TRUE(fifo.created);
  {
    ServeConfig config;
    config.files = {fifo.path.string()};  // one put in a file's place once the server runs
    Running s(config);
    const auto t = Clock::now();
    auto r = s.client(3).Get("/api/files/" + fifo.path.filename().string());
    ASSERT_TRUE(r) << httplib::to_string(r.error());
    EXPECT_EQ(r->status, 500);
    EXPECT_NE(r->body.find("not a regular file"), std::string::npos) << r->body;
    EXPECT_LT(seconds_since(t), 2);
    r = s.client(3).Get("/api/files");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200);
  }
  // `ncurve serve FIFO` is refused at the start
  const std::string command = fmt::format("timeout 10 {} serve --port 0 {} > /dev/null 2> {}.err", NCURVE_BINARY,
                                          fifo.path.string(), fifo.path.string());
  const int status = std::system(command.c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2) << status;
  std::ifstream err(fifo.path.string() + ".err");
  std::string message((std::istreambuf_iterator<char>(err)), {});
  EXPECT_NE(message.find("not a regular file"), std::string::npos) << message;
  fs::remove(fifo.path.string() + ".err");
}

// --- programs costly in memory -------------------------------------------------------------

TEST(ServeGuard, ProgramOverTheMemoryBudgetIs413) {
  ServeConfig config;
  config.max_body = 1u << 20;  // 1 MB: a program may take 8 MB once read
  Running s(config);
  auto c = s.client();
  std::string words;
  for (int i = 0; i < 200'000; ++i) words += "X1\n";  // 600 kB, 200,000 blocks: 20 MB and more
  for (const char* path : {"/api/run", "/api/analyze"}) {
    auto r = c.Post(path, json{{"program", words}}.dump(), "application/json");
    ASSERT_TRUE(r) << path;
    EXPECT_EQ(r->status, 413) << path;
    const std::string error = json::parse(r->body)["error"];
    EXPECT_NE(error.find("--max-body"), std::string::npos) << error;
    EXPECT_NE(error.find("200001 lines"), std::string::npos) << error;
  }
  // as many bytes in longer blocks are run
  std::string lines = "G01 F1000.\n";
  while (lines.size() < 600'000) lines += "X1.2345 Y2.3456 Z0.1 (a comment to make the block longer)\n";
  lines += "M30\n";
  auto r = c.Post("/api/run", json{{"program", lines}, {"moves", false}}.dump(), "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200) << r->body.substr(0, 300);
  EXPECT_EQ(program_lines("X1\nX2\nX3"), 3u);
}

// A profile of a table name of 60,000 dotted parts: 400 saying where and why; the server keeps serving.
TEST(ServeGuard, DeeplyNestedProfileIs400) {
  Running s(ServeConfig{});
  auto c = s.client();
  std::string deep = "[machine]\nname = \"deep\"\n[";
  for (int i = 0; i < 60'000; ++i) deep += "a.";
  deep += "b]\nx = 1\n";
  auto r = c.Post("/api/run", json{{"program", "M30\n"}, {"machine", deep}}.dump(), "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  const std::string error = json::parse(r->body)["error"];
  EXPECT_NE(error.find("<request>:3:65: error"), std::string::npos) << error;
  EXPECT_NE(error.find("a dotted key of more than 32 parts"), std::string::npos) << error;
  auto again = c.Post("/api/run", kShortRun, "application/json");
  ASSERT_TRUE(again);
  EXPECT_EQ(again->status, 200);
}

}  // namespace
}  // namespace ncurve::serve
