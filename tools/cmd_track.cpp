#include "config/display_config.h"
#include "input/recording.h"
#include "input/tracker_source.h"
#include "input/tracking_pipeline.h"
#include "tools/args.h"
#include "tools/commands.h"

#include <cerrno>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>
#include <thread>

namespace cavewall::tools {

const char* const kTrackUsage =
    "usage: cavewall track --tracker SPEC [--display FILE|PRESET] [--seconds S] [--rate HZ]\n"
    "                      [--record FILE] [--csv FILE]\n"
    "                      [--min-cutoff HZ] [--beta B] [--angular-beta B] [--d-cutoff HZ] [--no-filter]\n"
    "\n"
    "Reads a tracker for S seconds (default 10) at HZ samples per second (default 90), applies\n"
    "the display's calibration (tracking.caveFromTracker), the One Euro filter, the drop-out\n"
    "policy and the prediction over tracking.latencyMs, and prints the head poses as CSV:\n"
    "  t,head_x,head_y,head_z,qx,qy,qz,qw,dropped\n"
    "t in seconds from the start, position in metres in the cave frame, orientation as a unit\n"
    "quaternion, dropped = 1 while the head is not tracked (held, easing or default pose).\n"
    "SPEC: sim:walk[?seed=N&dropouts=1], file:PATH[?loop=1], replay:PATH,\n"
    "      dtrack:udp://HOST:PORT[?body=1&hand=0&bind=ADDR], opentrack:udp://HOST:PORT[?bind=ADDR],\n"
    "      vrpn:DEVICE@HOST[:PORT][?head=0&hand=1&buttons=NAME&udp=0]\n"
    "Simulated, file and replay sources run on a virtual clock (t = i / HZ, as fast as possible,\n"
    "reproducible); network sources run in real time. A replay without --seconds runs to the end\n"
    "of the recording. --record writes the raw samples and wand events as a replayable recording;\n"
    "--csv writes the CSV to FILE instead of standard output. Without --display the defaults are\n"
    "used: no calibration, no latency, a 3 m x 3 m floor, the head at 1.7 m.\n"
    "One Euro filter (input/one_euro.h): --min-cutoff (Hz, default 1) and --d-cutoff (Hz, default 1)\n"
    "for position and orientation, --beta (Hz per m/s, default 20) for position, --angular-beta\n"
    "(Hz per rad/s, default 10) for orientation; --no-filter passes the poses through.\n";

namespace {

// Numbers in the shortest form that reads back to the same double: exact and readable.
void writeRow(std::FILE* out, const input::TrackedFrame& f) {
    const auto& p = f.head.pose.position;
    const auto& q = f.head.pose.orientation;
    char line[512], *at = line;
    for (double v : {f.time, p.x, p.y, p.z, q.x, q.y, q.z, q.w}) {
        at = std::to_chars(at, line + sizeof line, v).ptr;
        *at++ = ',';
    }
    *at++ = f.head.state == input::TrackState::Tracked ? '0' : '1';
    *at++ = '\n';
    std::fwrite(line, 1, static_cast<std::size_t>(at - line), out);
}

struct Output {
    std::FILE* file = stdout;
    ~Output() {
        if (file && file != stdout) std::fclose(file);
    }
};

// One tracker read at a fixed rate: poll, record, filter, print.
class TrackLoop {
public:
    TrackLoop(input::TrackerSource& source, const input::PipelineConfig& config, input::Recorder* recorder,
              std::FILE* out)
        : _source(source), _replay(dynamic_cast<input::ReplaySource*>(&source)), _pipeline(config), _recorder(recorder),
          _out(out) {}

    void step(double t) {
        const input::Sample sample = _source.poll(t);
        std::vector<input::Event> events = _source.takeEvents();
        if (!_replay) input::appendWandEvents(_lastWand, sample.wand, t, events);  // a replay brings its own
        _lastWand = sample.wand;
        if (_recorder) {
            _recorder->write(sample);
            for (const auto& e : events) _recorder->write(e);
        }
        const input::TrackedFrame frame = _pipeline.update(sample);
        writeRow(_out, frame);
        ++rows;
        untracked += frame.head.state == input::TrackState::Tracked ? 0 : 1;
    }
    bool replayFinished() const { return _replay && _replay->finished(); }

