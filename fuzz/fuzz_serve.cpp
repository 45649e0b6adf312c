// libFuzzer target: any bytes as the body of POST /api/run, /api/analyze or /api/gen (the first
// byte picks which; src/serve). A refusal is an ApiError with its status; any other exception,
// a crash or undefined behaviour is a finding. Runs are kept short by the server's own limits.
#include <cstddef>
#include <cstdint>
#include <string>

#include "serve/api.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ncurve::serve;
  if (size == 0) return 0;
  ServeConfig config;
  config.max_steps = 20'000;
  config.max_seconds = 2;
  config.max_moves = 20'000;
  const std::string body(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    switch (data[0] % 3) {
      case 0: api_run(config, body); break;
      case 1: api_analyze(config, body); break;
      default: api_gen(config, body); break;
    }
  } catch (const ApiError&) {
  }
  return 0;
}
