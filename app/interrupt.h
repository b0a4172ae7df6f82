#pragma once
// Ctrl+C (SIGINT) and SIGTERM end a session cleanly: the handler only sets a flag, which the
// frame loop reads once per frame, so the session stops within a frame and closes its files
// (complete CSV rows, the summary). A second signal while the flag is set ends the process at
// once with the signal's default action (for a session stuck before its first frame, in a bake).
// Process-wide: one handler per signal, installed by the command line.

namespace cavewall::app {

// Installs the handler for SIGINT and SIGTERM and clears the flag.
void installInterruptHandler();

// The signal received since installInterruptHandler (SIGINT or SIGTERM), or 0 for none.
int interruptSignal();

}  // namespace cavewall::app
