#pragma once
// What the `cavewall track` end-to-end tests share (tests/input/track_udp_test.cpp,
// tests/vrpn/vrpn_track_cli_test.cpp): a tracker's pace while the child runs, and the last
// tracked head of its CSV.

#include "tests/support/run_cli.h"
#include "tests/support/csv_table.h"

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace cavewall::test {

// Calls `send(i)` at about 100 Hz (a tracker's rate) until `child` exits; kills it after
// `limit` (the test then fails, never hangs). Returns the child's result.
template <class Send>
CliResult sendUntilExit(CliProcess& child, std::chrono::seconds limit, Send send) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    for (int i = 0; !child.exited() && std::chrono::steady_clock::now() < deadline; ++i) {
        send(i);
        std::this_thread::sleep_for(std::chrono::milliseconds(10));  // the tracker's pace
    }
    return child.finish(std::chrono::seconds(5));
}

// The columns of `cavewall track --csv`.
inline const std::vector<std::string> kTrackColumns{"t",  "head_x", "head_y", "head_z", "qx",
                                                    "qy", "qz",     "qw",     "dropped"};

// The last row of `csv` (`cavewall track --csv`) whose head was tracked (dropped 0); nullopt
// when there is none.
inline std::optional<CsvRow> lastTrackedHead(const CsvTable& csv) {
    std::optional<CsvRow> last;
    for (const CsvRow& row : csv)
        if (row.at("dropped") == "0") last = row;
    return last;
}

}  // namespace cavewall::test
