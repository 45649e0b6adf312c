// The execution trace of a run as JSON for `POST /api/run` with "trace": true (docs/serve.md).
#pragma once
#include "machine/trace.hpp"
#include "serve/json_out.hpp"

namespace ncurve::serve {

void write_trace_json(Columns& out, const machine::ExecutionTrace& trace, FileTable& files);

}  // namespace ncurve::serve
