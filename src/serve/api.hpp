// The JSON API of `ncurve serve` (docs/serve.md): each endpoint a function from the request's
// body to the answer, apart from HTTP so that tests and the server call the same code.
#pragma once
#include <atomic>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "machine/interpreter.hpp"

namespace ncurve::serve {

struct ServeConfig {
  std::string machine;              // the profile of a request without "machine" (a file or shipped name)
  std::vector<std::string> libs;    // --lib folders, read for each run
  std::vector<std::string> files;   // FILE arguments, offered by GET /api/files
  std::uint64_t max_steps = machine::RunOptions{}.max_steps;  // the most a request may ask for
  double max_seconds = machine::RunOptions{}.max_seconds;
  std::size_t max_body = 64u << 20;     // bytes of a request body (413 past it)
  std::size_t max_moves = 5'000'000;    // moves put in one answer
  double request_seconds = 30;          // to read a request whole, and again to write its answer
  std::vector<std::string> allow_hosts; // names the Host header may give besides the bound address
};

// A run or analyze request whose program would take more than kProgramMemoryPerBodyByte times
// --max-body once read (nc::compiled_size of its bytes and lines) is refused (413) before it is read.
inline constexpr std::size_t kProgramMemoryPerBodyByte = 8;
// The largest Z-map a run request may cut (8 bytes a cell).
inline constexpr double kMostPartCells = 4e6;
std::size_t program_lines(std::string_view program);
std::size_t program_memory(std::string_view program);

// A request the API refuses: the HTTP status and what is wrong.
struct ApiError : std::runtime_error {
  ApiError(int status, const std::string& message) : std::runtime_error(message), status(status) {}
  int status;
};

struct Answer {
  int status = 200;
  std::string body;
  std::string content_type = "application/json";
};

// {"error": message, "status": status}
Answer error_answer(int status, const std::string& message);

Answer api_run(const ServeConfig& config, const std::string& body);
Answer api_analyze(const ServeConfig& config, const std::string& body);
// The same, stopped (NC9000) once `cancel` is set: its client has gone, the server is stopping.
Answer api_run(const ServeConfig& config, const std::string& body, const std::atomic<bool>* cancel);
Answer api_analyze(const ServeConfig& config, const std::string& body, const std::atomic<bool>* cancel);
Answer api_gen(const ServeConfig& config, const std::string& body);
Answer api_profiles(const ServeConfig& config);
// The curves of `ncurve gen --list` (geom::catalogue()) with their parameters' defaults.
Answer api_curves();
// The server's --lib folders, which a request's "lib" chooses among.
Answer api_libs(const ServeConfig& config);
Answer api_files(const ServeConfig& config);
Answer api_file(const ServeConfig& config, const std::string& name);
// The workbench page at GET / and its scripts, styles and example at GET /assets/NAME.
Answer page();
Answer asset(const std::string& name);

}  // namespace ncurve::serve
