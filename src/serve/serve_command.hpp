// `ncurve serve`: starts the server and serves until interrupted.
#pragma once
#include "app/serve_args.hpp"

namespace ncurve::serve {

int serve_command(const app::ServeArgs& args);

}  // namespace ncurve::serve