    long rows = 0, untracked = 0;

private:
    input::TrackerSource& _source;
    input::ReplaySource* _replay;
    input::TrackingPipeline _pipeline;
    input::Recorder* _recorder;
    std::FILE* _out;
    input::WandState _lastWand;
};

void applyFilterFlags(const Args& args, input::PipelineConfig& c) {
    const double minCutoff = args.number("min-cutoff", c.position.minCutoff, 1e-3, 1000.0);
    const double dCutoff = args.number("d-cutoff", c.position.dCutoff, 1e-3, 1000.0);
    c.position.minCutoff = c.orientation.minCutoff = minCutoff;
    c.position.dCutoff = c.orientation.dCutoff = dCutoff;
    c.position.beta = args.number("beta", c.position.beta, 0.0, 1e6);
    c.orientation.beta = args.number("angular-beta", c.orientation.beta, 0.0, 1e6);
    c.position.enabled = c.orientation.enabled = !args.has("no-filter");
}

void printSummary(const input::TrackerSource& source, const TrackLoop& loop) {
    const input::SourceStats s = source.stats();
    std::cerr << "track: " << source.describe() << ": " << loop.rows << " samples, " << loop.untracked
              << " without head tracking";
    if (source.isLive())
        std::cerr << "; packets " << s.packets << ", accepted " << s.accepted << ", dropped " << s.dropped()
                  << " (malformed " << s.malformed << ", non-finite " << s.nonFinite << ", foreign " << s.foreign
                  << ", outside the tracking volume " << s.outside << ")";
    if (!source.problem().empty()) std::cerr << "; " << source.problem();
    std::cerr << "\n";
}

}  // namespace

int runTrack(const std::vector<std::string>& words) {
    const Args args(words, {"no-filter"});
    args.expectFlags({"tracker", "display", "seconds", "rate", "record", "csv", "min-cutoff", "beta", "angular-beta",
                      "d-cutoff", "no-filter"});
    args.expectNoPositional("track");
    const std::string spec = args.require("tracker");
    input::TrackerContext context;
    input::PipelineConfig pipelineConfig;
    if (auto display = args.get("display")) {
        const config::DisplayConfig c = config::loadDisplayConfig(*display);
        context = input::trackerContextFor(c);
        pipelineConfig = input::pipelineConfigFor(c);
    }
    applyFilterFlags(args, pipelineConfig);
    const double rate = args.number("rate", 90.0, 1.0, 10000.0);
    const double seconds = args.number("seconds", 10.0, 0.0, 86400.0);
    const auto source = input::makeTracker(spec, context);
    if (source->isLive()) std::cerr << "track: " << source->describe() << std::endl;  // the bound port, for senders
    const bool untilEnd = dynamic_cast<input::ReplaySource*>(source.get()) && !args.has("seconds");
    std::unique_ptr<input::Recorder> recorder;
    if (auto file = args.get("record")) recorder = std::make_unique<input::Recorder>(*file, spec);
    Output out;
    if (auto file = args.get("csv")) {
        out.file = std::fopen(file->c_str(), "w");
        if (!out.file) throw Error("--csv: cannot write '" + *file + "': " + std::strerror(errno));
    }
    std::fprintf(out.file, "t,head_x,head_y,head_z,qx,qy,qz,qw,dropped\n");
    TrackLoop loop(*source, pipelineConfig, recorder.get(), out.file);
    const auto start = std::chrono::steady_clock::now();
    const long last = static_cast<long>(seconds * rate + 1e-9);
    // t = i / rate, not a running sum, so every run (and every replay) sees the same times.
    for (long i = 0; untilEnd ? !loop.replayFinished() : i <= last; ++i) {
        const double t = static_cast<double>(i) / rate;
        if (source->isLive()) std::this_thread::sleep_until(start + std::chrono::duration<double>(t));
        loop.step(t);
    }
    printSummary(*source, loop);
    return 0;
}

}  // namespace cavewall::tools
