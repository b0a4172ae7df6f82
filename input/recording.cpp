#include "input/recording.h"

#include "config/json_reader.h"

#include <charconv>
#include <cerrno>
#include <cstring>

namespace cavewall::input {
namespace {

const char* const kEventNames[] = {"buttonDown", "buttonUp",   "keyDown",    "keyUp",         "mouseMove",
                                   "scroll",     "selectMode", "speedScale", "pointerCapture"};

// The shortest text that reads back to the same double (std::to_chars round-trip guarantee).
std::string num(double v) {
    char buf[32];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, end);
}

std::string poseArray(const Pose& p) {
    const glm::dvec3& x = p.position;
    const glm::dquat& q = p.orientation;
    return "[" + num(x.x) + "," + num(x.y) + "," + num(x.z) + "," + num(q.x) + "," + num(q.y) + "," + num(q.z) + "," +
           num(q.w) + "]";
}

Pose readPose(const config::JsonNode& n) {
    const auto v = n.items(7, 7);
    return {{v[0].number(), v[1].number(), v[2].number()},
            {v[6].number(), v[3].number(), v[4].number(), v[5].number()}};
}

glm::dvec2 readVec2(const config::JsonNode& n) {
    const auto v = n.items(2, 2);
    return {v[0].number(), v[1].number()};
}

void readRecord(const config::JsonNode& r, Recording& out) {
    r.expectObject();
    const double t = r.at("t").number();
    if (r.has("event")) {
        r.expectKeys({"t", "event", "code", "value"});
        const std::string name = r.at("event").oneOf({"buttonDown", "buttonUp", "keyDown", "keyUp", "mouseMove",
                                                      "scroll", "selectMode", "speedScale", "pointerCapture"});
        Event e;
        e.time = t;
        for (std::size_t i = 0; i < std::size(kEventNames); ++i)
            if (name == kEventNames[i]) e.type = static_cast<EventType>(i);
        e.code = r.at("code").integer(-1000000, 1000000);
        e.value = readVec2(r.at("value"));
        if (!out.events.empty() && t < out.events.back().time) r.at("t").fail("events must be in time order");
        out.events.push_back(e);
        return;
    }
    r.expectKeys({"t", "head", "headValid", "hand", "handValid", "buttons", "joystick"});
    Sample s;
    s.time = t;
    s.head = readPose(r.at("head"));
    s.headValid = r.at("headValid").boolean();
    s.hand = readPose(r.at("hand"));
    s.handValid = r.at("handValid").boolean();
    s.wand.buttons = static_cast<std::uint32_t>(r.at("buttons").number(0, 4294967295.0));
    s.wand.joystick = readVec2(r.at("joystick"));
    if (!out.samples.empty() && t < out.samples.back().time) r.at("t").fail("samples must be in time order");
    out.samples.push_back(s);
}

}  // namespace

std::string_view toString(EventType type) { return kEventNames[static_cast<int>(type)]; }

std::string formatSampleLine(const Sample& s) {
    return "{\"t\":" + num(s.time) + ",\"head\":" + poseArray(s.head) +
           ",\"headValid\":" + (s.headValid ? "true" : "false") + ",\"hand\":" + poseArray(s.hand) +
           ",\"handValid\":" + (s.handValid ? "true" : "false") + ",\"buttons\":" + std::to_string(s.wand.buttons) +
           ",\"joystick\":[" + num(s.wand.joystick.x) + "," + num(s.wand.joystick.y) + "]}";
}

std::string formatEventLine(const Event& e) {
    return "{\"t\":" + num(e.time) + ",\"event\":\"" + std::string(toString(e.type)) +
           "\",\"code\":" + std::to_string(e.code) + ",\"value\":[" + num(e.value.x) + "," + num(e.value.y) + "]}";
}

Recorder::Recorder(const std::filesystem::path& file, std::string_view sourceDescription) : _file(file) {
    _out = std::fopen(file.c_str(), "w");
    if (!_out) throw Error(file.string() + ": cannot write the recording: " + std::strerror(errno));
    writeLine("{\"format\":\"cavewall-input\",\"version\":1,\"source\":" +
              nlohmann::json(std::string(sourceDescription)).dump() + "}");
}

Recorder::~Recorder() {
    if (_out) std::fclose(_out);
}

void Recorder::writeLine(const std::string& line) {
    if (std::fputs(line.c_str(), _out) < 0 || std::fputc('\n', _out) == EOF)
        throw Error(_file.string() + ": cannot write the recording: " + std::strerror(errno));
}

void Recorder::write(const Sample& sample) { writeLine(formatSampleLine(sample)); }
void Recorder::write(const Event& event) { writeLine(formatEventLine(event)); }

Recording parseRecording(std::string_view text, const std::string& sourceName) {
    Recording out;
    std::size_t lineNo = 0;
    bool header = false;
    while (!text.empty()) {
        const auto nl = text.find('\n');
        const std::string_view line = text.substr(0, nl);
        text = nl == std::string_view::npos ? std::string_view{} : text.substr(nl + 1);
        ++lineNo;
        if (line.find_first_not_of(" \t\r") == std::string_view::npos) continue;
        const auto doc = config::JsonDocument::fromText(line, sourceName + ":" + std::to_string(lineNo));
        const config::JsonNode root = doc.root();
        if (header) {
            readRecord(root, out);
            continue;
        }
        root.expectObject();
        root.expectKeys({"format", "version", "source"});
        if (root.at("format").string() != "cavewall-input")
            root.at("format").fail("expected \"cavewall-input\", got " + config::describeJson(root.at("format").raw()));
        root.at("version").integer(1, 1);
        out.source = root.at("source").string();
        header = true;
    }
    if (!header) throw Error(sourceName + ": expected a cavewall-input recording, got an empty file");
    if (out.samples.empty()) throw Error(sourceName + ": expected at least one sample, got none");
    return out;
}

Recording loadRecording(const std::filesystem::path& file) {
    return parseRecording(config::readTextFile(file), file.string());
}

Sample ReplaySource::poll(double now) {
    if (!_started) {
        _started = true;
        double first = _recording.samples.front().time;
        if (!_recording.events.empty()) first = std::min(first, _recording.events.front().time);
        _offset = first - now;
        _current = _recording.samples.front();
    }
    _now = now;
    const double t = now + _offset;
    while (_nextSample < _recording.samples.size() && _recording.samples[_nextSample].time <= t)
        _current = _recording.samples[_nextSample++];
    Sample s = _current;
    s.time = now;
    return s;
}

std::vector<Event> ReplaySource::takeEvents() {
    std::vector<Event> out;
    const double t = _now + _offset;
    while (_started && _nextEvent < _recording.events.size() && _recording.events[_nextEvent].time <= t)
        out.push_back(_recording.events[_nextEvent++]);
    return out;
}

bool ReplaySource::finished() const {
    return _nextSample == _recording.samples.size() && _nextEvent == _recording.events.size();
}

std::unique_ptr<TrackerSource> makeReplaySource(const TrackerSpec& spec) {
    spec.expectParams({});
    if (spec.target().empty()) spec.fail("expected replay:PATH, got an empty path");
    return std::make_unique<ReplaySource>(loadRecording(spec.target()));
}

}  // namespace cavewall::input
