// G10.6 tool retract and recover: the block sets how far (G91) or where (G90) the tool goes when the
// machine's tool retraction signal comes, or without axis words cancels it. The control retracts
// only on that signal, which no program gives: in a program run the block moves nothing.
#include "machine/executor.hpp"

namespace ncurve::machine::actions {

bool tool_retract(Executor&, int) { return false; }

}  // namespace ncurve::machine::actions
