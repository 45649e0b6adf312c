// The custom-cycle macros of macros/, built into the program so that ncurve gen can ship them.
#pragma once

namespace ncurve::gen {

const char* o9010_text();  // macros/O9010.nc: G102 Archimedean spiral

}  // namespace ncurve::gen
